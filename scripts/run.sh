#!/usr/bin/env bash
# Installs what is missing, builds the release programs and starts Pong (the sample).
# Usage: ./scripts/run.sh [program] [options]    e.g. ./scripts/run.sh sandbox --debug
# With no display (no DISPLAY: SFML draws through X11) it says so, saves one frame as a
# picture under xvfb-run, says where, and stops (exit 0; exit 2 when it cannot draw at all).
# HITBOX_RUN_BUILD_DIR=DIR uses an existing build folder instead (the tests do).
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/install-deps.sh
program=pong
if [[ $# -gt 0 && $1 != --* ]]; then
    program=$1
    shift
fi
build=${HITBOX_RUN_BUILD_DIR:-build/release}
config=() # a multi-config generator (CMAKE_GENERATOR=Ninja Multi-Config) builds Release here
if [[ -z ${HITBOX_RUN_BUILD_DIR:-} ]]; then
    cmake --preset release >/dev/null
    config=(--config Release)
fi
# The programs: Pong, the sandbox and every lab (the lab list's one home is scripts/lab.py).
mapfile -t programs < <(echo pong; echo sandbox; python3 scripts/lab.py labs)
if ! grep -qx -- "$program" < <(printf '%s\n' "${programs[@]}"); then
    echo "run.sh: no program called '$program'. The programs are: ${programs[*]}" >&2
    exit 2
fi
cmake --build "$build" --target "$program" "${config[@]}" >/dev/null
binary=$(find "$build" -type f -name "$program" -perm -u+x | head -n 1)
if [[ -z ${DISPLAY:-} && " $* " != *" --headless "* && " $* " != *" --screenshot "* ]]; then
    if ! command -v xvfb-run >/dev/null; then
        echo "run.sh: no display here, so no window can open: run it with --headless, or install xvfb to get a picture." >&2
        exit 2
    fi
    picture="$build/$program-screenshot.png"
    echo "run.sh: no display here, so no window can open; drawing one frame (5 simulated seconds in) instead."
    # No display usually means no sound device either: the null driver keeps the audio quiet.
    ALSOFT_DRIVERS=null xvfb-run -a -n $((100 + RANDOM % 800)) "$binary" --frames 600 "$@" --screenshot "$picture" >/dev/null
    echo "run.sh: saved $(realpath "$picture") - open it to see the frame, or run with --headless."
    exit 0
fi
exec "$binary" "$@"
