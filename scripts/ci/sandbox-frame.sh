#!/usr/bin/env bash
# CI stage 4: the sandbox draws a frame under Xvfb; 4a: the debug view's free/touching/
# overlapping colours stay apart under protanopia, deuteranopia and tritanopia (issue 27 item
# 6; ~10 s; simulated screenshots in BUILD_DIR/palette). Usage: sandbox-frame.sh BUILD_DIR
set -euo pipefail
build=$1
xvfb-run -a "$build/framework/sandbox" --screenshot "$build/sandbox.png" --debug --frames 10
test -s "$build/sandbox.png"
python3 "$(dirname "$0")/../check-palette.py" "$build/palette" "$build/sandbox.png"
