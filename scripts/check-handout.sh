#!/usr/bin/env bash
# Checks the student handout the way a student and a grader will use it (scripts/lab.py
# check-handout, with the grading engine):
#   1. make-handout.sh writes it (and refuses if any solution line is in it);
#   2. it configures and builds on its own (only the lab programs and their tests);
#   3. on the untouched handout, only task tests fail, and every task has a failing test;
#   4. pasting the solution of tasks 1..n into the handout (what a student who finished
#      them has) makes every test of tasks 1..n pass, for n = 1, 2, ... up to the last task.
# Usage: scripts/check-handout.sh [--lab NAME]... [--out DIR]
#   --lab NAME  check only this lab (repeat for more; default every lab)
#   --out DIR   where to write the handout (default build/handout-check; replaced)
# Uses ccache when it is installed. Exit status 0 when every check passed.
set -euo pipefail
arguments=()
while [[ $# -gt 0 ]]; do
    case $1 in
        --lab) [[ $# -ge 2 ]] || { echo "usage: $0 [--lab NAME]... [--out DIR]" >&2; exit 2; }
            arguments+=(--lab "$2"); shift 2 ;;
        --out) [[ $# -ge 2 ]] || { echo "usage: $0 [--lab NAME]... [--out DIR]" >&2; exit 2; }
            arguments+=(--out "$(realpath -m -- "$2")"); shift 2 ;;
        *) echo "usage: $0 [--lab NAME]... [--out DIR]" >&2; exit 2 ;;
    esac
done
export ALSOFT_DRIVERS=null
exec python3 "$(dirname "$0")/lab.py" check-handout "${arguments[@]}"
