#!/usr/bin/env bash
# Checks the student handout the way a student and a grader will use it:
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
HITBOX_CALLER=$PWD # relative paths on the command line are the caller's (from_caller)
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh
repo=$(pwd)

usage() {
    echo "usage: $0 [--lab NAME]... [--out DIR]" >&2
    exit 2
}
chosen=()
out=build/handout-check
while [[ $# -gt 0 ]]; do
    case $1 in
        --lab) [[ $# -ge 2 ]] || usage; chosen+=("$2"); shift 2 ;;
        --out) [[ $# -ge 2 ]] || usage; out=$(from_caller "$2"); shift 2 ;;
        -h | --help) usage ;;
        *) echo "check-handout: unknown option '$1'" >&2; usage ;;
    esac
done
export ALSOFT_DRIVERS=null

mapfile -t labs < <(lab_names)
if [[ ${#chosen[@]} -gt 0 ]]; then
    for lab in "${chosen[@]}"; do
        is_one_of "$lab" "${labs[@]}" || { echo "check-handout: no lab '$lab'" >&2; exit 2; }
    done
    labs=("${chosen[@]}")
fi

echo "== 1. Writing the handout to $out"
rm -rf "$out"
./scripts/make-handout.sh "$out"
out=$(cd "$out" && pwd)

echo "== 2. Building it on its own (lab programs and lab tests only)"
launcher=()
if command -v ccache >/dev/null; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$repo}
fi
(cd "$out" && cmake --preset debug "${launcher[@]}" >/dev/null)
targets=()
for lab in "${labs[@]}"; do
    targets+=("$lab" "${lab}_tests")
done
build() {
    if ! cmake --build "$out/build/debug" --parallel 2 --target "$@" >"$out/build.log" 2>&1; then
        cat "$out/build.log" >&2
        echo "check-handout: the handout does not build (see above)" >&2
        exit 1
    fi
}
build "${targets[@]}"

problems=()
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The folder and task numbers of each lab, read from the solution (the handout has none).
declare -A folder_of tasks_of
max_tasks=0
for lab in "${labs[@]}"; do
    folder_of[$lab]=$(lab_folder "$lab")
    tasks_of[$lab]=$(lab_tasks "${folder_of[$lab]}" | tr '\n' ' ')
    count=$(wc -w <<<"${tasks_of[$lab]}")
    ((count > max_tasks)) && max_tasks=$count
done

echo "== 3. The untouched handout: only task tests fail, every task has a failing test"
printf '%-28s %-5s %s\n' LAB TASK "FAILING (of all)"
for lab in "${labs[@]}"; do
    program=$(find_test_program "$out/build/debug" "${lab}_tests")
    run_gtest "$program" "$work/$lab" || true
    for task in ${tasks_of[$lab]}; do
        read -r passed failed < <(task_counts "$work/$lab" "$task")
        printf '%-28s %-5s %s\n' "$lab" "$task" "$failed of $((passed + failed))"
        [[ $failed -gt 0 ]] || problems+=("$lab task $task: no test fails on the untouched handout")
    done
    non_task_failures=$(awk '{ s = $2; sub(/\..*/, "", s) } $1 == "FAIL" && s !~ /^Task[0-9]/ { print $2 }' "$work/$lab")
    [[ -z $non_task_failures ]] ||
        problems+=("$lab: tests that belong to no task fail on the handout: $non_task_failures")
done

echo "== 4. Pasting the solution in, one task more at a time"
printf '%-28s %-12s %s\n' LAB "SOLVED" "RESULT"
for ((step = 1; step <= max_tasks; step++)); do
    step_targets=()
    declare -A solved_now=()
    for lab in "${labs[@]}"; do
        read -r -a tasks <<<"${tasks_of[$lab]}"
        ((step <= ${#tasks[@]})) || continue
        solved=$(printf '%s,' "${tasks[@]:0:step}")
        solved_now[$lab]=${solved%,}
        folder=${folder_of[$lab]}
        while IFS= read -r source; do
            cmake "-DINPUT=$source" "-DOUTPUT=$out/$source" "-DSOLVED_TASKS=${solved_now[$lab]}" \
                -P framework/cmake/HitboxMakeExercise.cmake
        done < <(find "$folder" -type f \( -name '*.cpp' -o -name '*.h' -o -name '*.hpp' \))
        step_targets+=("${lab}_tests")
    done
    build "${step_targets[@]}"
    for lab in "${labs[@]}"; do
        [[ -n ${solved_now[$lab]:-} ]] || continue
        program=$(find_test_program "$out/build/debug" "${lab}_tests")
        run_gtest "$program" "$work/$lab" || true
        result=ok
        for task in ${solved_now[$lab]//,/ }; do
            read -r passed failed < <(task_counts "$work/$lab" "$task")
            if [[ $failed -gt 0 ]]; then
                result="FAIL"
                problems+=("$lab: with tasks ${solved_now[$lab]} pasted in, $failed test(s) of task $task fail:" \
                    "$(grep '^FAIL' "$work/$lab" | cut -d' ' -f2 | tr '\n' ' ')")
            fi
        done
        # The tasks not pasted yet should still fail: the paste really was one task at a time.
        still_failing=$(awk -v solved=",${solved_now[$lab]}," '$1 == "FAIL" {
            s = $2; sub(/\..*/, "", s); if (match(s, /^Task[0-9]+/) && index(solved, "," substr(s, 5, RLENGTH - 4) ",") == 0) n++ }
            END { print n + 0 }' "$work/$lab")
        printf '%-28s %-12s %s\n' "$lab" "${solved_now[$lab]}" "$result ($still_failing tests of later tasks still fail)"
    done
    unset solved_now
done

if [[ ${#problems[@]} -gt 0 ]]; then
    echo "check-handout: FAILED" >&2
    printf '  - %s\n' "${problems[@]}" >&2
    exit 1
fi
echo "check-handout: the handout builds alone, fails only on unfinished tasks, and passes each task once its solution is in"
