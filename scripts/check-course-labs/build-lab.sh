# Sourced by scripts/check-course-labs.sh: build_lab FOLDER configures and builds one course lab
# folder (in the Debian unstable root when it needs SFML 3). It sets verdict: "go" (built: run
# it), "done" (skipped, or it must not build and did not) or "fail" (one FAIL line said why),
# and, for run_lab, name, build, inside and run_says.
build_lab() {
    local lab=$1
    verdict=go
    place_lab "$lab"
    [[ $verdict == go ]] || return 0

    mapfile -t cmake_options < <(expectation "$lab" cmake)
    mapfile -t configure_says < <(expectation "$lab" "configure says")
    mapfile -t run_says < <(expectation "$lab" "run says")
    mouse_at=$(expectation "$lab" "hold the mouse at")
    build_fails=$(grep -sx "build fails" "$lab/check-course-lab.txt" || true)

    echo "== $name ($generation-generation course framework, SFML $sfml_major): build"
    # One build folder per SFML major: the framework is compiled once. The converted copies
    # of the previous lab's files and its run folder are removed so nothing is picked up by
    # mistake.
    rm -rf "$build/course_lab_sources" "$build/course_lab_run"
    mkdir -p "$build"
    # The lab's own Framework/ files to build are named afresh for every folder.
    configured=0
    "${inside[@]}" cmake -S . -B "$build" -DHITBOX_COURSE_LAB_DIR="$lab_path" \
        -DHITBOX_BUILD_TESTS=OFF -DHITBOX_BUILD_BENCHMARKS=OFF -DHITBOX_COURSE_LAB_OWN_FRAMEWORK= \
        -DCMAKE_CXX_COMPILER_LAUNCHER="$launcher" "${cmake_options[@]}" >"$build/configure.log" 2>&1 ||
        configured=$?
    missing=0
    for line in "${configure_says[@]}"; do
        grep -F -- "$line" "$build/configure.log" || { echo "FAIL $name: configure did not say \"$line\" ($build/configure.log)" >&2; missing=1; }
    done
    if [[ $missing != 0 ]]; then
        verdict=fail
        return
    fi
    built=0
    if [[ $configured == 0 ]]; then
        "${inside[@]}" cmake --build "$build" --target course_lab -j 2 >"$build/build.log" 2>&1 || built=$?
    fi
    if [[ -n $build_fails ]]; then
        if [[ $configured == 0 && $built == 0 ]]; then
            echo "FAIL $name: built, but it should not (the project leaves out a file it needs)" >&2
            failed=1
        else
            echo "ok   $name (does not build, as in Visual Studio, and configure said so)"
        fi
        verdict=done
        return
    fi
    if [[ $configured != 0 || $built != 0 ]]; then
        tail -n 30 "$build/build.log" >&2 || true
        echo "FAIL $name: does not build (logs: $build/configure.log, $build/build.log)" >&2
        verdict=fail
        return
    fi
    grep -m1 "Course lab: .*course framework" "$build/configure.log" || true
}
