#!/usr/bin/env bash
# check-interactive.sh [BUILD_DIR] - the decks' interactive figures work in a real browser (CI).
#
# 1. installs what it needs: emscripten (wasm/build.sh) and Chromium (Debian packages, when
#    missing); playwright-core comes with build.sh's npm ci (package-lock.json);
# 2. builds Hitbox's geometry as WebAssembly for the figures and natively for the test
#    (wasm/build.sh --native);
# 3. uses the decks in slides/dist when build.sh made them after the last change to a deck,
#    the figures or the theme (as in CI, after check.sh); otherwise runs build.sh BUILD_DIR
#    --no-pdf;
# 4. tests/interactive.mjs: opens each deck from disk in headless Chromium, drags every
#    figure and checks each answer it shows against the native build of the same C++
#    (screenshots in slides/build/interactive-screens/);
# 5. shows the test can fail: with the native answers made wrong, it must fail.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
as_root() { if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi; }

chrome="${CHROME_PATH:-/usr/bin/chromium}"
if [[ ! -x "$chrome" ]]; then
    echo "== installing chromium (Debian package; the figures are tested in it)"
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null
    chrome=/usr/bin/chromium
fi
"$here/wasm/build.sh" --native

dist="$here/dist"
if [[ ! -f "$dist/index.html" || ! -d "$here/node_modules/playwright-core" ]] ||
    [[ -n "$(find "$here/src" "$here/interactive" "$here/theme" "$here/build/wasm/hitbox-geometry.js" \
        -newer "$dist/index.html" -print -quit)" ]]; then
    "$here/build.sh" "$@" --no-pdf
fi

test=(node "$here/tests/interactive.mjs" --dist "$dist" --chromium "$chrome")
"${test[@]}" --answers "$here/build/wasm/answers" --screenshots "$here/build/interactive-screens"

# A planted defect: answers that disagree with what the figure shows must fail the test.
wrong="$here/build/wasm/wrong-answers"
printf '#!/bin/sh\n"%s" | awk '"'"'{ $1 = 1 - $1; print }'"'"'\n' "$here/build/wasm/answers" >"$wrong"
chmod +x "$wrong"
if "${test[@]}" --answers "$wrong" --only boxes >/dev/null 2>&1; then
    echo "check-interactive: the test passed with wrong answers; it checks nothing" >&2
    exit 1
fi
echo "check-interactive: a wrong answer is caught"
