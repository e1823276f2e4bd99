#!/usr/bin/env bash
# build.sh [BUILD_DIR] [--draft] [--no-pdf] - builds every lecture deck. The one command.
# 1. installs what it needs when missing (tools/install-tools.sh: Node.js, npm, xvfb, ffmpeg,
#    clang-format, Chromium for the PDF, the pinned Marp CLI);
# 2. builds the programs that draw figures, and only those, into build/slides
#    (tools/build-programs.sh), unless BUILD_DIR already holds them;
# 3. draws the figures with those programs (make-figures.py, list in figures.txt), checking each
#    is the same on every run and shows what it claims; compiles Hitbox's geometry to
#    WebAssembly for the interactive figures (wasm/build.sh) and draws each one's still;
# 4. copies the named code regions into the decks (tools/include-regions.mjs), formatted to fit
#    the slide, the images beside them (tools/copy-figures.sh), and adds the navigation
#    (tools/deck-extras.mjs: previous/next lecture, notes decks, dist/index.html);
# 5. converts every deck in src/ to HTML in slides/dist/ (offline), and, when Chromium is
#    installed (/usr/bin/chromium or CHROME_PATH), to PDF with bookmarks and notes (tools/pdf.sh).
# --draft: a missing region or figure is reported and shown as a placeholder instead of failing
#          (for writing decks before the code they quote exists). --no-pdf: HTML only.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/.." && pwd)"
build_dir="" draft=() pdf=true
for arg in "$@"; do
    case "$arg" in
    --draft) draft=(--allow-missing) ;;
    --no-pdf) pdf=false ;;
    -*) echo "usage: $0 [BUILD_DIR] [--draft] [--no-pdf]" >&2; exit 2 ;;
    *) build_dir="$(cd "$arg" 2>/dev/null && pwd || echo "$arg")" ;; # relative to the caller
    esac
done
"$here/tools/install-tools.sh" "$($pdf && echo --pdf || echo --no-pdf)"
cd "$here"
if [[ -z "$build_dir" ]]; then
    build_dir="$repo/build/slides"
    "$here/tools/build-programs.sh" "$build_dir"
fi
[[ -d "$build_dir" ]] || { echo "build.sh: no build folder $build_dir" >&2; exit 1; }
echo "== figures (make-figures.py)"
python3 "$here/make-figures.py" "$build_dir" "${draft[@]}"
"$here/wasm/build.sh"
node "$here/tools/interactive-stills.mjs" --wasm "$here/build/wasm/hitbox-geometry.js" \
    --figures "$here/interactive/figures.js" --out "$here/figures/generated"
decks="$here/build/decks"
rm -rf "$decks" "$here/dist"
mkdir -p "$decks" "$here/dist"
echo "== code regions (include-regions.mjs)"
(cd "$here" && node "$here/tools/include-regions.mjs" --root "$repo" --src "$here/src" --out "$decks" "${draft[@]}")
"$here/tools/copy-figures.sh" "$decks" "$here/dist" "$here/build/notes"
mkdir -p "$here/dist/interactive"
cp "$here/build/wasm/hitbox-geometry.js" "$here/interactive/figures.js" "$here/dist/interactive/"
echo "== navigation (deck-extras.mjs)"
node "$here/tools/deck-extras.mjs" --decks "$decks" --notes "$here/build/notes" --dist "$here/dist"
echo "== HTML (Marp)"
"$here/node_modules/.bin/marp" --config-file "$here/marp.config.mjs" --input-dir "$decks" --output "$here/dist" --html
chrome="${CHROME_PATH:-/usr/bin/chromium}"
if $pdf && [[ -x "$chrome" ]]; then
    echo "== PDF with bookmarks, the slides as pictures, and the speaker notes (Marp + $chrome)"
    "$here/tools/pdf.sh" "$chrome"
elif $pdf; then
    echo "== PDF skipped: no Chromium (apt-get install chromium, or set CHROME_PATH)"
fi
echo "slides: open slides/dist/index.html"
