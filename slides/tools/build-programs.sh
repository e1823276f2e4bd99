#!/usr/bin/env bash
# build-programs.sh BUILD_DIR - builds the programs that draw the figures, and only those (the
# programs named in figures.txt), into BUILD_DIR: a release build without the tests and
# benchmarks (step 2 of build.sh, when it is given no build folder).
set -euo pipefail
slides="$(cd "$(dirname "$0")/.." && pwd)"
repo="$(cd "$slides/.." && pwd)"
build_dir="$1"
echo "== building the programs that draw the figures into ${build_dir#"$repo"/}"
[[ -x "$repo/scripts/install-deps.sh" && ! -f "$build_dir/CMakeCache.txt" ]] && "$repo/scripts/install-deps.sh"
export CMAKE_CXX_COMPILER_LAUNCHER="${CMAKE_CXX_COMPILER_LAUNCHER:-$(command -v ccache || true)}"
cmake -S "$repo" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DHITBOX_BUILD_TESTS=OFF \
    -DHITBOX_BUILD_BENCHMARKS=OFF >/dev/null
mapfile -t targets < <(awk '!/^#/ && NF { n = split($2, part, "/"); print part[n] }' "$slides/figures.txt" | sort -u)
cmake --build "$build_dir" --parallel 2 --target "${targets[@]}"
