#!/usr/bin/env bash
# Grades the labs in this tree: builds each lab's grading tests against the lab code here
# (a student's copy of the handout), runs them, and prints a per-task summary.
#
# Usage: scripts/grade.sh [--lab NAME] [--build DIR] [--exercise]
#   --lab NAME   grade one lab, e.g. --lab lab02_bouncing_balls (default: every lab)
#   --build DIR  build folder (default build/debug; configured with the debug preset if new)
#   --exercise   in the course repository: grade the generated exercise instead of the
#                solution (shows what a student starts from). Not available in a handout.
#
# Each lab is built and graded on its own: a lab that does not compile gets the row "did not
# build" and one failed test "Build" in its XML, and the other labs are still graded.
# The summary has one row per lab and task (test suites Task<n>...); task "-" counts the
# lab's other tests (e.g. that it starts the way the lab sheet says). A test that hangs
# (longer than LAB_TEST_TIMEOUT seconds, default 60) or crashes counts as failed and the
# row says so.
# Results, all written afresh on every run (the old ones are deleted first):
#   DIR/grade-results/<lab>.xml        JUnit XML: every test, the hung and crashed ones as
#                                      failures ("hung: timed out after N s", "crashed ...")
#   DIR/grade-results/<lab>.log        the tests' output
#   DIR/grade-results/<lab>.build.log  the compiler's output
# Exit status: 0 when every test of every graded lab passed, 1 otherwise (a failed or hung
# test, or a lab that did not build), 2 bad usage.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh

usage() {
    echo "usage: $0 [--lab NAME] [--build DIR] [--exercise]" >&2
    exit 2
}
only_lab=""
build_dir=build/debug
suffix=_tests
while [[ $# -gt 0 ]]; do
    case $1 in
        --lab) [[ $# -ge 2 ]] || usage; only_lab=$2; shift 2 ;;
        --build) [[ $# -ge 2 ]] || usage; build_dir=$2; shift 2 ;;
        --exercise) suffix=_exercise_tests; shift ;;
        -h | --help) usage ;;
        *) echo "grade: unknown option '$1'" >&2; usage ;;
    esac
done
export ALSOFT_DRIVERS=null
if [[ $suffix == _exercise_tests && -f framework/cmake/HitboxHandout.cmake ]]; then
    echo "grade: --exercise is for the course repository; in a handout the labs are the exercise already." >&2
    exit 2
fi

mapfile -t labs < <(lab_names)
if [[ -n $only_lab ]]; then
    if ! printf '%s\n' "${labs[@]}" | grep -qx "$only_lab"; then
        echo "grade: no lab called '$only_lab'. The labs here: ${labs[*]}" >&2
        exit 2
    fi
    labs=("$only_lab")
fi
if [[ ${#labs[@]} -eq 0 ]]; then
    echo "grade: no labs found (labs/NN_name/CMakeLists.txt). Run it from a handout or the course repository." >&2
    exit 2
fi

if [[ ! -f $build_dir/CMakeCache.txt ]]; then
    echo "grade: configuring $build_dir"
    if [[ $build_dir == build/debug ]]; then
        cmake --preset debug >/dev/null
    else
        cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Debug >/dev/null
    fi
fi
results_dir=$build_dir/grade-results
mkdir -p "$results_dir"
all_passed=yes
summary=()
for lab in "${labs[@]}"; do
    # Nothing from an earlier run may stand in for this one.
    rm -f "$results_dir/$lab".*
    xml=$results_dir/$lab.xml
    # Each lab is built on its own, so one lab that does not compile still lets the others
    # be graded.
    echo "grade: building ${lab}${suffix}..."
    if ! cmake --build "$build_dir" --parallel 2 --target "${lab}${suffix}" >"$results_dir/$lab.build.log" 2>&1; then
        cat "$results_dir/$lab.build.log" >&2
        echo "grade: $lab did not build (compiler errors above, also in $results_dir/$lab.build.log)" >&2
        write_empty_junit "$xml"
        add_junit_failure "$xml" "$lab.Build" "did not build: no test of this lab ran" \
            "$(grep -E ': (fatal )?error' "$results_dir/$lab.build.log" | head -n 40)"
        summary+=("$lab build")
        all_passed=no
        continue
    fi
    program=$(find_test_program "$build_dir" "${lab}${suffix}")
    if [[ -z $program ]]; then
        echo "grade: ${lab}${suffix} was not built; does tests/labs/ have this lab's tests?" >&2
        summary+=("$lab notests")
        all_passed=no
        continue
    fi
    echo "grade: running $lab..."
    results=$results_dir/$lab.results
    run_gtest "$program" "$results" "$xml" || all_passed=no
    mv "$results.log" "$results_dir/$lab.log"
    # The tasks marked in the code, and any task the tests name (in case a TASK comment
    # was deleted along the way).
    mapfile -t tasks < <({
        lab_tasks "$(lab_folder "$lab")"
        awk '{ s = $2; sub(/\..*/, "", s); if (match(s, /^Task[0-9]+/)) print substr(s, 5, RLENGTH - 4) }' "$results"
    } | sort -n -u)
    for task in "${tasks[@]}"; do
        read -r passed failed < <(task_counts "$results" "$task")
        summary+=("$lab $task $passed $failed $(task_stopped "$results" "$task")")
    done
    # Tests that belong to no task (e.g. the level starts as the sheet says).
    read -r passed failed < <(awk '{ s = $2; sub(/\..*/, "", s) } s !~ /^Task[0-9]/ {
        if ($1 == "PASS") p++; else f++ } END { printf "%d %d\n", p, f }' "$results")
    if [[ $((passed + failed)) -gt 0 ]]; then
        summary+=("$lab - $passed $failed $(task_stopped "$results" -)")
    fi
    rm -f "$results"
done

echo
printf '%-28s %-5s %-7s %-7s\n' LAB TASK PASSED FAILED
for row in "${summary[@]}"; do
    read -r lab task passed failed stopped <<<"$row"
    case $task in
        build) printf '%-28s %-5s %s\n' "$lab" - "did not build  <- see $results_dir/$lab.build.log" ;;
        notests) printf '%-28s %-5s %s\n' "$lab" - "no grading tests" ;;
        *)
            mark=""
            [[ $failed -gt 0 ]] && mark="  <- see $results_dir/$lab.log"
            [[ -n $stopped ]] && mark="  <- $stopped; see $results_dir/$lab.log"
            printf '%-28s %-5s %-7s %-7s%s\n' "$lab" "$task" "$passed" "$failed" "$mark"
            ;;
    esac
done
echo "JUnit XML: $results_dir/<lab>.xml"
if [[ $all_passed == yes ]]; then
    echo "grade: every test passed"
    exit 0
fi
echo "grade: some tests failed"
exit 1
