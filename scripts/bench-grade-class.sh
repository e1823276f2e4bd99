#!/usr/bin/env bash
# Measures the class grader on lab 2: a made-up class of N realistic submissions (solutions,
# one task wrong, the starter, not compiling, crashing in a task, hanging in a task) plus,
# with --hostile, five hostile ones (a hang, an output flood, a compile bomb, a 10 GiB file,
# a fork storm; scripts/labtool/tricks.py), graded
#   1. cold: a new instructor build folder (ccache, if installed, still warm:
#      CCACHE_DISABLE=1 in the environment measures without it), then
#   2. again with the instructor's build in place.
# Prints the machine's load with each figure (the wall-clock time depends on what else runs)
# and the CPU seconds of the grader and everything it ran.
# Usage: scripts/bench-grade-class.sh [--count N] [--hostile] [WORK_DIR]   (30, build/bench-grade-class)
set -euo pipefail
count=30
hostile=()
work=build/bench-grade-class
while [[ $# -gt 0 ]]; do
    case $1 in
        --count) count=$2; shift 2 ;;
        --hostile) hostile=(--hostile); shift ;;
        *) work=$1; shift ;;
    esac
done
mkdir -p "$work"
work=$(cd "$work" && pwd)
cd "$(dirname "$0")/.."
rm -rf "$work/instructor" "$work"/grades-*
python3 scripts/lab.py tricks bench "$work/class" --count "$count" "${hostile[@]}"
# grade_once NAME: grade the class into $work/grades-NAME; prints the time, CPU time and load.
grade_once() {
    local start=$SECONDS load
    load=$(cut -d' ' -f1 /proc/loadavg)
    /usr/bin/time -f '%e %U %S' -o "$work/$1.time" \
        ./scripts/grade-class.sh "$work/class" --lab 02 --out "$work/grades-$1" --build "$work/instructor" >"$work/$1.log"
    read -r wall user system <"$work/$1.time"
    echo "bench: $1: $(ls "$work/class" | wc -l) submissions in ${wall} s wall, $(echo "$user + $system" | bc) CPU s" \
        "(load before $load, after $(cut -d' ' -f1 /proc/loadavg) on $(nproc) cores; $((SECONDS - start)) s)"
}
grade_once cold
grade_once warm
grep -E '^\[' "$work/warm.log" | sed 's/^/    /'
cmp -s "$work/grades-cold/grades.csv" "$work/grades-warm/grades.csv" ||
    { echo "bench: the two runs gave different grades" >&2; exit 1; }
echo "bench: both runs gave the same grades ($work/grades-warm/grades.csv)"
