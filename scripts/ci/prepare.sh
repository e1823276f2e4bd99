#!/usr/bin/env bash
# CI's first step: names the machine, installs what the README's command needs, and Ninja.
# .ci/run then builds everything on this host with Ninja (CMAKE_GENERATOR): the multi-config
# clone of stage 1c (Ninja Multi-Config) compiles from a folder as deep as build/debug's, so
# ccache reuses stage 1's objects. Under Make each folder of the tree compiles from a folder
# of its own and no relative path matched (5.7 % ccache hits in a whole CI run). Students keep
# CMake's default generator, and so does the SFML 3 root, where a new user runs the README's
# commands (stage 1b).
set -euo pipefail
cd "$(dirname "$0")/../.."
echo "CI on: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p' | head -n 1)," \
    "$(free -g | awk '/^Mem:/ { print $2 }') GiB, $(df -h --output=avail . | tail -n 1 | tr -d ' ') free"
./scripts/install-deps.sh
command -v ninja >/dev/null && exit 0
install=(apt-get -o DPkg::Lock::Timeout=600 install -y -q --no-install-recommends ninja-build)
DEBIAN_FRONTEND=noninteractive "${install[@]}" >/dev/null ||
    { apt-get -o DPkg::Lock::Timeout=600 update -q >/dev/null && DEBIAN_FRONTEND=noninteractive "${install[@]}" >/dev/null; }
command -v ninja >/dev/null || { echo "ci/prepare.sh: ninja-build did not install" >&2; exit 1; }
