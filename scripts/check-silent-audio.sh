#!/usr/bin/env bash
# Hitbox's own programs with no sound device (issue 25, finding 26): Pong, in a window under
# Xvfb with sound on, run with no ALSOFT_DRIVERS and no sound server must print one line
# ("no sound device found") and stay silent, not an OpenAL error for every sound (before:
# 223 lines in 5 s). About 10 s. Usage: scripts/check-silent-audio.sh [BUILD_FOLDER]
set -euo pipefail
build=${1:-build/debug}
pong="$build/pong/pong"
seconds=5
most_lines=3 # the one line, plus what SFML or the X server may say once (vertical sync)
[[ -x $pong ]] || { echo "check-silent-audio: no $pong (build the pong target first)" >&2; exit 2; }
if compgen -G "/dev/snd/pcm*" >/dev/null; then
    echo "check-silent-audio: SKIP (this machine has a sound card, so OpenAL has a device)"
    exit 0
fi
output=$(mktemp)
trap 'rm -f "$output"' EXIT
# timeout inside xvfb-run: Pong is stopped, then xvfb-run closes its display.
env -u ALSOFT_DRIVERS -u PULSE_SERVER -u XDG_RUNTIME_DIR \
    xvfb-run -a timeout "$seconds" "$pong" --mode cvc >"$output" 2>&1 || true
lines=$(wc -l <"$output")
said=$(<"$output")
if ((lines > most_lines)) || [[ $said =~ (AL lib|OpenAL|AL_INVALID) ]] ||
    [[ $said != *"no sound device found"* ]]; then
    echo "check-silent-audio: FAIL: Pong printed $lines lines in ${seconds} s with no sound device (at most $most_lines, one saying 'no sound device found'):" >&2
    head -n 20 "$output" >&2
    exit 1
fi
echo "check-silent-audio: Pong with no sound device: $lines lines in ${seconds} s (one says so)"
