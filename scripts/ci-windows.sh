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

# The test program must say every test passed: a crash or a failure is a non-zero exit.
# (Output under wine ends its lines with CR LF, as on Windows.)
expect_all_passed() { # log
    grep -qE $'^\\[  PASSED  \\] [0-9]+ tests\\.\r?$' "$1" && ! grep -q "^\[  FAILED  \]" "$1"
}

step "1. mingw-w64: the SFML-free layers for Windows, Debug and Release, tests under wine"
# GoogleTest is built as DLLs (BUILD_SHARED_LIBS), as SFML 2.6 is on Windows: the tests start
# only if the build copied the DLLs next to them (hitbox_copy_runtime_dlls).
cmake -S . -B "$out/mingw" -G "Ninja Multi-Config" \
    --toolchain "$PWD/framework/cmake/MingwW64Toolchain.cmake" \
    -DHITBOX_WITH_SFML=OFF -DHITBOX_WARNINGS_AS_ERRORS=ON -DHITBOX_BUILD_BENCHMARKS=OFF \
    -DBUILD_SHARED_LIBS=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    "-DFETCHCONTENT_SOURCE_DIR_GOOGLETEST=$googletest" \
    "-DCMAKE_CROSSCOMPILING_EMULATOR=$PWD/scripts/wine-run.sh" >"$out/mingw.log"
grep -q "Hitbox: using GoogleTest from $googletest" "$out/mingw.log"
# A new wine prefix sets itself up on its first start (tens of seconds): once, before the
# build runs the tests to list them.
scripts/wine-run.sh wineboot --init >/dev/null 2>&1
WINEPREFIX="$HITBOX_WINEPREFIX" wineserver -w
for config in Debug Release; do
    cmake --build "$out/mingw" --config "$config" -j2 >>"$out/mingw.log"
    program="$out/mingw/tests/$config/hitbox_core_tests.exe"
    [[ $(file "$program") == *"PE32+ executable"* ]] # a Windows program, not a Linux one
    if ! scripts/wine-run.sh "$program" >"$out/wine-$config.log" 2>&1 || \
        ! expect_all_passed "$out/wine-$config.log"; then
        tail -n 30 "$out/wine-$config.log" >&2
        echo "ci-windows: the SFML-free tests fail under wine ($config); see $out/wine-$config.log" >&2
        exit 1
    fi
    echo "  $config: $(tr -d '\r' <"$out/wine-$config.log" | grep "^\[  PASSED  \]")"
done
# ctest runs the discovered tests through the emulator too (one process per test: a sample).
(cd "$out/mingw" && ctest -C Release -R '^(Platform|Tunnelling)\.' --output-on-failure) \
    >"$out/mingw-ctest.log" || { cat "$out/mingw-ctest.log" >&2; exit 1; }
grep "tests passed" "$out/mingw-ctest.log" | sed 's/^/  ctest under wine: /'

step "2. every other source compiled for Windows (mingw, MSVC's deprecations, -Werror)"
# Against SFML 3's headers (what a Windows build downloads) when the Debian unstable root
# exists, else SFML 2's. The sources step 1 built for real are left out.
sfml=/var/cache/hitbox/sid-root/usr/include/SFML
[[ -f "$sfml/Config.hpp" ]] || sfml=/usr/include/SFML
mkdir -p "$out/sfml" && ln -sfn "$sfml" "$out/sfml/SFML"
label="SFML $(sed -n 's/^#define SFML_VERSION_MAJOR *\([0-9]*\).*/\1/p' "$sfml/Config.hpp")"
python3 scripts/compile-check.py mingw "$linux_build" "$PWD/$out/sfml" \
    "$googletest/googletest/include" "$googletest/googlemock/include" --skip "$out/mingw" | sed "s|^|  $label: |"
# mingw marks fewer calls deprecated than MSVC does (localtime, gmtime, ctime...): name them.
# Only framework/hitbox/platform/Platform.cpp may call them, or a POSIX environment call.
crt='(localtime|gmtime|ctime|asctime|strerror|getenv|strtok|v?sprintf|v?sscanf|v?fscanf|scanf'
crt+='|fopen|freopen|strn?cpy|strn?cat|mbstowcs|wcstombs|tmpnam|_?getpid|_?putenv|(un)?setenv)'
if git grep -nE "\b$crt\s*\(" -- '*.cpp' '*.h' ':!tests/course/week*' \
    ':!framework/hitbox/platform/Platform.cpp' | grep -vE '^[^:]*:[0-9]+:\s*//'; then
    echo "ci-windows: a C runtime call MSVC deprecates (C4996), outside the platform file:" \
         "call hitbox::platform (framework/hitbox/platform/Platform.h) instead" >&2
    exit 1
fi
if git grep -nE '#\s*include\s*<(unistd|dlfcn|pthread|fcntl|pwd|termios|windows|process)\.h>|#\s*include\s*<sys/' \
    -- '*.cpp' '*.h' ':!tests/course/week*' ':!framework/hitbox/platform/Platform.cpp'; then
    echo "ci-windows: a system header outside framework/hitbox/platform/Platform.cpp" >&2
    exit 1
fi
# A per-file optimisation pragma can break another file's code under GCC's inter-procedural
# register allocation (a mingw Release build once crashed so): the build type decides.
if git grep -nE '^\s*#\s*pragma\s+GCC\s+optimize' -- '*.cpp' '*.h'; then
    echo "ci-windows: #pragma GCC optimize: leave optimisation to the build type" >&2
    exit 1
fi
echo "  no call MSVC deprecates and no system header outside framework/hitbox/platform/Platform.cpp"

step "3. clang + libc++: the SFML-free layers built and tested, the rest compiled"
CC=clang CXX=clang++ CXXFLAGS="-stdlib=libc++" LDFLAGS="-stdlib=libc++" \
    cmake -S . -B "$out/libcxx" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DHITBOX_WITH_SFML=OFF \
    -DHITBOX_WARNINGS_AS_ERRORS=ON -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON \
    "-DFETCHCONTENT_SOURCE_DIR_GOOGLETEST=$googletest" >"$out/libcxx.log"
cmake --build "$out/libcxx" -j2 >>"$out/libcxx.log"
(cd "$out/libcxx" && ctest -LE long -j2 --output-on-failure) >"$out/libcxx-ctest.log" ||
    { tail -n 40 "$out/libcxx-ctest.log" >&2; exit 1; }
grep "tests passed" "$out/libcxx-ctest.log" | sed 's/^/  libc++: /'
python3 scripts/compile-check.py libc++ "$linux_build" | sed 's/^/  libc++: /'

step "4. the presets: schema, Windows-only and Linux-only ones, a multi-config run"
# Visual Studio 2022 reads presets up to schema version 5 (learn.microsoft.com, "Configure
# and build with CMake Presets in Visual Studio").
python3 -c 'import json, sys; version = json.load(open("CMakePresets.json"))["version"]
sys.exit(f"CMakePresets.json: schema version {version}; Visual Studio 2022 reads up to 5" if version > 5 else 0)'
# What Visual Studio lists on Windows: CMake's own answer on a copy where this host plays Windows.
mkdir -p "$out/presets-on-windows"
sed 's/"Windows"/"Linux"/g' CMakePresets.json >"$out/presets-on-windows/CMakePresets.json"
listed=$(cd "$out/presets-on-windows" && cmake --list-presets=all | grep -oE '^ +"[a-z-]+"' | tr -d ' "' | sort -u | tr '\n' ' ')
if [[ "$listed" != "windows windows-release " ]]; then
    echo "ci-windows: on Windows the presets listed would be: $listed (expected windows windows-release)" >&2
    exit 1
fi
echo "  on Windows only these presets show: $listed"
# Shell scripts stay LF on a Windows checkout (.gitattributes).
if git ls-files '*.sh' | xargs git check-attr eol -- | grep -v ': eol: lf$'; then
    echo "ci-windows: these scripts would get CRLF line endings on Windows (.gitattributes)" >&2
    exit 1
fi
# A clean clone through the presets with a multi-config generator: every test runs.
git clone -q . "$out/clone"
(
    cd "$out/clone"
    export CMAKE_GENERATOR="Ninja Multi-Config"
    cmake --preset debug >../clone-configure.log
    cmake --build --preset debug >../clone-build.log
    ctest --preset debug >../clone-ctest.log 2>&1 || true
)
if grep -q "Not Run" "$out/clone-ctest.log" || ! grep -q "100% tests passed" "$out/clone-ctest.log"; then
    grep -E "Not Run|Failed|tests passed" "$out/clone-ctest.log" | tail -n 20 >&2
    echo "ci-windows: the presets under Ninja Multi-Config do not run every test; see $out/clone-ctest.log" >&2
    exit 1
fi
grep "tests passed" "$out/clone-ctest.log" | sed 's/^/  Ninja Multi-Config: /'
step "all Windows and libc++ checks passed"
