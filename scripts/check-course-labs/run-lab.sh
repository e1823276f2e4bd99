# Sourced by scripts/check-course-labs.sh: run_lab runs the lab build_lab built, under Xvfb for
# seconds_to_run seconds, photographs it and checks what it printed and drew. It sets verdict:
# "done" (ok) or "fail" (one FAIL line said why).
run_lab() {
    echo "== $name: run for $seconds_to_run seconds"
    shot="${screenshots:-$PWD/$build}/$name.png"
    rm -f "$shot"
    # Start the lab, let it run, photograph the screen, then close it (runner.sh says how).
    if ! xvfb-run -a -s "-screen 0 1920x1920x24 -ac -noreset" \
        sh scripts/check-course-labs/runner.sh "${inside[*]}" "$build" "$seconds_to_run" "$shot" "$build/run.log" "$mouse_at"; then
        echo "FAIL $name: did not keep running" >&2
        verdict=fail
        return
    fi
    # First the flood (its lines would bury everything else).
    lines=$(wc -l <"$build/run.log")
    if [[ $lines -gt $most_output_lines ]]; then
        sort "$build/run.log" | uniq -c | sort -rn | head -n 3 >&2
        echo "FAIL $name: printed $lines lines in $seconds_to_run seconds (output: $build/run.log)" >&2
        verdict=fail
        return
    fi
    # SFML says when a picture, font or sound does not load (a white box, no text, silence).
    if grep -E "Failed to (load|open)" "$build/run.log" >&2; then
        echo "FAIL $name: a file did not load (output: $build/run.log)" >&2
        verdict=fail
        return
    fi
    missing=0
    for line in "${run_says[@]}"; do
        grep -qF -- "$line" "$build/run.log" || { echo "FAIL $name: did not print \"$line\" (output: $build/run.log)" >&2; missing=1; }
    done
    if [[ $missing != 0 ]]; then
        verdict=fail
        return
    fi
    # Blank: nothing but the screen's black and the window's clear colour.
    colours=$(ffmpeg -loglevel error -i "$shot" -vf scale=480:-1:flags=neighbor -f rawvideo -pix_fmt rgb24 - |
        python3 -c 'import sys; d = sys.stdin.buffer.read(); print(len({d[i:i + 3] for i in range(0, len(d), 3)}))')
    if [[ $colours -le 2 ]]; then
        echo "FAIL $name: the window stayed blank ($colours colours; screenshot: $shot)" >&2
        verdict=fail
        return
    fi
    echo "ok   $name (screenshot: $shot, $colours colours)"
    verdict=done
}
