#!/usr/bin/env bash
# build.sh [BUILD_DIR] [--draft] [--no-pdf] - builds every lecture deck. The one command.
#
# 1. installs what it needs: Node.js and npm (Debian's nodejs npm, when missing) and the
#    pinned Marp CLI (npm ci, from package-lock.json);
# 2. builds the project's programs into build/debug when no BUILD_DIR with programs is given;
# 3. draws the figures with those programs (make-figures.sh, list in figures.txt);
# 4. copies the named code regions into the decks (tools/include-regions.mjs);
# 5. converts every deck in src/ to HTML in slides/dist/ (offline: formulas as SVG, images
#    beside the HTML), and to PDF as well when Chromium is installed (/usr/bin/chromium or
#    CHROME_PATH).
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

# --- 1. Node.js, npm and Marp -------------------------------------------------------------
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    echo "== installing Node.js and npm (Debian packages)"
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq nodejs npm
fi
if ! command -v xvfb-run >/dev/null; then
    echo "== installing xvfb (the figures are drawn in a virtual display)"
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq xvfb xauth
fi
cd "$here"
# npm ci again only when the lockfile changed since the last install.
if [[ ! -f node_modules/.package-lock.json || package-lock.json -nt node_modules/.package-lock.json ]]; then
    echo "== npm ci (Marp CLI, pinned in package-lock.json)"
    npm ci --no-audit --no-fund --loglevel=error
fi
marp=("$here/node_modules/.bin/marp" --config-file "$here/marp.config.mjs")

# --- 2. The programs that draw the figures ---------------------------------------------------
if [[ -z "$build_dir" ]]; then
    build_dir="$repo/build/debug"
    if [[ ! -x "$build_dir/framework/sandbox" ]]; then
        echo "== building the project's programs into build/debug"
        [[ -x "$repo/scripts/install-deps.sh" ]] && "$repo/scripts/install-deps.sh"
        (cd "$repo" && cmake --preset debug && cmake --build --preset debug)
    fi
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

# --- 4. Code regions into the decks ------------------------------------------------------------
decks="$here/build/decks"
rm -rf "$decks" "$here/dist"
mkdir -p "$decks" "$here/dist"
echo "== code regions (include-regions.mjs)"
include=(node "$here/tools/include-regions.mjs" --root "$repo" --src "$here/src" --out "$decks")
$draft && include+=(--allow-missing)
(cd "$here" && "${include[@]}")
# Images are relative links: they sit beside the decks and beside the HTML.
for folder in "$decks" "$here/dist"; do
    mkdir -p "$folder/figures/generated"
    cp "$here"/figures/*.svg "$folder/figures/"
    cp "$here"/figures/generated/*.png "$folder/figures/generated/" 2>/dev/null || true
done

# --- 5. HTML (always) and PDF (with Chromium) ----------------------------------------------------
echo "== HTML (Marp)"
"${marp[@]}" --input-dir "$decks" --output "$here/dist" --html
chrome="${CHROME_PATH:-/usr/bin/chromium}"
if $pdf && [[ -x "$chrome" ]]; then
    echo "== PDF (Marp + $chrome)"
    # Local images need --allow-local-files, or they are silently left out of the PDF.
    CHROME_PATH="$chrome" "${marp[@]}" --input-dir "$decks" --output "$here/dist" --pdf \
        --allow-local-files
elif $pdf; then
    echo "== PDF skipped: no Chromium (apt-get install chromium, or set CHROME_PATH)"
fi
# An index page: one link per deck (and its PDF when there is one).
{
    echo '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>Hitbox lectures</title>'
    echo '<style>body{font-family:sans-serif;font-size:22px;margin:40px}li{margin:8px 0}</style></head>'
    echo '<body><h1>Hitbox: collision detection lectures</h1><ol>'
    for deck in "$here"/src/*.md; do
        name="$(basename "$deck" .md)"
        title="$(sed -n 's/^title: *"\{0,1\}\([^"]*\)"\{0,1\}$/\1/p' "$deck" | head -n 1)"
        pdf_link=""
        [[ -f "$here/dist/$name.pdf" ]] && pdf_link=" (<a href=\"$name.pdf\">PDF</a>)"
        echo "<li><a href=\"$name.html\">${title:-$name}</a>$pdf_link</li>"
    done
    echo '</ol><p>Press P in a deck for the presenter view with speaker notes.</p></body></html>'
} >"$here/dist/index.html"
echo "slides: open slides/dist/index.html"
