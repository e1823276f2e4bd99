#!/usr/bin/env bash
# Installs what is missing, builds the release programs and starts Pong (the sample).
# Usage: ./scripts/run.sh [program] [options]    e.g. ./scripts/run.sh sandbox --debug
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/install-deps.sh
program=pong
if [[ $# -gt 0 && $1 != --* ]]; then
    program=$1
    shift
fi
cmake --preset release >/dev/null
programs=$(cmake --build --preset release --target help | sed -n 's/^\.\.\. \(pong\|sandbox\|lab[0-9][0-9]_[a-z_]*\)$/\1/p' | grep -vE "_(level|tests)$" | sort -u)
if ! grep -qx -- "$program" <<<"$programs"; then
    echo "run.sh: no program called '$program'. The programs are:" $programs >&2
    exit 2
fi
cmake --build --preset release --target "$program"
binary=$(find build/release -type f -name "$program" -perm -u+x | head -n 1)
if [[ -z ${DISPLAY:-}${WAYLAND_DISPLAY:-} && " $* " != *" --headless "* ]]; then
    echo "No display here: running under xvfb-run (add --screenshot out.png to see a frame)."
    exec xvfb-run -a "$binary" "$@"
fi
exec "$binary" "$@"
