#!/usr/bin/env bash
# make-figures.sh BUILD_DIR [--allow-missing]
#
# Draws the slides' screenshots with the project's own programs, so a figure always shows
# what the code really does. Each line of figures.txt names an output PNG, a program (a
# path inside BUILD_DIR) and its arguments (a set-up state: --frames/--seed/--debug and the
# program's own options). Every program is run under xvfb-run with --screenshot into
# figures/generated/. A missing program or an empty PNG fails, naming it; with
# --allow-missing (drafts only) they are reported and skipped.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

if [[ $# -lt 1 ]]; then
    echo "usage: $0 BUILD_DIR [--allow-missing]" >&2
    exit 2
fi
build_dir="$(cd "$1" && pwd)"
allow_missing=false
[[ "${2:-}" == "--allow-missing" ]] && allow_missing=true

out_dir="$here/figures/generated"
mkdir -p "$out_dir"
export ALSOFT_DRIVERS=null # programs with sound stay silent without a sound device

# A display: use the one we have, otherwise run this whole script once under xvfb-run
# (one X server for all figures instead of one per figure).
if [[ -z "${DISPLAY:-}" ]]; then
    if ! command -v xvfb-run >/dev/null; then
        echo "make-figures: xvfb-run is needed (apt-get install xvfb xauth)" >&2
        exit 1
    fi
    exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "$@"
fi

failures=()
made=0
while read -r name program arguments; do
    [[ -z "$name" || "$name" == \#* ]] && continue
    executable="$build_dir/$program"
    target="$out_dir/$name"
    if [[ ! -x "$executable" ]]; then
        failures+=("$name: program $program not found in $build_dir")
        continue
    fi
    rm -f "$target"
    # shellcheck disable=SC2086 # the arguments column is split into words on purpose
    if ! "$executable" --screenshot "$target" $arguments \
        >"$out_dir/$name.log" 2>&1; then
        failures+=("$name: $program $arguments failed (see figures/generated/$name.log)")
        continue
    fi
    if [[ ! -s "$target" ]]; then
        failures+=("$name: $program wrote no image (empty or missing $target)")
        continue
    fi
    rm -f "$out_dir/$name.log"
    made=$((made + 1))
done <"$here/figures.txt"

echo "make-figures: $made figure(s) made in slides/figures/generated/"
if [[ ${#failures[@]} -gt 0 ]]; then
    printf 'make-figures: %s\n' "${failures[@]}" >&2
    if ! $allow_missing; then
        echo "make-figures: ${#failures[@]} figure(s) missing" >&2
        exit 1
    fi
fi
