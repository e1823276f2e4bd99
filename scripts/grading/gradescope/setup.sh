#!/usr/bin/env bash
# Gradescope autograder setup (runs once, as root, when the autograder image is built):
# installs the Debian/Ubuntu packages the grader needs and builds the framework and the
# instructor's tests, so that grading a submission compiles only the student's files.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends g++ make cmake pkg-config libsfml-dev \
    libgtest-dev libgmock-dev python3 git unzip ca-certificates ccache bubblewrap util-linux
python3 /autograder/source/hitbox/scripts/lab.py gradescope --root /autograder --prepare-only
