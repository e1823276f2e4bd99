#!/usr/bin/env bash
# Checks that the labs' grading tests tell a finished lab from an unfinished one:
#   - every test of <lab>_tests (built against the solution) passes, and
#   - for every task marked "// BEGIN TASK n" in the lab's sources, at least one test in a
#     suite named Task<n>... FAILS on <lab>_exercise_tests (built against the exercise), so
#     no task's tests pass on code the student has not written yet.
# Usage: scripts/check-exercises.sh [BUILD_DIR]     (default build/debug, already configured)
# Builds the test programs it needs, prints a table, exits 1 naming every lab/task that fails.
set -euo pipefail
HITBOX_CALLER=$PWD # relative paths on the command line are the caller's (from_caller)
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh

if [[ ${1:-} == -h || ${1:-} == --help || $# -gt 1 ]]; then
    echo "usage: $0 [BUILD_DIR]    (default build/debug)" >&2
    exit 2
fi
build_dir=${1:-build/debug}
if [[ $# -ge 1 ]]; then build_dir=$(from_caller "$1"); fi
if [[ ! -f $build_dir/CMakeCache.txt ]]; then
    echo "check-exercises: $build_dir is not a configured build folder." >&2
    echo "Fix: cmake --preset debug   (or give the build folder as the argument)" >&2
    exit 2
fi
export ALSOFT_DRIVERS=null

mapfile -t labs < <(lab_names)
if [[ ${#labs[@]} -eq 0 ]]; then
    echo "check-exercises: no labs found (labs/NN_name/CMakeLists.txt)" >&2
    exit 1
fi

targets=()
for lab in "${labs[@]}"; do
    targets+=("${lab}_tests" "${lab}_exercise_tests")
done
echo "check-exercises: building ${targets[*]}"
cmake --build "$build_dir" --parallel 2 --target "${targets[@]}" >/dev/null

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
problems=()
printf '%-28s %-5s %-16s %-22s %s\n' LAB TASK "SOLUTION PASSES" "EXERCISE FAILS" VERDICT
for lab in "${labs[@]}"; do
    folder=$(lab_folder "$lab")
    solution=$(find_test_program "$build_dir" "${lab}_tests")
    exercise=$(find_test_program "$build_dir" "${lab}_exercise_tests")
    if [[ -z $solution || -z $exercise ]]; then
        problems+=("$lab: no grading tests (add tests/labs/${folder#labs/}/CMakeLists.txt)")
        printf '%-28s %-5s %-16s %-22s %s\n' "$lab" - - - "NO TESTS"
        continue
    fi
    solution_ok=yes
    run_gtest "$solution" "$work/$lab.solution" || solution_ok=no
    run_gtest "$exercise" "$work/$lab.exercise" || true
    if [[ $solution_ok == no ]]; then
        problems+=("$lab: the solution fails $(grep -c '^FAIL' "$work/$lab.solution") test(s):" \
            "$(grep '^FAIL' "$work/$lab.solution" | cut -d' ' -f2 | tr '\n' ' ')")
    fi

    mapfile -t tasks < <(lab_tasks "$folder")
    if [[ ${#tasks[@]} -eq 0 ]]; then
        problems+=("$lab: no '// BEGIN TASK n: title' markers in $folder")
    fi
    for task in "${tasks[@]}"; do
        read -r solution_passed solution_failed < <(task_counts "$work/$lab.solution" "$task")
        read -r exercise_passed exercise_failed < <(task_counts "$work/$lab.exercise" "$task")
        total=$((exercise_passed + exercise_failed))
        verdict=ok
        if [[ $total -eq 0 ]]; then
            verdict="NO TESTS"
            problems+=("$lab task $task: no test suite named Task${task}... in its grading tests")
        elif [[ $exercise_failed -eq 0 ]]; then
            verdict="PASSES VACUOUSLY"
            problems+=("$lab task $task: every Task${task} test passes on the unmodified exercise")
        elif [[ $solution_failed -gt 0 ]]; then
            verdict="SOLUTION FAILS"
        fi
        printf '%-28s %-5s %-16s %-22s %s\n' "$lab" "$task" \
            "$solution_passed/$((solution_passed + solution_failed))" \
            "$exercise_failed of $total" "$verdict"
    done
    # Suites named for a task the sources do not mark are probably a typo.
    for suite_task in $(awk '{ s = $2; sub(/\..*/, "", s); if (match(s, /^Task[0-9]+/)) print substr(s, 5, RLENGTH - 4) }' \
        "$work/$lab.solution" | sort -n -u); do
        if ! is_one_of "$suite_task" "${tasks[@]}"; then
            problems+=("$lab: tests for task $suite_task, but no '// BEGIN TASK $suite_task:' in $folder")
        fi
    done
done

if [[ ${#problems[@]} -gt 0 ]]; then
    echo
    echo "check-exercises: FAILED" >&2
    printf '  - %s\n' "${problems[@]}" >&2
    echo "Test output: run the program named above, e.g. $build_dir/tests/labs/<folder>/<lab>_exercise_tests" >&2
    exit 1
fi
echo
echo "check-exercises: every solution passes and every task has a test that fails on the exercise"
