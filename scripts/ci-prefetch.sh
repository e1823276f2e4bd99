#!/usr/bin/env bash
# CI only: fetches, in the background of the first build, what later CI stages would install
# one at a time (Debian packages, the SFML 3 root), so their downloads overlap with compiling.
# Every stage still installs what it needs by itself: this only makes it already there.
# Usage: scripts/ci-prefetch.sh LOG_FILE     (run as root, after ./scripts/install-deps.sh)
set -uo pipefail
cd "$(dirname "$0")/.."
log=${1:?usage: scripts/ci-prefetch.sh LOG_FILE}
# What the later stages install (each stage's own script names the same packages).
packages=(
    debootstrap                                           # 1b: the SFML 3 root
    g++-mingw-w64-x86-64-posix mingw-w64-x86-64-dev wine wine64 ninja-build
    libc++-dev libc++abi-dev googletest                   # Windows, multi-config, libc++ checks
    bubblewrap python3-pil                                # class grading's sandbox; picture checks
    clang-14 libclang-rt-14-dev ffmpeg xdotool            # 11b: fuzzers; 8 and 10: videos, a held mouse
)
# These the slide scripts install with apt's recommended packages: prefetch them the same way.
# (Node.js and npm: slides/build.sh installs them only where `npm` is missing; this machine's
# Node.js may bring its own npm, which Debian's npm package conflicts with.)
with_recommends=(emscripten chromium)
status=0
missing() {
    local package
    for package in "$@"; do
        [[ $(dpkg-query -W -f='${Status}' "$package" 2>/dev/null) == *"install ok installed"* ]] ||
            echo "$package"
    done
}
install() {
    [[ $# -gt 1 ]] || return 0
    echo "ci-prefetch: installing ${*:2}"
    DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -qq "$1" "${@:2}"
}
{
    apt-get update -qq || status=1
    mapfile -t plain < <(missing "${packages[@]}")
    install --no-install-recommends "${plain[@]}" || status=1
    mapfile -t recommended < <(missing "${with_recommends[@]}")
    install --install-recommends "${recommended[@]}" || status=1
    scripts/sid-root.sh create || status=1
} >"$log" 2>&1
echo "ci-prefetch: finished with status $status (log: $log)" >>"$log"
exit $status
