#!/usr/bin/env bash
# Measures the class grader: a made-up class of N submissions of one lab (a mix of the
# solution, the starter and every "all tasks but one" version, each with a comment that
# makes it differ from the others, as real submissions do), graded
#   1. from a cold start: a new instructor build folder (ccache, if installed, still warm:
#      CCACHE_DISABLE=1 in the environment measures without it), then
#   2. again with the instructor's build in place: the time per additional submission.
# Prints the machine's load before and after: the wall-clock figures depend on what else
# runs. The CPU seconds (user + system of the grader and every compiler, linker and test it
# ran) hardly do: on an idle machine the wall time is about CPU seconds / cores.
# Usage: scripts/bench-grade-class.sh [--lab NAME] [--count N] [WORK_DIR]
#        (default lab02_bouncing_balls, 30, build/bench-grade-class)
set -euo pipefail
HITBOX_CALLER=$PWD # relative paths on the command line are the caller's (from_caller)
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh
lab=lab02_bouncing_balls
count=30
work=build/bench-grade-class
while [[ $# -gt 0 ]]; do
    case $1 in
        --lab) lab=$2; shift 2 ;;
        --count) count=$2; shift 2 ;;
        *) work=$(from_caller "$1"); shift ;;
    esac
done
folder=$(lab_folder "$lab")
mapfile -t tasks < <(lab_tasks "$folder")
rm -rf "$work"
mkdir -p "$work/class"
variants=("$(printf '%s,' "${tasks[@]}")" "")
for task in "${tasks[@]}"; do
    variants+=("$(printf '%s\n' "${tasks[@]}" | grep -vx "$task" | paste -sd, -)")
done
for ((i = 1; i <= count; i++)); do
    solved=${variants[$(((i - 1) % ${#variants[@]}))]}
    into=$work/class/student$(printf '%02d' "$i")/$folder
    mkdir -p "$into"
    while IFS= read -r source; do
        cmake "-DINPUT=$source" "-DOUTPUT=$into/$(basename "$source")" "-DSOLVED_TASKS=${solved%,}" \
            -P framework/cmake/HitboxMakeExercise.cmake
        echo "// student $i" >>"$into/$(basename "$source")"
    done < <(grep -rlE '//[[:space:]]*BEGIN TASK [0-9]+:' "$folder")
done

echo "bench: load before: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
# grade_once NAME: grade the class into $work/grades-NAME; sets seconds and cpu_seconds.
grade_once() {
    local start
    start=$(date +%s.%N)
    /usr/bin/time -f '%U %S' -o "$work/$1.cpu" \
        ./scripts/grade-class.sh "$work/class" --lab "$lab" --out "$work/grades-$1" --build "$work/instructor"
    seconds=$(echo "$(date +%s.%N) - $start" | bc)
    cpu_seconds=$(awk 'END { print $1 + $2 }' "$work/$1.cpu")
    echo "bench: load after the $1 run: $(cut -d' ' -f1-3 /proc/loadavg)"
}
grade_once cold
cold=$seconds cold_cpu=$cpu_seconds
grade_once warm
warm=$seconds warm_cpu=$cpu_seconds
cmp -s "$work/grades-cold/grades.csv" "$work/grades-warm/grades.csv" ||
    { echo "bench: the two runs gave different grades" >&2; exit 1; }
printf 'bench: %d submissions of %s: cold start %.0f s (%.0f CPU s); with the instructor build in place %.0f s (%.1f s per submission; %.1f CPU s per submission)\n' \
    "$count" "$lab" "$cold" "$cold_cpu" "$warm" "$(echo "$warm / $count" | bc -l)" "$(echo "$warm_cpu / $count" | bc -l)"
