#!/usr/bin/env bash
# Writes a Gradescope autograder zip for one lab: setup.sh (installs the packages and builds
# the instructor's tests), run_autograder (grades /autograder/submission into
# /autograder/results/results.json: one test per task, 1 point each, with the feedback), and
# the instructor's tree (hidden variants included; the zip is for Gradescope only, never for
# students).
# Usage: scripts/make-gradescope.sh LAB OUT.zip     e.g. lab02_bouncing_balls autograder.zip
set -euo pipefail
HITBOX_CALLER=$PWD # relative paths on the command line are the caller's (from_caller)
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh
if [[ $# -ne 2 ]]; then
    echo "usage: $0 LAB OUT.zip   (the labs: $(lab_names | paste -sd' ' -))" >&2
    exit 2
fi
lab=$1
out=$(realpath -m "$(from_caller "$2")")
mapfile -t labs < <(lab_names)
if ! is_one_of "$lab" "${labs[@]}"; then
    echo "make-gradescope: no lab called '$lab'; the labs: $(lab_names | paste -sd' ' -)" >&2
    exit 2
fi
staging=$(mktemp -d)
trap 'rm -rf "$staging"' EXIT
mkdir "$staging/hitbox"
git ls-files --cached --others --exclude-standard -z |
    grep -zvE '^(slides|docs|pong|tests/pong|tests/benchmarks|tests/long|tests/course|\.ci)/' |
    xargs -0 cp --parents -t "$staging/hitbox" 2>/dev/null || true
cp scripts/grading/gradescope/setup.sh scripts/grading/gradescope/run_autograder "$staging/"
echo "$lab" >"$staging/lab.txt"
rm -f "$out"
(cd "$staging" && zip -qr "$out" .)
echo "make-gradescope: wrote $out ($lab; upload it as the autograder of a Gradescope assignment)"
