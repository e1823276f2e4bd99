#!/usr/bin/env bash
# Installs what Hitbox needs on Debian/Ubuntu, skipping what is already there.
# Safe to run any number of times. Other systems: see README.md ("Windows" and "macOS").
set -euo pipefail

packages=(g++ make cmake pkg-config libsfml-dev libgtest-dev libgmock-dev libbenchmark-dev
          libbox2d-dev xvfb xauth clang-format ffmpeg)

missing=()
for package in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
        missing+=("$package")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

if ! command -v apt-get >/dev/null; then
    echo "install-deps: no apt-get here; install these yourself: ${missing[*]}" >&2
    exit 1
fi
sudo=""
if [[ $(id -u) -ne 0 ]]; then
    sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
