# Sourced by scripts/check-course-labs.sh: place_lab FOLDER decides where one course lab folder
# is built and run: here, or in the Debian unstable root when it needs an SFML this machine
# lacks. It sets verdict ("go", "done": skipped, "fail": one FAIL line said why), name,
# generation, sfml_major, inside (the command prefix), build, launcher and lab_path.
place_lab() {
    local lab=$1
    verdict=go
    name="$(basename "$lab")"
    if [[ ! -f $lab/Main.cpp ]]; then
        echo "FAIL $name: not a lab folder (no Main.cpp in it)" >&2
        verdict=fail
        return
    fi
    # The generation decides the SFML major; the build says the same (HitboxCourseLab.cmake).
    generation=$(cmake "-DHITBOX_PRINT_GENERATION_OF=$lab" -P framework/cmake/HitboxCourseLab.cmake)
    sfml_major=2
    [[ $generation == 2025 ]] && sfml_major=3
    inside=()                 # run build and program here...
    build=build/course-sfml$sfml_major
    launcher=$(command -v ccache || true)
    lab_path="$(cd "$lab" && pwd)"
    if [[ $sfml_major != "$sfml_major_here" ]]; then
        inside=(scripts/sid-root.sh run) # ...or in the root, where this checkout is /hitbox
        build=build/sid-course
        launcher=""
        lab_path="$(realpath --relative-to=. "$lab")"
        if [[ $sfml_major != 3 || $lab_path == ../* ]]; then
            echo "FAIL $name: needs SFML $sfml_major, not installed here (only folders inside this checkout can use scripts/sid-root.sh)" >&2
            verdict=fail
            return
        fi
        # A 2025-26 lab needs Hitbox's SFML 3 port (HitboxSFML.cmake accepting SFML 3) and
        # its maths free of SFML types (the geometry layer marked NO_SFML). Until both are in,
        # say so on one line rather than fail or pass in silence.
        if ! grep -q 'SFML 3' framework/cmake/HitboxSFML.cmake ||
            ! grep -qE '^hitbox_layer\(geometry +NO_SFML' framework/CMakeLists.txt; then
            echo "SKIP $name: a 2025-26 lab; Hitbox does not build on SFML 3 yet" >&2
            verdict=done
            return
        fi
    fi
}
