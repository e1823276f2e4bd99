#!/usr/bin/env bash
# pdf.sh CHROME - the PDF decks with bookmarks (dist/NN-name.pdf) and the lecturer's notes with
# each slide's picture above its notes (dist/NN-name-notes.pdf), printed by Marp with Chromium
# (step 5 of build.sh, after the HTML: reads build/decks).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
chrome="$1"
marp=("$here/node_modules/.bin/marp" --config-file "$here/marp.config.mjs")
# The PDF decks carry their images inside (data: URLs): Chromium then reads no local
# file, so Marp needs no --allow-local-files (and prints no warning about it).
pdf_decks="$here/build/pdf"
pictures="$here/build/pictures"
rm -rf "$pdf_decks" "$pictures" "$here/build/notes"
node "$here/tools/inline-images.mjs" --in "$here/build/decks" --out "$pdf_decks"
CHROME_PATH="$chrome" "${marp[@]}" --input-dir "$pdf_decks" --output "$here/dist" --pdf --pdf-outlines
# Each slide as a picture for the notes pages (0.6 of full size: sharp enough on paper).
# One deck at a time: all at once can time out in Chromium on a busy 2-core machine.
mkdir -p "$pictures"
for deck in "$pdf_decks"/*.md; do
    CHROME_PATH="$chrome" "${marp[@]}" "$deck" --output "$pictures/$(basename "${deck%.md}").png" \
        --images png --image-scale 0.6
done
node "$here/tools/deck-extras.mjs" --decks "$pdf_decks" --notes "$here/build/notes" --dist "$here/dist" \
    --pictures "$pictures"
CHROME_PATH="$chrome" "${marp[@]}" --input-dir "$here/build/notes" --output "$here/dist" \
    --pdf --pdf-outlines
# The index again, now with the PDFs.
node "$here/tools/deck-extras.mjs" --decks "$here/build/decks" --notes "$here/build/notes" --dist "$here/dist" \
    --index-only 1
