#!/usr/bin/env bash
# CI stage 3: each program named runs headless with no display, and refuses (with a message,
# not a crash) to open a window with none. Usage: headless-programs.sh PROGRAM...
set -euo pipefail
for program in "$@"; do
    env -u DISPLAY -u WAYLAND_DISPLAY "$program" --headless --frames 120
    if env -u DISPLAY -u WAYLAND_DISPLAY "$program" 2>/dev/null; then
        echo "expected $program to refuse to open a window with no display" >&2
        exit 1
    fi
done
