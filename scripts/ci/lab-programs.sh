#!/usr/bin/env bash
# CI stage 7: every lab program (solution and exercise) runs headless, and draws a frame under
# Xvfb into BUILD_DIR/NAME.png; then every sheet's screenshot is what its caption's command
# draws, pixel for pixel (issue 26; ~20 s). Usage: lab-programs.sh BUILD_DIR
set -euo pipefail
build=$1
for program in $(find "$build/labs" -mindepth 2 -maxdepth 2 -type f -perm -u+x -name 'lab[0-9][0-9]_*' | sort); do
    env -u DISPLAY -u WAYLAND_DISPLAY "$program" --headless --frames 240
    xvfb-run -a "$program" --frames 180 --debug --screenshot "$build/$(basename "$program").png"
    test -s "$build/$(basename "$program").png"
done
xvfb-run -a python3 "$(dirname "$0")/../../tests/docs/check_screenshots.py" "$build"
