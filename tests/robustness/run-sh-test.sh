#!/usr/bin/env bash
# scripts/run.sh with no display (issue 19, item 4): one line saying so, a picture saved
# under xvfb-run, where it is, and it stops (exit 0) - no window run forever, no audio spam.
# Usage: run-sh-test.sh SOURCE_DIR BUILD_DIR
set -uo pipefail
command -v xvfb-run >/dev/null || { echo "xvfb-run is not installed: nothing to test"; exit 0; }
picture="$2/pong-screenshot.png"
rm -f "$picture"
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 # GL under Xvfb (platform notes)
output=$(env -u DISPLAY -u WAYLAND_DISPLAY -u ALSOFT_DRIVERS HITBOX_RUN_BUILD_DIR="$2" \
    timeout 120 "$1/scripts/run.sh" 2>&1)
code=$?
echo "$output"
failures=0
[[ $code -eq 0 ]] || { echo "FAIL: exit $code, expected 0" >&2; failures=1; }
[[ $(wc -l <<<"$output") -eq 2 ]] || { echo "FAIL: expected two lines (no display; saved)" >&2; failures=1; }
grep -q "^run.sh: no display here" <<<"$output" || { echo "FAIL: no 'no display' line" >&2; failures=1; }
grep -qF "run.sh: saved $(realpath "$2")/pong-screenshot.png" <<<"$output" || { echo "FAIL: no line saying where the picture is" >&2; failures=1; }
[[ -s $picture ]] || { echo "FAIL: no picture at $picture" >&2; failures=1; }
[[ $failures -eq 0 ]]
