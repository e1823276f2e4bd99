# Sourced by scripts/ci-windows.sh, which sets out, linux_build, googletest and step():
# clang + libc++ (as on macOS).
step "3. clang + libc++: the SFML-free layers built and tested, the rest compiled"
CC=clang CXX=clang++ CXXFLAGS="-stdlib=libc++" LDFLAGS="-stdlib=libc++" \
    cmake -S . -B "$out/libcxx" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DHITBOX_WITH_SFML=OFF \
    -DHITBOX_WARNINGS_AS_ERRORS=ON -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON \
    "-DFETCHCONTENT_SOURCE_DIR_GOOGLETEST=$googletest" >"$out/libcxx.log"
cmake --build "$out/libcxx" -j2 >>"$out/libcxx.log"
(cd "$out/libcxx" && ctest -LE long -j2 --output-on-failure) >"$out/libcxx-ctest.log" ||
    { tail -n 40 "$out/libcxx-ctest.log" >&2; exit 1; }
grep "tests passed" "$out/libcxx-ctest.log" | sed 's/^/  libc++: /'
# The sources built for real just now are left out.
python3 scripts/compile-check.py libc++ "$linux_build" --skip "$out/libcxx" | sed 's/^/  libc++: /'
