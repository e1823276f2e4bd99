#!/usr/bin/env bash
# copy-figures.sh FOLDER... - the images beside each folder of decks or HTML (they are relative
# links): figures/*.svg, the drawn figures of figures/generated/, and each lab's own screenshot
# (labs/NN_name/screenshot.png) as figures/labs/NN.png (step 4 of build.sh).
set -euo pipefail
slides="$(cd "$(dirname "$0")/.." && pwd)"
repo="$(cd "$slides/.." && pwd)"
for folder in "$@"; do
    mkdir -p "$folder/figures/generated"
    cp "$slides"/figures/*.svg "$folder/figures/"
    cp "$slides"/figures/generated/*.png "$slides"/figures/generated/*.apng "$folder/figures/generated/" 2>/dev/null || true
    cp "$slides"/figures/generated/interactive-*.svg "$folder/figures/generated/"
    # Each screenshot's smallest text and size (make-figures.py), for tools/check-layout.mjs.
    cp "$slides"/figures/generated/figure-text.json "$folder/figures/generated/" 2>/dev/null || true
    mkdir -p "$folder/figures/labs"
    for shot in "$repo"/labs/*/screenshot.png; do
        lab="$(basename "$(dirname "$shot")")"
        cp "$shot" "$folder/figures/labs/${lab%%_*}.png"
    done
done
