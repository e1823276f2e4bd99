#!/usr/bin/env bash
# CI: what a Windows (and macOS) student's build meets, checked from this Debian machine.
# There is no MSVC here; the nearest things are used, and each check fails on the mistake
# it guards against:
#  1. The SFML-free layers (platform, geometry, broadphase: -DHITBOX_WITH_SFML=OFF) cross-built
#     for 64-bit Windows with mingw-w64 (framework/cmake/MingwW64Toolchain.cmake), Debug AND
#     Release in one Ninja Multi-Config tree, GoogleTest through FetchContent (from Debian's
#     copy of its sources, /usr/src/googletest: nothing downloads here); the tests run under
#     wine (scripts/wine-run.sh), directly and through ctest.
#  2. Every other source (framework, labs' solutions and generated exercises, Pong, tests)
#     compiled for Windows, compile only, against SFML 2's headers and, when the Debian
#     unstable root exists, SFML 3's, with mingw's copy of Microsoft's CRT deprecations and
#     warnings as errors (scripts/compile-check.py): a getenv or a POSIX call fails here.
#  3. clang + libc++ (LLVM's standard library, as on macOS): the SFML-free layers built and
#     every one of their tests run; the rest compiled only, because Debian's SFML and
#     GoogleTest are built against libstdc++ and cannot link with libc++ code.
#  4. A clean clone configured, built and tested through the presets with a multi-config
#     generator (CMAKE_GENERATOR="Ninja Multi-Config", as Visual Studio's is): ctest must run
#     every test (none "Not Run").
# Each step is a file of scripts/ci-windows/, run here in turn.
# Usage: scripts/ci-windows.sh [LINUX_BUILD]   (default build/debug, made by ./scripts/test.sh;
# its compile_commands.json lists what step 2 and 3 compile). Takes about 10 minutes cold.
set -euo pipefail
cd "$(dirname "$0")/.."
linux_build=${1:-build/debug}
out=build/ci-windows
step() { echo "ci-windows [${SECONDS}s]: $*"; }
if [[ ! -f "$linux_build/compile_commands.json" ]]; then
    echo "ci-windows: no $linux_build/compile_commands.json; build first with ./scripts/test.sh" >&2
    exit 2
fi

step "0. packages: mingw-w64, wine, ninja, googletest sources, clang and libc++"
packages=(g++-mingw-w64-x86-64-posix mingw-w64-x86-64-dev wine wine64 ninja-build googletest
          clang libc++-dev libc++abi-dev)
missing=()
for package in "${packages[@]}"; do
    [[ $(dpkg-query -W -f='${Status}' "$package" 2>/dev/null) == *"install ok installed"* ]] ||
        missing+=("$package")
done
if [[ ${#missing[@]} -gt 0 ]]; then
    echo "ci-windows: installing ${missing[*]}"
    apt-get -o DPkg::Lock::Timeout=600 update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -q \
        --no-install-recommends "${missing[@]}" >/dev/null
fi
rm -rf "$out" && mkdir -p "$out"
export HITBOX_WINEPREFIX="${HITBOX_WINEPREFIX:-$PWD/$out/wine}"
googletest=/usr/src/googletest

for part in 1-mingw 2-windows-sources 3-libcxx 4-presets; do
    source "scripts/ci-windows/$part.sh"
done
step "all Windows and libc++ checks passed"
