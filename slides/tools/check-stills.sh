#!/usr/bin/env bash
# check-stills.sh NAME.apng... - each animation's still (NAME.png, the PDF's picture) is one
# frame or a strip of frames (in a row with white gutters, or in a column), each under a label
# band and exactly one of the animation's frames, pixel for pixel, as it is or doubled
# (make-figures.py's zoom). Frames laid over each other match no frame and fail, naming the
# panel. Needs ffmpeg and ffprobe. Exit 1 on a bad still, 2 on usage.
set -euo pipefail
[[ $# -lt 1 ]] && { echo "usage: $0 NAME.apng..." >&2; exit 2; }

# size FILE: "W H"; md5s INPUT [FILTER]: the md5 of every decoded frame (as rgb24), one a line.
size() { ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=p=0 "$1" | tr , ' '; }
md5s() { ffmpeg -nostdin -loglevel error -i "$1" ${2:+-vf "$2"} -pix_fmt rgb24 -f framemd5 - | awk '!/^#/ { print $NF }'; }
problems=0
bad() { echo "check-stills: $*" >&2; problems=$((problems + 1)); }
for animation in "$@"; do
    still="${animation%.apng}.png"
    if [[ ! -s "$animation" || ! -s "$still" ]]; then
        bad "$animation: the animation or its still $still is missing"
        continue
    fi
    read -r w0 h0 <<<"$(size "$animation")"
    read -r W H <<<"$(size "$still")"
    clean=false message="${still} (${W}x$H) is not made of ${w0}x$h0 frames of $animation"
    for zoom in 1 2; do
        w=$((w0 * zoom)) h=$((h0 * zoom))
        # The layouts it may have: n panels of w x (h + band), in a row with g-pixel gutters
        # (W = n w + (n - 1) g) or a column (W = w; n = 3, 2 or 1). Passes when, in one of
        # them, every panel is a frame.
        layouts=()
        if ((W > w && H >= h)); then
            for n in 3 2; do
                ((W >= n * w && (W - n * w) % (n - 1) == 0)) || continue
                g=$(((W - n * w) / (n - 1)))
                layout="" && for ((i = 0; i < n; i++)); do layout+="crop=$w:$h:$((i * (w + g))):$((H - h)) "; done
                layouts+=("$layout")
            done
        elif ((W == w)); then
            for n in 3 2 1; do
                ((H % n == 0 && H / n >= h)) || continue
                layout="" && for ((i = 0; i < n; i++)); do layout+="crop=$w:$h:0:$((i * H / n + H / n - h)) "; done
                layouts+=("$layout")
            done
        fi
        [[ ${#layouts[@]} -eq 0 ]] && continue
        frames="$(md5s "$animation" "scale=iw*$zoom:ih*$zoom:flags=neighbor")"
        for layout in "${layouts[@]}"; do
            message="" i=0
            for panel in $layout; do
                i=$((i + 1))
                if ! grep -qx "$(md5s "$still" "$panel")" <<<"$frames"; then
                    message="panel $i is not one frame of $animation (frames laid over each other?)"
                    break
                fi
            done
            [[ -z "$message" ]] && clean=true && break 2
        done
    done
    $clean || bad "$still: $message"
done
[[ $problems -eq 0 ]] || exit 1
