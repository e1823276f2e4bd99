#!/usr/bin/env bash
# Builds lab folders written for the course's old framework and runs each one, to prove that
# old lab code builds and runs on Hitbox unchanged.
#
#   ./scripts/check-course-labs.sh                    every folder in tests/course/
#   ./scripts/check-course-labs.sh ~/labs/Week8 ...   your own lab folders
#   ./scripts/check-course-labs.sh --screenshots DIR  also save what each window showed
#
# Each folder is built as `cmake -DHITBOX_COURSE_LAB_DIR=<folder>` (see README.md), then run
# from its own folder for a few seconds (under xvfb-run when there is no display). A lab
# passes when it builds and is still running when it is closed.
set -euo pipefail
cd "$(dirname "$0")/.."

screenshots=""
labs=()
while [[ $# -gt 0 ]]; do
    case "$1" in
    --screenshots) screenshots="$(mkdir -p "$2" && cd "$2" && pwd)"; shift 2 ;;
    -h | --help) sed -n '2,12p' "$0"; exit 0 ;;
    *) labs+=("$1"); shift ;;
    esac
done
if [[ ${#labs[@]} -eq 0 ]]; then
    for folder in tests/course/*/; do labs+=("${folder%/}"); done
fi

build=build/course
mkdir -p "$build"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
seconds_to_run=4
failed=0

for lab in "${labs[@]}"; do
    if [[ ! -f $lab/Main.cpp ]]; then
        echo "FAIL $lab: not a lab folder (no Main.cpp in it)" >&2
        failed=1
        continue
    fi
    lab="$(cd "$lab" && pwd)"
    name="$(basename "$lab")"
    echo "== $name: build"
    # One build folder for every lab: the framework is compiled once. The converted copies
    # of the previous lab's files are removed so they cannot be picked up by mistake.
    rm -rf "$build/course_lab_sources"
    if ! cmake -S . -B "$build" -DHITBOX_COURSE_LAB_DIR="$lab" -DHITBOX_BUILD_TESTS=OFF \
        -DHITBOX_BUILD_BENCHMARKS=OFF "${launcher[@]}" >"$build/configure.log" 2>&1 ||
        ! cmake --build "$build" --target course_lab -j 2; then
        echo "FAIL $name: does not build (configure log: $build/configure.log)" >&2
        failed=1
        continue
    fi

    echo "== $name: run for $seconds_to_run seconds"
    program="$PWD/$build/course_lab"
    shot=""
    [[ -n $screenshots ]] && command -v import >/dev/null && shot="$screenshots/$name.png"
    # Start the lab, let it run, photograph the screen, then close it. Exit code 0 means it
    # was still running when closed; anything else is a crash or an early exit.
    runner='
        "$1" & lab_pid=$!
        sleep "$2"
        kill -0 "$lab_pid" 2>/dev/null || { wait "$lab_pid"; echo "exited early with code $?" >&2; exit 1; }
        if [ -n "$3" ]; then import -window root "$3"; fi
        kill "$lab_pid"; wait "$lab_pid" 2>/dev/null; exit 0'
    display=(xvfb-run -a -s "-screen 0 1920x1920x24")
    [[ -n ${DISPLAY:-} ]] && display=()
    if (cd "$lab" && ALSOFT_DRIVERS=null "${display[@]}" \
        sh -c "$runner" runner "$program" "$seconds_to_run" "$shot"); then
        echo "ok   $name${shot:+ (screenshot: $shot)}"
    else
        echo "FAIL $name: did not keep running" >&2
        failed=1
    fi
done
exit $failed
