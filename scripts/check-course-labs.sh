#!/usr/bin/env bash
# Builds lab folders written for the course's own framework and runs each one, to prove that
# course lab code of both generations builds and runs on Hitbox unchanged.
#
#   ./scripts/check-course-labs.sh                    every folder in tests/course/
#   ./scripts/check-course-labs.sh ~/labs/Week8 ...   your own lab folders
#   ./scripts/check-course-labs.sh --screenshots DIR  keep what each window showed
#
# Each folder is built as `cmake -DHITBOX_COURSE_LAB_DIR=<folder>` (see docs/course-labs.md), then run
# for a few seconds under Xvfb and photographed. A lab passes when it builds, is still
# running when it is closed, every picture, font and sound it asked for loaded, and the
# picture is not blank (more than the screen's black and one clear colour), and its output
# is not flooded (no sound device must cost one line, not thousands). A folder may hold
# check-course-lab.txt, saying what else it must do (see "Expectations" below).
# 2019-24 labs need SFML 2 and 2025-26 labs SFML 3: a lab whose SFML is not installed here
# is built and run in the Debian unstable root (scripts/sid-root.sh, SFML 3), shown on this
# machine's Xvfb; such a folder must be inside this checkout.
set -euo pipefail
cd "$(dirname "$0")/.."

screenshots=""
labs=()
while [[ $# -gt 0 ]]; do
    case "$1" in
    --screenshots) screenshots="$(mkdir -p "$2" && cd "$2" && pwd)"; shift 2 ;;
    -h | --help) sed -n '2,17p' "$0"; exit 0 ;;
    *) labs+=("$1"); shift ;;
    esac
done
if [[ ${#labs[@]} -eq 0 ]]; then
    for folder in tests/course/*/; do labs+=("${folder%/}"); done
fi
# ffmpeg grabs the Xvfb screen; only this check needs it, so students' install-deps leaves it out.
if ! command -v ffmpeg >/dev/null && command -v apt-get >/dev/null && [[ $(id -u) -eq 0 ]]; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends ffmpeg >/dev/null
fi
# xdotool holds the mouse down for the folders that ask for it.
if ! command -v xdotool >/dev/null && command -v apt-get >/dev/null && [[ $(id -u) -eq 0 ]]; then
    DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends xdotool >/dev/null
fi
for tool in xvfb-run ffmpeg python3 xdotool; do
    command -v "$tool" >/dev/null || { echo "check-course-labs: needs $tool (./scripts/install-deps.sh; apt-get install ffmpeg)" >&2; exit 2; }
done

sfml_major_here=$(pkg-config --modversion sfml-graphics 2>/dev/null || echo 0)
sfml_major_here=${sfml_major_here%%.*}
seconds_to_run=4
# A flood, not a chatty lab: a lab printing a line every frame writes about 240 lines in four
# seconds; OpenAL Soft with no sound device wrote 2.6 million (week10_sound_effects, unsilenced).
most_output_lines=1000
failed=0

# Expectations: a folder's check-course-lab.txt, one per line (# starts a comment):
#   cmake: -DNAME=VALUE          an option for its configure step
#   configure says: TEXT         a line the configure step must print
#   build fails                  it must not build (the configure lines still count)
#   hold the mouse at: X Y       hold the left button down there from the second second
#   run says: TEXT               a line the program must print
expectation() { # expectation FOLDER KEY -> every value given for KEY, one a line
    [[ -f $1/check-course-lab.txt ]] || return 0
    sed -n "s/^$2: *//p" "$1/check-course-lab.txt"
}

for lab in "${labs[@]}"; do
    name="$(basename "$lab")"
    if [[ ! -f $lab/Main.cpp ]]; then
        echo "FAIL $name: not a lab folder (no Main.cpp in it)" >&2
        failed=1
        continue
    fi
    # The generation decides the SFML major; the build says the same (HitboxCourseLab.cmake).
    generation=$(cmake "-DHITBOX_PRINT_GENERATION_OF=$lab" -P framework/cmake/HitboxCourseLab.cmake)
    sfml_major=2
    [[ $generation == 2025 ]] && sfml_major=3
    inside=()                 # run build and program here...
    build=build/course-sfml$sfml_major
    launcher=$(command -v ccache || true)
    lab_path="$(cd "$lab" && pwd)"
    if [[ $sfml_major != "$sfml_major_here" ]]; then
        inside=(scripts/sid-root.sh run) # ...or in the root, where this checkout is /hitbox
        build=build/sid-course
        launcher=""
        lab_path="$(realpath --relative-to=. "$lab")"
        if [[ $sfml_major != 3 || $lab_path == ../* ]]; then
            echo "FAIL $name: needs SFML $sfml_major, not installed here (only folders inside this checkout can use scripts/sid-root.sh)" >&2
            failed=1
            continue
        fi
        # A 2025-26 lab needs Hitbox's SFML 3 port (HitboxSFML.cmake accepting SFML 3) and
        # its maths free of SFML types (the geometry layer marked NO_SFML). Until both are in,
        # say so on one line rather than fail or pass in silence.
        if ! grep -q 'SFML 3' framework/cmake/HitboxSFML.cmake ||
            ! grep -qE '^hitbox_layer\(geometry +NO_SFML' framework/CMakeLists.txt; then
            echo "SKIP $name: a 2025-26 lab; Hitbox does not build on SFML 3 yet" >&2
            continue
        fi
    fi

    mapfile -t cmake_options < <(expectation "$lab" cmake)
    mapfile -t configure_says < <(expectation "$lab" "configure says")
    mapfile -t run_says < <(expectation "$lab" "run says")
    mouse_at=$(expectation "$lab" "hold the mouse at")
    build_fails=$(grep -sx "build fails" "$lab/check-course-lab.txt" || true)

    echo "== $name ($generation-generation course framework, SFML $sfml_major): build"
    # One build folder per SFML major: the framework is compiled once. The converted copies
    # of the previous lab's files and its run folder are removed so nothing is picked up by
    # mistake.
    rm -rf "$build/course_lab_sources" "$build/course_lab_run"
    mkdir -p "$build"
    # The lab's own Framework/ files to build are named afresh for every folder.
    configured=0
    "${inside[@]}" cmake -S . -B "$build" -DHITBOX_COURSE_LAB_DIR="$lab_path" \
        -DHITBOX_BUILD_TESTS=OFF -DHITBOX_BUILD_BENCHMARKS=OFF -DHITBOX_COURSE_LAB_OWN_FRAMEWORK= \
        -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" "${cmake_options[@]}" >"$build/configure.log" 2>&1 ||
        configured=$?
    missing=0
    for line in "${configure_says[@]}"; do
        grep -F -- "$line" "$build/configure.log" || { echo "FAIL $name: configure did not say \"$line\" ($build/configure.log)" >&2; missing=1; }
    done
    if [[ $missing != 0 ]]; then
        failed=1
        continue
    fi
    built=0
    if [[ $configured == 0 ]]; then
        "${inside[@]}" cmake --build "$build" --target course_lab -j 2 >"$build/build.log" 2>&1 || built=$?
    fi
    if [[ -n $build_fails ]]; then
        if [[ $configured == 0 && $built == 0 ]]; then
            echo "FAIL $name: built, but it should not (the project leaves out a file it needs)" >&2
            failed=1
        else
            echo "ok   $name (does not build, as in Visual Studio, and configure said so)"
        fi
        continue
    fi
    if [[ $configured != 0 || $built != 0 ]]; then
        tail -n 30 "$build/build.log" >&2 || true
        echo "FAIL $name: does not build (logs: $build/configure.log, $build/build.log)" >&2
        failed=1
        continue
    fi
    grep -m1 "Course lab: .*course framework" "$build/configure.log" || true

    echo "== $name: run for $seconds_to_run seconds"
    shot="${screenshots:-$PWD/$build}/$name.png"
    rm -f "$shot"
    # Start the lab, let it run, photograph the screen, then close it. Exit code 0 means it
    # was still running when closed; anything else is a crash or an early exit. The X server
    # accepts any local client (-ac), so a program in the Debian root can use it too, and
    # does not reset when its last client leaves (-noreset: a lab that asks the desktop's
    # size before opening its window connects twice, and a resetting server refuses the
    # second connection, which a real desktop never does). setsid puts the program (and, in
    # the root, the commands around it) in a group of its own.
    runner='
        inside=$1 build=$2 seconds=$3 shot=$4 log=$5 mouse_at=$6
        setsid $inside env DISPLAY="$DISPLAY" \
            sh -c "cd \"$build/course_lab_run\" && exec ../course_lab" >"$log" 2>&1 & lab_pid=$!
        if [ -n "$mouse_at" ]; then
            sleep 2
            xdotool mousemove $mouse_at mousedown 1
            sleep $((seconds - 2))
        else
            sleep "$seconds"
        fi
        kill -0 "$lab_pid" 2>/dev/null || { wait "$lab_pid"; echo "exited early with code $? (output: $log)" >&2; exit 1; }
        ffmpeg -loglevel error -f x11grab -draw_mouse 0 -video_size 1920x1920 -i "$DISPLAY" -frames:v 1 "$shot"
        kill -- "-$lab_pid"; wait "$lab_pid" 2>/dev/null; exit 0'
    if ! xvfb-run -a -s "-screen 0 1920x1920x24 -ac -noreset" \
        sh -c "$runner" runner "${inside[*]}" "$build" "$seconds_to_run" "$shot" "$build/run.log" "$mouse_at"; then
        echo "FAIL $name: did not keep running" >&2
        failed=1
        continue
    fi
    # First the flood (its lines would bury everything else).
    lines=$(wc -l <"$build/run.log")
    if [[ $lines -gt $most_output_lines ]]; then
        sort "$build/run.log" | uniq -c | sort -rn | head -n 3 >&2
        echo "FAIL $name: printed $lines lines in $seconds_to_run seconds (output: $build/run.log)" >&2
        failed=1
        continue
    fi
    # SFML says when a picture, font or sound does not load (a white box, no text, silence).
    if grep -E "Failed to (load|open)" "$build/run.log" >&2; then
        echo "FAIL $name: a file did not load (output: $build/run.log)" >&2
        failed=1
        continue
    fi
    missing=0
    for line in "${run_says[@]}"; do
        grep -qF -- "$line" "$build/run.log" || { echo "FAIL $name: did not print \"$line\" (output: $build/run.log)" >&2; missing=1; }
    done
    if [[ $missing != 0 ]]; then
        failed=1
        continue
    fi
    # Blank: nothing but the screen's black and the window's clear colour.
    colours=$(ffmpeg -loglevel error -i "$shot" -vf scale=480:-1:flags=neighbor -f rawvideo -pix_fmt rgb24 - |
        python3 -c 'import sys; d = sys.stdin.buffer.read(); print(len({d[i:i + 3] for i in range(0, len(d), 3)}))')
    if [[ $colours -le 2 ]]; then
        echo "FAIL $name: the window stayed blank ($colours colours; screenshot: $shot)" >&2
        failed=1
        continue
    fi
    echo "ok   $name (screenshot: $shot, $colours colours)"
done
exit $failed
