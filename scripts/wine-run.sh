#!/usr/bin/env bash
# Runs a Windows program under wine, quietly and without install prompts: the emulator
# scripts/ci-windows.sh gives CMake (CMAKE_CROSSCOMPILING_EMULATOR), so that test discovery
# and ctest run the cross-built tests. The wine prefix (wine's fake C: drive) is
# $HITBOX_WINEPREFIX, else ~/.cache/hitbox/wine; its first start takes tens of seconds.
# Usage: scripts/wine-run.sh program.exe [arguments...]
set -euo pipefail
export WINEPREFIX="${HITBOX_WINEPREFIX:-$HOME/.cache/hitbox/wine}"
export WINEDEBUG=-all
export WINEDLLOVERRIDES="mscoree,mshtml="
# mingw's own runtime DLLs (libstdc++-6.dll, libwinpthread-1.dll), which a DLL built with
# mingw needs; a program's other DLLs must sit next to it, as on Windows. Wine's Z: is /.
gcc_dlls=$(dirname "$(x86_64-w64-mingw32-g++-posix -print-libgcc-file-name)")
export WINEPATH="Z:${gcc_dlls//\//\\};Z:\\usr\\x86_64-w64-mingw32\\lib"
mkdir -p "$WINEPREFIX"
exec wine "$@"
