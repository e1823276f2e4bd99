#!/usr/bin/env bash
# install-tools.sh --pdf|--no-pdf - what build.sh needs, installed when missing (step 1 of build.sh).
# One apt-get for everything missing (a package whose command is already there is skipped):
# node/npm (Marp), xvfb-run (figures drawn in a virtual display), ffmpeg (crops, animations,
# the PDF's frame strips), clang-format (code excerpts formatted to the slide's width), the
# font of the strips' labels, and Chromium with --pdf (Marp prints PDFs with it; not when
# CHROME_PATH is set). Waits for another apt to finish. Then the pinned Marp CLI: npm ci from
# package-lock.json, again only when the lockfile changed since the last install, with npm's
# cache in /var/cache/hitbox/npm (or HITBOX_NPM_CACHE) when it can be written, so CI downloads
# it once.
set -euo pipefail
slides="$(cd "$(dirname "$0")/.." && pwd)"
as_root() { if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi; }
needed=()
need() { command -v "$1" >/dev/null || needed+=("${@:2}"); }
need node nodejs
need npm npm
need xvfb-run xvfb xauth
need ffmpeg ffmpeg
need clang-format clang-format
# The font of the labels ffmpeg draws on the animation strips (make-figures.py).
[[ -f /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf ]] || needed+=(fonts-dejavu-core)
[[ ${1:-} == --pdf && -z "${CHROME_PATH:-}" ]] && need chromium chromium
if [[ ${#needed[@]} -gt 0 ]]; then
    echo "== installing ${needed[*]} (Debian packages)"
    as_root apt-get -o DPkg::Lock::Timeout=600 update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq \
        --no-install-recommends "${needed[@]}" >/dev/null
fi
cd "$slides"
npm_cache=(--cache "${HITBOX_NPM_CACHE:-/var/cache/hitbox/npm}" --prefer-offline)
mkdir -p "${HITBOX_NPM_CACHE:-/var/cache/hitbox/npm}" 2>/dev/null || npm_cache=()
if [[ ! -f node_modules/.package-lock.json || package-lock.json -nt node_modules/.package-lock.json ]]; then
    echo "== npm ci (Marp CLI, pinned in package-lock.json)"
    npm ci --no-audit --no-fund --loglevel=error "${npm_cache[@]}"
fi
