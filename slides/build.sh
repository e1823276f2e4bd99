#!/usr/bin/env bash
# build.sh [BUILD_DIR] [--draft] [--no-pdf] - builds every lecture deck. The one command.
#
# 1. installs what it needs: Node.js and npm, xvfb, ffmpeg, clang-format and (for the PDF)
#    Chromium, from Debian when missing, and the pinned Marp CLI (npm ci, from
#    package-lock.json, with npm's cache in /var/cache/hitbox/npm when that folder can be
#    written, so CI downloads it once);
# 2. builds the programs that draw figures, and only those, into build/slides (a release
#    build without the tests and benchmarks), unless BUILD_DIR already holds them;
# 3. draws the figures with those programs (make-figures.sh, list in figures.txt) and checks
#    that each is the same on every run and shows what it claims; compiles Hitbox's geometry
#    to WebAssembly for the interactive figures (wasm/build.sh, installs emscripten) and draws
#    each one's still for the PDF (tools/interactive-stills.mjs);
# 4. copies the named code regions into the decks (tools/include-regions.mjs), formatted to
#    fit the slide, and adds the navigation (tools/deck-extras.mjs: previous/next lecture
#    slide, notes decks, dist/index.html with every lecture's outline);
# 5. converts every deck in src/ to HTML in slides/dist/ (offline: formulas as SVG, images
#    beside the HTML), and, when Chromium is installed (/usr/bin/chromium or CHROME_PATH),
#    to PDF with bookmarks (NN-name.pdf) and the lecturer's notes (NN-name-notes.pdf).
# --draft: a missing region or figure is reported and shown as a placeholder instead of
#          failing (for writing decks before the code they quote exists).
# --no-pdf: HTML only.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/.." && pwd)"

build_dir=""
draft=false
pdf=true
for arg in "$@"; do
    case "$arg" in
    --draft) draft=true ;;
    --no-pdf) pdf=false ;;
    -*) echo "usage: $0 [BUILD_DIR] [--draft] [--no-pdf]" >&2; exit 2 ;;
    *) build_dir="$(cd "$arg" 2>/dev/null && pwd || echo "$arg")" ;; # relative to the caller
    esac
done

as_root() { if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi; }

# --- 1. Node.js, npm, Marp, and the tools the figures need ------------------------------------
# One apt-get for everything missing (a package whose command is already there is skipped):
# node/npm (Marp), xvfb-run (figures drawn in a virtual display), ffmpeg (crops, animations,
# the PDF's frame strips), clang-format (code excerpts formatted to the slide's width), and
# Chromium when PDFs are wanted (Marp prints them with it). Waits for another apt to finish.
needed=()
need() { command -v "$1" >/dev/null || needed+=("${@:2}"); }
need node nodejs
need npm npm
need xvfb-run xvfb xauth
need ffmpeg ffmpeg
need clang-format clang-format
# The font of the labels ffmpeg draws on the animation strips (make-figures.sh).
[[ -f /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf ]] || needed+=(fonts-dejavu-core)
$pdf && [[ -z "${CHROME_PATH:-}" ]] && need chromium chromium
if [[ ${#needed[@]} -gt 0 ]]; then
    echo "== installing ${needed[*]} (Debian packages)"
    as_root apt-get -o DPkg::Lock::Timeout=600 update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq \
        --no-install-recommends "${needed[@]}" >/dev/null
fi
cd "$here"
# npm ci again only when the lockfile changed since the last install.
npm_cache=(--cache "${HITBOX_NPM_CACHE:-/var/cache/hitbox/npm}" --prefer-offline)
mkdir -p "${HITBOX_NPM_CACHE:-/var/cache/hitbox/npm}" 2>/dev/null || npm_cache=()
if [[ ! -f node_modules/.package-lock.json || package-lock.json -nt node_modules/.package-lock.json ]]; then
    echo "== npm ci (Marp CLI, pinned in package-lock.json)"
    npm ci --no-audit --no-fund --loglevel=error "${npm_cache[@]}"
fi
marp=("$here/node_modules/.bin/marp" --config-file "$here/marp.config.mjs")

# --- 2. The programs that draw the figures ---------------------------------------------------
# Only the programs named in figures.txt, in a folder of their own: no tests, no benchmarks.
figure_targets() { awk '!/^#/ && NF { n = split($2, part, "/"); print part[n] }' "$here/figures.txt" | sort -u; }
if [[ -z "$build_dir" ]]; then
    build_dir="$repo/build/slides"
    echo "== building the programs that draw the figures into build/slides"
    [[ -x "$repo/scripts/install-deps.sh" && ! -f "$build_dir/CMakeCache.txt" ]] && "$repo/scripts/install-deps.sh"
    export CMAKE_CXX_COMPILER_LAUNCHER="${CMAKE_CXX_COMPILER_LAUNCHER:-$(command -v ccache || true)}"
    cmake -S "$repo" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DHITBOX_BUILD_TESTS=OFF \
        -DHITBOX_BUILD_BENCHMARKS=OFF >/dev/null
    mapfile -t targets < <(figure_targets)
    cmake --build "$build_dir" --parallel 2 --target "${targets[@]}"
fi
if [[ ! -d "$build_dir" ]]; then
    echo "build.sh: no build folder $build_dir" >&2
    exit 1
fi

# --- 3. Figures ------------------------------------------------------------------------------
echo "== figures (make-figures.sh)"
if $draft; then
    "$here/make-figures.sh" "$build_dir" --allow-missing
else
    "$here/make-figures.sh" "$build_dir"
fi

# Interactive figures: the geometry as WebAssembly (wasm/build.sh), and each figure's still.
"$here/wasm/build.sh"
node "$here/tools/interactive-stills.mjs" --wasm "$here/build/wasm/hitbox-geometry.js" \
    --figures "$here/interactive/figures.js" --out "$here/figures/generated"

# --- 4. Code regions into the decks ------------------------------------------------------------
decks="$here/build/decks"
rm -rf "$decks" "$here/dist"
mkdir -p "$decks" "$here/dist"
echo "== code regions (include-regions.mjs)"
include=(node "$here/tools/include-regions.mjs" --root "$repo" --src "$here/src" --out "$decks")
$draft && include+=(--allow-missing)
(cd "$here" && "${include[@]}")
# Images are relative links: they sit beside the decks and beside the HTML.
for folder in "$decks" "$here/dist" "$here/build/notes"; do
    mkdir -p "$folder/figures/generated"
    cp "$here"/figures/*.svg "$folder/figures/"
    cp "$here"/figures/generated/*.png "$here"/figures/generated/*.apng "$folder/figures/generated/" 2>/dev/null || true
    cp "$here"/figures/generated/interactive-*.svg "$folder/figures/generated/"
    # Each lab's own screenshot (labs/NN_name/screenshot.png) as figures/labs/NN.png.
    mkdir -p "$folder/figures/labs"
    for shot in "$repo"/labs/*/screenshot.png; do
        lab="$(basename "$(dirname "$shot")")"
        cp "$shot" "$folder/figures/labs/${lab%%_*}.png"
    done
done
mkdir -p "$here/dist/interactive"
cp "$here/build/wasm/hitbox-geometry.js" "$here/interactive/figures.js" "$here/dist/interactive/"
echo "== navigation (deck-extras.mjs)"
extras=(node "$here/tools/deck-extras.mjs" --decks "$decks" --notes "$here/build/notes" --dist "$here/dist")
"${extras[@]}"

# --- 5. HTML (always) and PDF (with Chromium) ----------------------------------------------------
echo "== HTML (Marp)"
"${marp[@]}" --input-dir "$decks" --output "$here/dist" --html
chrome="${CHROME_PATH:-/usr/bin/chromium}"
if $pdf && [[ -x "$chrome" ]]; then
    echo "== PDF with bookmarks, the slides as pictures, and the speaker notes (Marp + $chrome)"
    # The PDF decks carry their images inside (data: URLs): Chromium then reads no local
    # file, so Marp needs no --allow-local-files (and prints no warning about it).
    pdf_decks="$here/build/pdf"
    pictures="$here/build/pictures"
    rm -rf "$pdf_decks" "$pictures" "$here/build/notes"
    node "$here/tools/inline-images.mjs" --in "$decks" --out "$pdf_decks"
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
    "${extras[@]}" --index-only 1 # the index again, now with the PDFs
elif $pdf; then
    echo "== PDF skipped: no Chromium (apt-get install chromium, or set CHROME_PATH)"
fi
echo "slides: open slides/dist/index.html"
