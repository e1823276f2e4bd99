#!/usr/bin/env bash
# Writes the student handout: the framework, the EXERCISE version of every lab, the lab
# sheets, the grading tests and the lab tool; no solution code. The lab tool does the work
# (scripts/labtool/handout.py; its README and CMake marker are files in scripts/labtool/handout/).
#
# Usage: scripts/make-handout.sh OUT_DIR      (OUT_DIR must not exist, or be empty; a relative
# OUT_DIR is taken from the folder you run it in). One line and exit 2 for a bad OUT_DIR; on
# any failure one line, exit 1 and nothing left in OUT_DIR.
#
# In the handout, `cmake --preset debug` then `cmake --build --preset debug --target <lab>`
# builds the student's program, <lab>_tests tests the student's code, and
# `python3 scripts/lab.py grade` grades it. scripts/check-handout.sh checks all of that.
set -euo pipefail
if [[ $# -ne 1 || $1 == -h || $1 == --help ]]; then
    echo "usage: $0 OUT_DIR" >&2
    exit 2
fi
exec python3 "$(dirname "$0")/lab.py" handout "$1"
