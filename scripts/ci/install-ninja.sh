#!/usr/bin/env bash
# CI only: installs Ninja (Debian's ninja-build) when it is missing; .ci/run builds with it.
set -euo pipefail
command -v ninja >/dev/null && exit 0
DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -q --no-install-recommends ninja-build >/dev/null ||
    { apt-get -o DPkg::Lock::Timeout=600 update -q >/dev/null &&
      DEBIAN_FRONTEND=noninteractive apt-get -o DPkg::Lock::Timeout=600 install -y -q --no-install-recommends ninja-build >/dev/null; }
command -v ninja >/dev/null || { echo "install-ninja: ninja-build did not install" >&2; exit 1; }
