#!/usr/bin/env bash
# CI stage 4b: an hour of Pong, computer against computer, twice with one seed gives the same
# line (the simulation is deterministic); each screen draws under Xvfb.
# Usage: pong-hour.sh BUILD_DIR
set -euo pipefail
build=$1
first=$("$build/pong/pong" --headless --seconds 3600 --seed 7)
second=$("$build/pong/pong" --headless --seconds 3600 --seed 7)
echo "$first"
if [[ "$first" != "$second" ]]; then
    echo "pong: the same seed gave two different games:" >&2
    echo "$second" >&2
    exit 1
fi
for screen in title play win; do
    xvfb-run -a "$build/pong/pong" --screen "$screen" --frames 200 --debug \
        --screenshot "$build/pong-$screen.png"
    test -s "$build/pong-$screen.png"
done
