#!/usr/bin/env bash
# Long runs and big worlds (issue 25, items 12, 13, 16 and 21): a headless run says how far it
# is on stderr every few seconds and answers Ctrl-C with one line; --frames N closes a window
# after N steps; a 1000 x 1000 tile level opens a window the screen can hold and saves a
# picture of it. Usage: long-runs.sh BUILD_DIR   (about 20 s)
set -uo pipefail
build=$1
if [[ -z ${DISPLAY:-} && -z ${HITBOX_LONG_RUNS_XVFB:-} ]] && command -v xvfb-run >/dev/null; then
    exec xvfb-run -a -n $((100 + RANDOM % 800)) env HITBOX_LONG_RUNS_XVFB=1 bash "$0" "$@" # -n: its own display number, not 99 (ctest runs tests at once)
fi
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
export ALSOFT_DRIVERS=null
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 # Mesa under Xvfb
program() { find "$build" -type f -perm -u+x -name "$1" -not -path '*/CMakeFiles/*' | head -n 1; }
pong=$(program pong) lab09=$(program lab09_platformer)
failures=0
fail() { failures=$((failures + 1)); echo "FAIL: $*" >&2; }

# Item 13: the longest allowed run, interrupted after 7 s of wall time.
env -u DISPLAY "$pong" --headless --seconds 100000000 >"$work/out" 2>"$work/err" &
runner=$!
sleep 7
kill -INT "$runner"
wait "$runner"
code=$?
progress=$(grep -c '^Pong: [0-9]* of 12000000000 steps simulated (.*%), about .* left; Ctrl-C stops$' "$work/err")
stopped=$(grep -c '^Pong: stopped by Ctrl-C after [0-9]* of 12000000000 steps; nothing more is printed or saved$' "$work/err")
lines=$(wc -l <"$work/err")
if [[ $code -ne 130 || $progress -lt 1 || $stopped -ne 1 || $lines -ne $((progress + 1)) || -s $work/out ]]; then
    fail "a long headless run: exit $code, $progress progress lines, $stopped stop lines, stderr:"
    sed 's/^/    /' "$work/err" >&2
fi
# A short run prints no progress at all.
if [[ -n $(env -u DISPLAY "$pong" --headless --seconds 2 2>&1 >/dev/null) ]]; then
    fail "a two-second run printed on stderr"
fi

if [[ -n ${DISPLAY:-} ]]; then
    # Item 16: --frames in a window closes it after that many steps (before: never).
    if ! timeout 60 "$pong" --frames 30 >"$work/out" 2>&1; then
        fail "pong --frames 30 in a window did not end by itself: $(cat "$work/out")"
    fi
    # Items 12 and 21: 1000 x 1000 tiles are 48000 x 48000 px (before: a segfault in the GL
    # driver for the window, "Impossible to create render texture" for the picture): a wall
    # round 998 x 998 empty tiles, the player's start on the third row.
    wall=$(printf '#%.0s' {1..1000}) empty=$(printf '#%998s#' '')
    { echo "$wall"; echo "$empty"; echo "#P${empty:2}"; for _ in {1..996}; do echo "$empty"; done; echo "$wall"; } |
        tr ' ' . >"$work/big.txt"
    if ! timeout 120 "$lab09" --level "$work/big.txt" --frames 5 >"$work/out" 2>&1; then
        fail "a 1000 x 1000 tile level in a window: $(tail -n 3 "$work/out")"
    fi
    if ! timeout 120 "$lab09" --level "$work/big.txt" --screenshot "$work/big.png" >"$work/out" 2>&1 ||
        [[ ! -s $work/big.png ]]; then
        fail "a picture of a 1000 x 1000 tile level: $(tail -n 3 "$work/out")"
    fi
else
    echo "note: no display and no xvfb-run; the window rows are skipped"
fi
echo "long runs: $failures failed"
[[ $failures -eq 0 ]]
