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
mkdir -p "$WINEPREFIX"
exec wine "$@"
