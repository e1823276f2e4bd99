# shellcheck shell=bash
# lab-tests.sh - shell functions shared by grade.sh, check-exercises.sh and check-handout.sh.
# Source it; it is not a program:   source "$(dirname "$0")/lab-tests.sh"

# Seconds one run of a test program may take before it counts as hung.
: "${LAB_TEST_TIMEOUT:=60}"

# lab_names: prints the name of every lab in labs/NN_*/CMakeLists.txt, one a line, in order
# (the first argument of its hitbox_add_lab call). Run from the tree's top folder.
lab_names() {
    local cmakelists
    for cmakelists in labs/[0-9][0-9]_*/CMakeLists.txt; do
        [[ -f $cmakelists ]] || continue
        sed -n 's/^[[:space:]]*hitbox_add_lab([[:space:]]*\([A-Za-z0-9_]*\).*/\1/p' "$cmakelists" | head -n 1
    done
}

# lab_folder NAME: prints labs/NN_folder of the lab called NAME.
lab_folder() {
    local cmakelists
    for cmakelists in labs/[0-9][0-9]_*/CMakeLists.txt; do
        if grep -Eq "^[[:space:]]*hitbox_add_lab\([[:space:]]*$1([[:space:]]|$)" "$cmakelists"; then
            dirname "$cmakelists"
            return 0
        fi
    done
    return 1
}

# lab_tasks FOLDER: the task numbers marked "// BEGIN TASK n:" in the folder's sources
# (or "// TASK n:" in a handout), sorted, one a line.
lab_tasks() {
    grep -rhoE '//[[:space:]]*(BEGIN )?TASK [0-9]+:' "$1" --include='*.cpp' --include='*.h' --include='*.hpp' |
        grep -oE '[0-9]+' | sort -n -u
}

# find_test_program BUILD_DIR NAME: the path of the built program NAME under BUILD_DIR.
find_test_program() {
    find "$1" -type f -name "$2" -perm -u+x -not -path '*/CMakeFiles/*' 2>/dev/null | head -n 1
}

# run_gtest PROGRAM RESULTS_FILE [XML_FILE]
# Runs every test of a GoogleTest program and writes one line per test to RESULTS_FILE:
#     PASS Suite.Name      or      FAIL Suite.Name
# A test that crashes the program or hangs (LAB_TEST_TIMEOUT) counts as failed, and the
# other tests run again without it, so one crash never hides the rest. The program's
# output goes to RESULTS_FILE.log. With XML_FILE, GoogleTest writes JUnit XML there; crashed
# tests are added to XML_FILE.crashed.xml (also JUnit). Returns 0 when every test passed.
run_gtest() {
    local program=$1 results=$2 xml=${3:-}
    local excluded="" filter status crashed output
    : >"$results"
    : >"$results.log"
    rm -f "${xml:+$xml.crashed.xml}"
    local crashed_list=()
    while true; do
        filter="*${excluded:+-$excluded}"
        output=$(mktemp)
        status=0
        timeout --kill-after=5 "$LAB_TEST_TIMEOUT" "$program" --gtest_color=no \
            --gtest_filter="$filter" ${xml:+"--gtest_output=xml:$xml"} >"$output" 2>&1 || status=$?
        cat "$output" >>"$results.log"
        # The test that started but never finished is the one that crashed or hung.
        crashed=$(awk '
            /^\[ RUN      \] / { running = $4 }
            /^\[       OK \] / || /^\[  FAILED  \] .*\([0-9]+ ms\)$/ { running = "" }
            END { print running }' "$output")
        if [[ $status -le 1 || -z $crashed ]]; then
            awk '
                /^\[       OK \] / { print "PASS " $4 }
                /^\[  FAILED  \] .*\([0-9]+ ms\)$/ { sub(/,$/, "", $4); print "FAIL " $4 }' \
                "$output" >>"$results"
            if [[ $status -gt 1 ]]; then
                # It failed outside any test (before the first one, or while exiting).
                echo "run_gtest: $program stopped with exit status $status outside a test" >>"$results.log"
                echo "FAIL WholeProgram.ExitedNormally" >>"$results"
            fi
            rm -f "$output"
            break
        fi
        rm -f "$output"
        local why="crashed (exit status $status)"
        [[ $status -eq 124 || $status -eq 137 ]] && why="did not finish within ${LAB_TEST_TIMEOUT} s"
        echo "run_gtest: $crashed $why; running the other tests again without it" >>"$results.log"
        crashed_list+=("$crashed|$why")
        excluded="${excluded:+$excluded:}$crashed"
    done
    local entry
    for entry in "${crashed_list[@]}"; do
        echo "FAIL ${entry%%|*}" >>"$results"
    done
    if [[ -n $xml && ${#crashed_list[@]} -gt 0 ]]; then
        {
            echo '<?xml version="1.0" encoding="UTF-8"?>'
            echo "<testsuites name=\"crashed\" tests=\"${#crashed_list[@]}\" failures=\"${#crashed_list[@]}\">"
            for entry in "${crashed_list[@]}"; do
                local name=${entry%%|*}
                echo "  <testsuite name=\"${name%%.*}\" tests=\"1\" failures=\"1\">"
                echo "    <testcase name=\"${name#*.}\" classname=\"${name%%.*}\">"
                echo "      <failure message=\"${entry#*|}\"/>"
                echo "    </testcase>"
                echo "  </testsuite>"
            done
            echo "</testsuites>"
        } >"$xml.crashed.xml"
    fi
    ! grep -q '^FAIL ' "$results"
}

# task_counts RESULTS_FILE TASK: prints "passed failed" for the tests of suites named
# Task<TASK><not a digit>... (Task1Hover, not Task12Hover).
task_counts() {
    awk -v task="$2" '
        { suite = $2; sub(/\..*/, "", suite) }
        suite ~ ("^Task" task "([^0-9]|$)") { if ($1 == "PASS") passed++; else failed++ }
        END { printf "%d %d\n", passed, failed }' "$1"
}
