#!/usr/bin/env bash
# make-figures.sh BUILD_DIR [--allow-missing] [--list FILE] [--out DIR]
#
# Draws the slides' screenshots with the project's own programs, so a figure always shows
# what the code really does. Each line of figures.txt (or FILE) names an output PNG, a
# program (a path inside BUILD_DIR), its arguments (a set-up state: --frames/--seed and the
# program's own options) and, after a `|`, the arguments that make what the figure claims to
# show (--debug for "the debug view", --method quadtree for "the quadtree"). An argument
# crop=W:H:X:Y is not passed on: the picture is cut to that rectangle (ffmpeg), to show the
# part the slide is about at a size the back row can read. Every program
# runs under xvfb-run with --screenshot into figures/generated/ (or DIR), and each figure is
# checked:
# - drawn twice, the same pixels: nothing run-dependent (a timing, a clock) is on it;
# - drawn once more without the claimed arguments, different pixels: the claimed part is
#   really drawn (a quadtree figure that looks the same as the default grid fails).
# An output NAME.apng is an animation: an argument frames=FIRST:LAST:STEP draws the picture
# after FIRST, FIRST+STEP, ... LAST fixed steps (--frames), and ffmpeg joins them into
# NAME.apng (for the HTML, looping) and an onion-skin still NAME.png (every frame laid over
# the others, lightest wins: for the PDF). Both are checked the same way as a picture.
# A missing program, a failed run, an empty PNG or a failed check fails, naming the figure;
# with --allow-missing (drafts only) they are reported and skipped.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

usage() { echo "usage: $0 BUILD_DIR [--allow-missing] [--list FILE] [--out DIR]" >&2; exit 2; }
[[ $# -lt 1 ]] && usage
build_dir="$(cd "$1" && pwd)"
shift
allow_missing=false
list="$here/figures.txt"
out_dir="$here/figures/generated"
while [[ $# -gt 0 ]]; do
    case "$1" in
    --allow-missing) allow_missing=true ;;
    --list) list="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift ;;
    --out) mkdir -p "$2"; out_dir="$(cd "$2" && pwd)"; shift ;;
    *) usage ;;
    esac
    shift
done
mkdir -p "$out_dir"
export ALSOFT_DRIVERS=null # programs with sound stay silent without a sound device

# A display: use the one we have, otherwise run this whole script once under xvfb-run
# (one X server for all figures instead of one per figure).
if [[ -z "${DISPLAY:-}" ]]; then
    if ! command -v xvfb-run >/dev/null; then
        echo "make-figures: xvfb-run is needed (apt-get install xvfb xauth)" >&2
        exit 1
    fi
    exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "$build_dir" \
        $($allow_missing && echo --allow-missing) --list "$list" --out "$out_dir"
fi

# draw EXECUTABLE TARGET LOG ARGUMENTS...: one screenshot (cropped when an argument is
# crop=W:H:X:Y); false when the run fails.
draw() {
    local executable="$1" target="$2" log="$3" crop="" argument
    shift 3
    local passed=()
    for argument in "$@"; do
        if [[ "$argument" == crop=* ]]; then crop="${argument#crop=}"; else passed+=("$argument"); fi
    done
    rm -f "$target"
    "$executable" --screenshot "$target" "${passed[@]}" </dev/null >"$log" 2>&1 || return 1
    if [[ -n "$crop" && -s "$target" ]]; then
        ffmpeg -nostdin -loglevel error -y -i "$target" -vf "crop=$crop" "$target.crop.png" >>"$log" 2>&1 || return 1
        mv "$target.crop.png" "$target"
    fi
}

# animate EXECUTABLE TARGET.apng LOG FRAMES ARGUMENTS...: the frames of an animation, joined
# into TARGET.apng, and its onion-skin still TARGET.png (same name, .png).
animate() {
    local executable="$1" target="$2" log="$3" frames="$4"
    shift 4
    local first last step frame count=0 folder="$target.frames"
    IFS=: read -r first last step <<<"$frames"
    rm -rf "$folder" && mkdir -p "$folder"
    for ((frame = first; frame <= last; frame += step)); do
        draw "$executable" "$folder/$(printf %03d $count).png" "$log" "$@" --frames "$frame" || return 1
        count=$((count + 1))
    done
    ffmpeg -nostdin -loglevel error -y -framerate 2 -i "$folder/%03d.png" -plays 0 -f apng "$target" >>"$log" 2>&1 || return 1
    # Onion skin: each frame blended over the ones before it, the lighter pixel kept.
    local inputs=() graph="" previous="[0:v]" i
    for ((i = 0; i < count; i++)); do inputs+=(-i "$folder/$(printf %03d $i).png"); done
    for ((i = 1; i < count; i++)); do
        graph+="${previous}[$i:v]blend=all_mode=lighten[m$i];"
        previous="[m$i]"
    done
    if [[ $count -gt 1 ]]; then
        ffmpeg -nostdin -loglevel error -y "${inputs[@]}" -filter_complex "${graph%;}" -map "$previous" \
            "${target%.apng}.png" >>"$log" 2>&1 || return 1
    else
        cp "$folder/000.png" "${target%.apng}.png"
    fi
    rm -rf "$folder"
}

failures=()
made=0
while IFS= read -r line; do
    [[ -z "${line// /}" || "$line" == \#* ]] && continue
    claimed=""
    [[ "$line" == *"|"* ]] && claimed="${line#*|}" && line="${line%%|*}"
    read -r name program arguments <<<"$line"
    read -r -a set_up <<<"$arguments"
    read -r -a claims <<<"$claimed"
    executable="$build_dir/$program"
    target="$out_dir/$name"
    log="$out_dir/$name.log"
    if [[ ! -x "$executable" ]]; then
        failures+=("$name: program $program not found in $build_dir")
        continue
    fi
    # An animation: the frames=FIRST:LAST:STEP argument names its frames.
    paint=draw
    if [[ "$name" == *.apng ]]; then
        frames=""
        kept=()
        for argument in "${set_up[@]}"; do
            if [[ "$argument" == frames=* ]]; then frames="${argument#frames=}"; else kept+=("$argument"); fi
        done
        if [[ -z "$frames" ]]; then
            failures+=("$name: an animation needs frames=FIRST:LAST:STEP")
            continue
        fi
        set_up=("$frames" "${kept[@]}")
        paint=animate
    fi
    if ! $paint "$executable" "$target" "$log" "${set_up[@]}" "${claims[@]}"; then
        failures+=("$name: $program $arguments $claimed failed (see $log)")
        continue
    fi
    if [[ ! -s "$target" ]]; then
        failures+=("$name: $program wrote no image (empty or missing $target)")
        continue
    fi
    again="$out_dir/.again-$name"
    if ! $paint "$executable" "$again" "$log" "${set_up[@]}" "${claims[@]}" ||
        ! cmp -s "$target" "$again"; then
        failures+=("$name: two runs drew different pictures: run-dependent text (a timing?) or state on the figure")
        rm -f "$again"
        continue
    fi
    if [[ ${#claims[@]} -gt 0 ]]; then
        if ! $paint "$executable" "$again" "$log" "${set_up[@]}" || cmp -s "$target" "$again"; then
            failures+=("$name: claims '${claims[*]}' but looks the same without it")
            rm -f "$again"
            continue
        fi
    fi
    rm -f "$again" "$log" "${again%.apng}.png"
    made=$((made + 1))
done <"$list"

echo "make-figures: $made figure(s) made and checked in $out_dir"
if [[ ${#failures[@]} -gt 0 ]]; then
    printf 'make-figures: %s\n' "${failures[@]}" >&2
    if ! $allow_missing; then
        echo "make-figures: ${#failures[@]} figure(s) missing or wrong" >&2
        exit 1
    fi
fi
