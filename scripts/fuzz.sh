#!/usr/bin/env bash
# Fuzzes lab 9's level parser, the shared command line and a World changed from inside its
# own responses with libFuzzer (clang-14, with
# AddressSanitizer and UndefinedBehaviorSanitizer) for a fixed time each, then prints the
# executions per second. Builds in build/fuzz, apart from the g++ builds.
# Usage: ./scripts/fuzz.sh [SECONDS_PER_TARGET]     (default 30; CI runs 30 + 30 + 30)
# A crash stops it with the input's path: copy that file into tests/fuzz/corpus/TARGET/,
# where every build replays it as a regression test (fuzz.TARGET.ReplaysTheCorpus).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
if ! command -v clang++-14 >/dev/null; then
    echo "fuzz.sh: needs clang 14 and its libFuzzer: apt-get install clang-14 libclang-rt-14-dev" >&2
    exit 1
fi
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
mkdir -p build/fuzz
if ! { cmake -S . -B build/fuzz -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "${launcher[@]}" -DHITBOX_FUZZ=ON -DHITBOX_BUILD_BENCHMARKS=OFF \
    "-DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined" &&
    cmake --build build/fuzz -j2 --target options_fuzzer level_fuzzer world_fuzzer; } >build/fuzz/build.log 2>&1; then
    tail -n 30 build/fuzz/build.log >&2
    echo "fuzz.sh: the fuzz targets did not build (full log: build/fuzz/build.log)" >&2
    exit 1
fi
for target in level options world; do
    # New inputs go to the build folder; the repository's corpus is read only.
    mkdir -p "build/fuzz/corpus-$target"
    log="build/fuzz/$target.log"
    if ! "build/fuzz/tests/fuzz/${target}_fuzzer" -max_total_time="$seconds" -print_final_stats=1 \
        -artifact_prefix="build/fuzz/crash-$target-" "build/fuzz/corpus-$target" \
        "tests/fuzz/corpus/$target" >"$log" 2>&1; then
        grep -E "ERROR|SUMMARY|Test unit written" "$log" >&2 || tail -n 20 "$log" >&2
        echo "fuzz.sh: $target found a bug (full log: $log). Keep the input as a regression test:" \
             "cp build/fuzz/crash-$target-* tests/fuzz/corpus/$target/" >&2
        exit 1
    fi
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
    echo "fuzz.sh: $target: $runs inputs in ${seconds} s ($rate per second), no crash"
done
