#!/usr/bin/env bash
# Installs what is missing, builds everything (warnings as errors) and runs every test.
# Usage: ./scripts/test.sh        (from anywhere; safe to run twice)
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/install-deps.sh
export ALSOFT_DRIVERS=null # tests never need a sound device
cmake --preset debug >/dev/null
cmake --build --preset debug
ctest --preset debug
