#!/usr/bin/env bash
# Measures the class grader: a made-up class of N submissions of one lab (a mix of the
# solution, the starter and every "all tasks but one" version, each with a comment that
# makes it differ from the others, as real submissions do), graded
#   1. from a cold start: a new instructor build folder (ccache, if installed, still warm:
#      CCACHE_DISABLE=1 in the environment measures without it), then
#   2. again with the instructor's build in place: the time per additional submission.
# Prints the machine's load before and after: the figures depend on what else runs.
# Usage: scripts/bench-grade-class.sh [--lab NAME] [--count N] [WORK_DIR]
#        (default lab02_bouncing_balls, 30, build/bench-grade-class)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh
lab=lab02_bouncing_balls
count=30
work=build/bench-grade-class
while [[ $# -gt 0 ]]; do
    case $1 in
        --lab) lab=$2; shift 2 ;;
        --count) count=$2; shift 2 ;;
        *) work=$1; shift ;;
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
start=$(date +%s.%N)
./scripts/grade-class.sh "$work/class" --lab "$lab" --out "$work/grades-cold" --build "$work/instructor"
cold=$(echo "$(date +%s.%N) - $start" | bc)
echo "bench: load after the cold run: $(cut -d' ' -f1-3 /proc/loadavg)"
start=$(date +%s.%N)
./scripts/grade-class.sh "$work/class" --lab "$lab" --out "$work/grades-warm" --build "$work/instructor"
warm=$(echo "$(date +%s.%N) - $start" | bc)
echo "bench: load after the warm run: $(cut -d' ' -f1-3 /proc/loadavg)"
cmp -s "$work/grades-cold/grades.csv" "$work/grades-warm/grades.csv" ||
    { echo "bench: the two runs gave different grades" >&2; exit 1; }
printf 'bench: %d submissions of %s: cold start %.0f s; with the instructor build in place %.0f s (%.1f s per submission)\n' \
    "$count" "$lab" "$cold" "$warm" "$(echo "$warm / $count" | bc -l)"
