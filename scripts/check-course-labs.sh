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
# check-course-lab.txt, saying what else it must do (scripts/check-course-labs/expectations.sh).
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
# ffmpeg grabs the Xvfb screen and xdotool holds the mouse down for the folders that ask for
# it; only this check needs them, so students' install-deps leaves them out.
for tool in ffmpeg xdotool; do
    if ! command -v "$tool" >/dev/null && command -v apt-get >/dev/null && [[ $(id -u) -eq 0 ]]; then
        DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends "$tool" >/dev/null
    fi
done
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

for part in expectations place-lab build-lab run-lab; do # each lab's steps, one file each
    source "scripts/check-course-labs/$part.sh"
done
for lab in "${labs[@]}"; do
    build_lab "$lab"
    [[ $verdict != go ]] || run_lab
    [[ $verdict != fail ]] || failed=1
done
exit $failed
