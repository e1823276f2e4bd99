#!/usr/bin/env bash
# CI stage 9: the benchmarks run (a short debug run: proves they work, not how fast; see
# docs/performance.md). Usage: benchmarks.sh BUILD_DIR
set -euo pipefail
"$1/tests/benchmarks/broadphase_bench" --benchmark_min_time=0.01 --benchmark_filter='-BruteForce/100000'
"$1/tests/benchmarks/narrowphase_bench" --benchmark_min_time=0.01
