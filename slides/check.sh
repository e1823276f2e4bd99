#!/usr/bin/env bash
# check.sh [BUILD_DIR] - the slides' checks, for CI (and before a lecture).
#
# 1. tests/run.py: the checks themselves are shown to catch each mistake they exist for
#    (a defect planted in a small deck or figure list must fail, a clean one pass).
# 2. build.sh in strict mode (HTML only): fails when a code region named by a deck does not
#    exist, lacks its key line or is not whole (starts or ends mid-statement, in or on a
#    comment, repeats lines, uses a local it does not show), shows a lab task's answer, when a figure in figures.txt cannot be drawn, differs between
#    two runs or does not show what it claims, when an animation's still is not clean
#    frames (tools/check-stills.sh), or when a deck does not convert.
# 3. check-decks.mjs on the built decks: useful speaker notes on every slide, code that fits at
#    24px (16 lines of at most 78 characters), balanced brackets in every excerpt, captions
#    that name only code their slide shows, no words for insiders on the slides, images
#    present, every figure used by a deck, offline HTML, and every concept listed in
#    concepts.txt on at least one slide.
# 4. check-layout.mjs: in headless Chromium, no slide's content runs below the slide, no label
#    or screenshot text (figures.txt's text=PX, as drawn) under 24 px, no screenshot at the
#    slide's edge, no interactive still without its whole border in print (skipped, saying
#    so, without Chromium).
# BUILD_DIR: where the programs are (default: build.sh builds the figure programs alone into
# build/slides).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

python3 "$here/tests/run.py"
"$here/build.sh" "$@" --no-pdf
node "$here/tools/check-decks.mjs" --decks "$here/build/decks" --dist "$here/dist" \
    --concepts "$here/concepts.txt" --src "$here/src" --figures "$here/figures" \
    --labs "$here/../labs"
node "$here/tools/check-layout.mjs" --dist "$here/dist"
echo "slides: all checks passed"
