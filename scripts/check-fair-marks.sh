#!/usr/bin/env bash
# Checks that one mistake costs one task, in every lab: for each task n of each lab, a
# submission has every task solved except n, which is left as the starter code. The class
# grader must give that submission every task's mark except task n's. The lab tool writes
# the class and reads the gradebook (scripts/labtool/fairmarks.py says how).
# Usage: scripts/check-fair-marks.sh [--lab NAME]... [--build DIR] [WORK_DIR]
#   WORK_DIR default build/check-fair-marks; --build DIR the instructor's build to grade
#   with (default build/grading; CI passes build/debug, already built)
set -euo pipefail
HITBOX_CALLER=$PWD # relative paths on the command line are the caller's (from_caller)
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh
lab_options=()
build_options=()
work=build/check-fair-marks
while [[ $# -gt 0 ]]; do
    case $1 in
        --lab) lab_options+=(--lab "$2"); shift 2 ;;
        --lab=*) lab_options+=(--lab "${1#--lab=}"); shift ;;
        --build) build_options=(--build "$(from_caller "$2")"); shift 2 ;;
        *) work=$(from_caller "$1"); shift ;;
    esac
done
rm -rf "$work/class" "$work/grades"
python3 scripts/lab.py fair-marks make "$work/class" "${lab_options[@]}"
# The submissions are the instructor's own code with one task undone: graded by the same engine
# with the same limits, without the sandbox (it only costs time here; check-grading.sh proves it).
./scripts/grade-class.sh "$work/class" "${lab_options[@]}" --no-cage --out "$work/grades" "${build_options[@]}"
if ! python3 scripts/lab.py fair-marks check "$work/grades" "${lab_options[@]}"; then
    echo "check-fair-marks: FAILED: a mistake cost more than its own task (above)" >&2
    exit 1
fi
echo "check-fair-marks: in every lab, a task left undone costs that task and no other"
