#!/usr/bin/env bash
# check.sh [BUILD_DIR] - the slides' checks, for CI (and before a lecture).
#
# Builds every deck to HTML with build.sh in strict mode, so it fails when a code region
# named by a deck does not exist, when a figure in figures.txt cannot be drawn (a missing
# program or an empty PNG), or when a deck does not convert. Then check-decks.mjs checks
# speaker notes on every slide, at most 16 code lines a slide, images present, offline
# HTML, and that every concept listed in concepts.txt (the ideas of the seed documents)
# is on at least one slide. BUILD_DIR: where the programs are (default build/debug,
# built when missing).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

"$here/build.sh" "$@" --no-pdf
node "$here/tools/check-decks.mjs" --decks "$here/build/decks" --dist "$here/dist" \
    --concepts "$here/concepts.txt" --src "$here/src"
echo "slides: all checks passed"
