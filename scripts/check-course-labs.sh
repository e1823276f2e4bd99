#!/usr/bin/env bash
# Builds lab folders written for the course's own framework and runs each one under Xvfb, to
# prove that course lab code of both generations builds and runs on Hitbox unchanged.
#
#   ./scripts/check-course-labs.sh                    every folder in tests/course/
#   ./scripts/check-course-labs.sh ~/labs/Week8 ...   your own lab folders
#   ./scripts/check-course-labs.sh --screenshots DIR  keep what each window showed
#
# The lab tool does it (python3 scripts/lab.py check-course-labs; scripts/labtool/courselabs.py
# says what passes, and what a folder's check-course-lab.txt may add). Exit status: 0 every lab
# passed, 1 one failed, 2 a tool is missing.
set -euo pipefail
command -v python3 >/dev/null || { echo "check-course-labs: needs python3 (./scripts/install-deps.sh)" >&2; exit 2; }
exec python3 "$(dirname "$0")/lab.py" check-course-labs "$@"
