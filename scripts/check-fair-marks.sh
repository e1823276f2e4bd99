#!/usr/bin/env bash
# Checks that one mistake costs one task, in every lab: for each task n of each lab, a
# submission has every task solved except n, which is left as the starter code (a wrong
# answer: the tests of task n fail on it, check-exercises.sh proves that). The class grader
# must give that submission every task's mark except task n's. A cascade (task n's mistake
# failing another task's tests) fails this check, naming the lab, the task and the tests.
# Usage: scripts/check-fair-marks.sh [--lab NAME]... [--build DIR] [WORK_DIR]
#   WORK_DIR default build/check-fair-marks; --build DIR the instructor's build to grade
#   with (default build/grading; CI passes build/debug, already built)
set -euo pipefail
HITBOX_CALLER=$PWD # relative paths on the command line are the caller's (from_caller)
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh
chosen=()
build_options=()
work=build/check-fair-marks
while [[ $# -gt 0 ]]; do
    case $1 in
        --lab) chosen+=("$2"); shift 2 ;;
        --lab=*) chosen+=("${1#--lab=}"); shift ;;
        --build) build_options=(--build "$(from_caller "$2")"); shift 2 ;;
        *) work=$(from_caller "$1"); shift ;;
    esac
done
mapfile -t labs < <(lab_names)
[[ ${#chosen[@]} -eq 0 ]] || labs=("${chosen[@]}")
rm -rf "$work/class" "$work/grades"
mkdir -p "$work/class"

# One submission per lab and task: "<lab>-without-<n>".
lab_options=()
for lab in "${labs[@]}"; do
    folder=$(lab_folder "$lab")
    mapfile -t tasks < <(lab_tasks "$folder")
    for task in "${tasks[@]}"; do
        solved=$(printf '%s\n' "${tasks[@]}" | grep -vx "$task" | paste -sd, -)
        into=$work/class/$lab-without-$task/$folder
        mkdir -p "$into"
        while IFS= read -r source; do
            mkdir -p "$(dirname "$into/${source#"$folder"/}")"
            cmake "-DINPUT=$source" "-DOUTPUT=$into/${source#"$folder"/}" "-DSOLVED_TASKS=$solved" \
                -P framework/cmake/HitboxMakeExercise.cmake
        done < <(lab_sources "$folder")
    done
    lab_options+=(--lab "$lab")
done

# The submissions are the instructor's own code with one task undone: graded by the same engine
# with the same limits, without the sandbox (it only costs time here; check-grading.sh proves it).
./scripts/grade-class.sh "$work/class" "${lab_options[@]}" --no-cage --out "$work/grades" "${build_options[@]}"

# Each submission: a mark for every task of its lab but the one left undone.
problems=0
for lab in "${labs[@]}"; do
    mapfile -t tasks < <(lab_tasks "$(lab_folder "$lab")")
    for task in "${tasks[@]}"; do
        student=$lab-without-$task
        expected=$(printf '%s\n' "${tasks[@]}" | grep -vx "$task" | paste -sd, -)
        marked=$(awk -F, -v student="$student" -v lab="$lab" '$1 == student && $2 == lab && $3 != "total" && $6 == 1 { print $3 }' \
            "$work/grades/grades.csv" | paste -sd, -)
        if [[ $marked != "$expected" ]]; then
            echo "check-fair-marks: $lab with only task $task undone got marks for tasks '$marked', expected '$expected'" >&2
            grep -E '^\*\*Task' "$work/grades/students/$student.md" | grep -v "(task $task)" | sed 's/^/    failed: /' >&2 || true
            problems=$((problems + 1))
        fi
    done
done
if [[ $problems -gt 0 ]]; then
    echo "check-fair-marks: FAILED: $problems mistake(s) cost more than their own task" >&2
    exit 1
fi
echo "check-fair-marks: in every lab, a task left undone costs that task and no other"
