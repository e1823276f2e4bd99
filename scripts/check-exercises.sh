#!/usr/bin/env bash
# Checks that the labs' grading tests tell a finished lab from an unfinished one: every test of
# <lab>_tests (the solution) passes, and every task marked "// BEGIN TASK n" has a test in a
# suite Task<n>... that FAILS on <lab>_exercise_tests (the exercise). The tests run with the
# grading engine (scripts/lab.py check-exercises), so "passes" means what it means to a grader.
# Usage: scripts/check-exercises.sh [BUILD_DIR]     (default build/debug, already configured)
set -euo pipefail
if [[ ${1:-} == -h || ${1:-} == --help || $# -gt 1 ]]; then
    echo "usage: $0 [BUILD_DIR]    (default build/debug)" >&2
    exit 2
fi
build=()
if [[ $# -eq 1 ]]; then build=(--build "$(realpath -m -- "$1")"); fi
exec python3 "$(dirname "$0")/lab.py" check-exercises "${build[@]}"
