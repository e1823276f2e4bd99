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
# NAME.apng (for the HTML, looping) and a still NAME.png for the PDF: three of its frames
# in a labelled strip (tools/check-stills.sh: each panel is one clean frame). Both are
# checked the same way as a picture.
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
# into TARGET.apng, and its still for the PDF, TARGET.png (same name, .png): the first, middle
# and last frames side by side (or one above the other, whichever shows them larger on a
# slide), each under a label with its number and time. Never frames laid over each other:
# a handout must show each moment cleanly (tools/check-stills.sh checks every panel is one
# of the animation's frames, pixel for pixel).
animate() {
    local executable="$1" target="$2" log="$3" frames="$4"
    shift 4
    local first last step frame count=0 folder="$target.frames"
    IFS=: read -r first last step <<<"$frames"
    rm -rf "$folder" && mkdir -p "$folder"
    local times=()
    for ((frame = first; frame <= last; frame += step)); do
        draw "$executable" "$folder/$(printf %03d $count).png" "$log" "$@" --frames "$frame" || return 1
        times+=("$frame")
        count=$((count + 1))
    done
    ffmpeg -nostdin -loglevel error -y -framerate 2 -i "$folder/%03d.png" -plays 0 -f apng "$target" >>"$log" 2>&1 || return 1
    strip "$folder" "${target%.apng}.png" "$log" "${times[@]}" || return 1
    rm -rf "$folder"
}

# strip FOLDER STILL LOG STEPS...: the still of an animation whose frames are FOLDER/000.png...
# (STEPS: each frame's fixed steps), three labelled panels (one when there is one frame).
strip() {
    local folder="$1" still="$2" log="$3"
    shift 3
    local steps=("$@") count=$#
    local picks=(0)
    [[ $count -ge 3 ]] && picks=(0 $(((count - 1) / 2)) $((count - 1)))
    [[ $count -eq 2 ]] && picks=(0 1)
    local size w h
    size="$(ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=p=0 "$folder/000.png")"
    IFS=, read -r w h <<<"$size"
    # The layout that shows the frames larger in a figure slide's 1200x560, and the label size
    # that is still 28 px there.
    local n=${#picks[@]} layout font band
    read -r layout font band < <(python3 -c '
import math, sys
w, h, n = (int(a) for a in sys.argv[1:])
best = None
for layout in ("h", "v"):
    font = 40
    for _ in range(4):
        band = round(font * 1.5)
        W, H = (n * w, h + band) if layout == "h" else (w, n * (h + band))
        scale = min(1200 / W, 560 / H, 1.0)
        font = max(28, math.ceil(28 / scale))
    if best is None or scale > best[0]:
        best = (scale, layout, font, band)
print(best[1], best[2], best[3])' "$w" "$h" "$n") || return 1
    local inputs=() graph="" labels="" i=0 pick
    for pick in "${picks[@]}"; do
        local label="$folder/label-$i.txt"
        # The label: the frame's number in the strip and its time (a fixed step is 1/120 s).
        python3 -c 'import sys; print(f"{sys.argv[1]}   t = {int(sys.argv[2]) / 120:.2f} s", end="")' \
            "$((i + 1))" "${steps[$pick]}" >"$label"
        inputs+=(-i "$folder/$(printf %03d "$pick").png")
        graph+="[$i:v]format=rgb24,pad=$w:$((h + band)):0:$band:white,drawtext=fontfile=$font_file:textfile=$label:fontsize=$font:fontcolor=black:x=(w-text_w)/2:y=($band-text_h)/2[p$i];"
        labels+="[p$i]"
        i=$((i + 1))
    done
    if [[ $n -gt 1 ]]; then
        graph+="${labels}$([[ $layout == h ]] && echo hstack || echo vstack)=inputs=$n[out]"
    else
        graph+="${labels}null[out]"
    fi
    ffmpeg -nostdin -loglevel error -y "${inputs[@]}" -filter_complex "$graph" -map "[out]" "$still" >>"$log" 2>&1
}
font_file=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf

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
    if [[ "$name" == *.apng ]] && ! "$here/tools/check-stills.sh" "$target" 2>>"$log"; then
        failures+=("$name: its still ${name%.apng}.png is not made of clean frames (see $log)")
        rm -f "$again" "${again%.apng}.png"
        continue
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
