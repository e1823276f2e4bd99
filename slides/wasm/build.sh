#!/usr/bin/env bash
# wasm/build.sh [--native] - Hitbox's geometry for the slides' interactive figures.
#
# Compiles framework/hitbox/geometry/ and the figures' answer functions (figures.cpp) to
# WebAssembly with Debian's emscripten (installed when missing): slides/build/wasm/
# hitbox-geometry.js, one file with the .wasm inside it as base64 (SINGLE_FILE), because a
# deck opened from disk (file://) may not fetch a separate .wasm file.
# --native: also builds slides/build/wasm/answers, the same functions compiled by g++, which
#           the test of the figures (check-interactive.sh) compares them with.
# Each output is rebuilt only when a source is newer.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
out="$here/../build/wasm"
mkdir -p "$out"
as_root() { if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi; }

sources=("$here/figures.cpp" "$repo"/framework/hitbox/geometry/*.cpp)
inputs=("${sources[@]}" "$repo"/framework/hitbox/geometry/*.h "$here/answers.cpp" "$0")
stale() { # stale FILE: true when FILE is missing or older than any input
    [[ ! -f "$1" ]] && return 0
    local input
    for input in "${inputs[@]}"; do [[ "$input" -nt "$1" ]] && return 0; done
    return 1
}

if stale "$out/hitbox-geometry.js"; then
    if ! command -v emcc >/dev/null; then
        echo "== installing emscripten (Debian package; compiles the geometry to WebAssembly)"
        as_root apt-get update -qq
        as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq emscripten >/dev/null
    fi
    echo "== geometry to WebAssembly (emcc): slides/build/wasm/hitbox-geometry.js"
    # Debian's emcc runs its JavaScript optimiser with Debian's acorn package.
    NODE_PATH=/usr/share/nodejs emcc -std=c++17 -O2 -Wall -Wextra -Werror -I"$repo/framework" \
        "${sources[@]}" -o "$out/hitbox-geometry.js" \
        -sSINGLE_FILE=1 -sMODULARIZE=1 -sEXPORT_NAME=HitboxGeometry -sENVIRONMENT=web \
        -sFILESYSTEM=0 -sEXPORTED_FUNCTIONS=_malloc
fi

if [[ "${1:-}" == "--native" ]] && stale "$out/answers"; then
    echo "== the same answers compiled natively (g++): slides/build/wasm/answers"
    "${CXX:-g++}" -std=c++17 -O2 -Wall -Wextra -Wpedantic -Werror -I"$repo/framework" \
        "${sources[@]}" "$here/answers.cpp" -o "$out/answers"
fi
