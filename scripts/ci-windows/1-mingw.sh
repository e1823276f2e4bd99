# Sourced by scripts/ci-windows.sh, which sets out, linux_build, googletest and step():
# the SFML-free layers cross-built for Windows with mingw-w64, Debug and Release, their
# tests run under wine.

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
# Debug runs every test but the seeded agreement suites: unoptimised under wine they took
# 1,000 of its 1,070 s (wine's heap); Release runs all of them, as Linux's Debug build does.
declare -A filter=([Debug]="-EveryKindOfScene/*:AllMethodsAgreeWithBruteForce.*:Agreement.*" [Release]="*")
for config in Debug Release; do
    cmake --build "$out/mingw" --config "$config" -j2 >>"$out/mingw.log"
    program="$out/mingw/tests/$config/hitbox_core_tests.exe"
    [[ $(file "$program") == *"PE32+ executable"* ]] # a Windows program, not a Linux one
    if ! scripts/wine-run.sh "$program" "--gtest_filter=${filter[$config]}" >"$out/wine-$config.log" 2>&1 || \
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
