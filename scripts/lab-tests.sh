# shellcheck shell=bash
# lab-tests.sh - shell functions shared by check-exercises.sh, check-handout.sh and other checks.
# Source it; it is not a program:   source "$(dirname "$0")/lab-tests.sh"

# Seconds one run of a test program may take before it counts as hung.
: "${LAB_TEST_TIMEOUT:=60}"

# from_caller PATH: PATH as the one who started the script meant it. The scripts move to the
# repository's top folder first, so a relative path on their command line is taken from
# HITBOX_CALLER, the folder they were started in (each sets it before its `cd`).
from_caller() {
    if [[ -z $1 || $1 == /* ]]; then
        printf '%s\n' "$1"
    else
        printf '%s\n' "${HITBOX_CALLER:-$PWD}/$1"
    fi
}

# is_one_of WORD LIST...: true when WORD is one of the LIST. No `printf | grep -qx`: under
# `set -o pipefail` that pipeline fails whenever grep finds the word and exits before printf
# has written everything (printf dies of SIGPIPE, exit 141), a random "not found".
is_one_of() {
    local word=$1 item
    shift
    for item in "$@"; do
        [[ $item == "$word" ]] && return 0
    done
    return 1
}

# lab_names, lab_folder NAME, lab_tasks FOLDER_OR_NAME: the lab list and the task numbers,
# from the one lab tool (scripts/lab.py, which owns the lab list and the task-marker grammar).
lab_names() { python3 scripts/lab.py labs; }
lab_folder() { python3 scripts/lab.py folder "$1"; }
lab_tasks() { python3 scripts/lab.py tasks "$1"; }
# lab_sources FOLDER: the files of the lab that hold a task marker (the student's files).
lab_sources() { python3 scripts/lab.py student-files | grep "^$1/" || true; }

# find_test_program BUILD_DIR NAME: the path of the built program NAME under BUILD_DIR.
find_test_program() {
    find "$1" -type f -name "$2" -perm -u+x -not -path '*/CMakeFiles/*' 2>/dev/null | head -n 1
}

# run_gtest PROGRAM RESULTS_FILE [XML_FILE]
# Runs every test of a GoogleTest program and writes one line per test to RESULTS_FILE:
#     PASS Suite.Name      or      FAIL Suite.Name      (FAIL Suite.Name hung|crashed)
# A test that crashes the program or hangs (runs longer than LAB_TEST_TIMEOUT seconds)
# counts as failed, and the other tests run again without it, so one crash never hides the
# rest. The program's output goes to RESULTS_FILE.log. With XML_FILE, writes JUnit XML there
# for every test, the crashed and hung ones included (as failures saying "crashed ..." or
# "hung: timed out after N s"). Returns 0 when every test passed.
run_gtest() {
    local program=$1 results=$2 xml=${3:-}
    local excluded="" filter status crashed output why
    : >"$results"
    : >"$results.log"
    # A result left from an earlier run must never stand in for this one.
    [[ -z $xml ]] || rm -f "$xml" "$xml.crashed.xml"
    local crashed_names=() crashed_whys=() crashed_outputs=()
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
                why="stopped with exit status $status outside any test"
                [[ $status -eq 124 || $status -eq 137 ]] && why="hung outside any test: timed out after ${LAB_TEST_TIMEOUT} s"
                echo "run_gtest: $program $why" >>"$results.log"
                echo "FAIL WholeProgram.ExitedNormally crashed" >>"$results"
                crashed_names+=("WholeProgram.ExitedNormally")
                crashed_whys+=("$why")
                crashed_outputs+=("$(tail -n 40 "$output")")
            fi
            rm -f "$output"
            break
        fi
        if [[ $status -eq 124 || $status -eq 137 ]]; then
            why="hung: timed out after ${LAB_TEST_TIMEOUT} s"
            echo "FAIL $crashed hung" >>"$results"
        else
            why="crashed (exit status $status)"
            # 128 + n: killed by signal n (SIGSEGV, SIGABRT, ...).
            [[ $status -gt 128 ]] && why="crashed (exit status $status: SIG$(kill -l $((status - 128)) 2>/dev/null || echo "?"))"
            echo "FAIL $crashed crashed" >>"$results"
        fi
        echo "run_gtest: $crashed $why; running the other tests again without it" >>"$results.log"
        echo "  $crashed $why; running the other tests again without it" >&2
        crashed_names+=("$crashed")
        crashed_whys+=("$why")
        # What the test printed before it stopped (from its RUN line on).
        crashed_outputs+=("$(awk -v name="$crashed" '$0 == "[ RUN      ] " name { on = 1 } on' "$output" | tail -n 40)")
        rm -f "$output"
        excluded="${excluded:+$excluded:}$crashed"
    done
    if [[ -n $xml ]]; then
        [[ -f $xml ]] || write_empty_junit "$xml"
        local i
        for i in "${!crashed_names[@]}"; do
            add_junit_failure "$xml" "${crashed_names[$i]}" "${crashed_whys[$i]}" "${crashed_outputs[$i]}"
        done
    fi
    ! grep -q '^FAIL ' "$results"
}

# write_empty_junit XML_FILE: a JUnit file with no tests (for when none could run).
write_empty_junit() {
    printf '%s\n' '<?xml version="1.0" encoding="UTF-8"?>' \
        '<testsuites tests="0" failures="0" disabled="0" errors="0" name="AllTests">' \
        '</testsuites>' >"$1"
}

# add_junit_failure XML_FILE SUITE.NAME MESSAGE [DETAILS]: adds a failed test to a JUnit
# file GoogleTest (or write_empty_junit) wrote: into the <testsuite> of that name when the
# file has one (the suite's other tests ran without it), else in a <testsuite> of its own.
# The totals of the suite and of the file count it, so tools that read the file see it
# like any other failed test, once.
add_junit_failure() {
    local xml=$1 name=$2 message=$3 details=${4:-}
    local suite=${name%%.*} test=${name#*.}
    local escaped_details=${details//]]>/]] >}
    local case_xml suite_open
    case_xml=$(
        echo "    <testcase name=\"$(xml_escape "$test")\" status=\"run\" result=\"completed\" time=\"0\" classname=\"$(xml_escape "$suite")\">"
        echo "      <failure message=\"$(xml_escape "$message")\" type=\"\"><![CDATA[$message"
        [[ -z $escaped_details ]] || printf '%s\n' "$escaped_details"
        echo "]]></failure>"
        echo "    </testcase>"
    )
    suite_open="<testsuite name=\"$(xml_escape "$suite")\""
    local updated
    updated=$(mktemp)
    CASE_XML=$case_xml SUITE_OPEN=$suite_open awk '
        # One more test and one more failure in the first tests= and failures= of a line.
        function count_one(line,    n) {
            if (match(line, / tests="[0-9]+"/)) {
                n = substr(line, RSTART + 8, RLENGTH - 9) + 1
                line = substr(line, 1, RSTART - 1) " tests=\"" n "\"" substr(line, RSTART + RLENGTH)
            }
            if (match(line, / failures="[0-9]+"/)) {
                n = substr(line, RSTART + 11, RLENGTH - 12) + 1
                line = substr(line, 1, RSTART - 1) " failures=\"" n "\"" substr(line, RSTART + RLENGTH)
            }
            return line
        }
        /<testsuites / && !done_totals { $0 = count_one($0); done_totals = 1 }
        !added && index($0, ENVIRON["SUITE_OPEN"] " ") { $0 = count_one($0); inside = 1 }
        inside && /<\/testsuite>/ { print ENVIRON["CASE_XML"]; inside = 0; added = 1 }
        /^<\/testsuites>/ && !added {
            print "  " ENVIRON["SUITE_OPEN"] " tests=\"1\" failures=\"1\" disabled=\"0\" skipped=\"0\" errors=\"0\" time=\"0\">"
            print ENVIRON["CASE_XML"]
            print "  </testsuite>"
        }
        { print }' "$xml" >"$updated"
    mv "$updated" "$xml"
}

# xml_escape TEXT: TEXT with & < > " escaped for an XML attribute.
xml_escape() {
    local text=${1//&/&amp;}
    text=${text//</&lt;}
    text=${text//>/&gt;}
    printf '%s' "${text//\"/&quot;}"
}

# task_counts RESULTS_FILE TASK: prints "passed failed" for the tests of suites named
# Task<TASK><not a digit>... (Task1Hover, not Task12Hover).
task_counts() {
    awk -v task="$2" '
        { suite = $2; sub(/\..*/, "", suite) }
        suite ~ ("^Task" task "([^0-9]|$)") { if ($1 == "PASS") passed++; else failed++ }
        END { printf "%d %d\n", passed, failed }' "$1"
}

# task_stopped RESULTS_FILE TASK: says how many tests of the task (or "-": of no task) hung
# or crashed, e.g. "2 hung (timed out after 60 s), 1 crashed"; prints nothing when none did.
task_stopped() {
    awk -v task="$2" -v timeout="$LAB_TEST_TIMEOUT" '
        { suite = $2; sub(/\..*/, "", suite) }
        task == "-" && suite ~ /^Task[0-9]/ { next }
        task != "-" && suite !~ ("^Task" task "([^0-9]|$)") { next }
        $3 == "hung" { hung++ }
        $3 == "crashed" { crashed++ }
        END {
            text = ""
            if (hung) text = hung " hung (timed out after " timeout " s)"
            if (crashed) text = text (text == "" ? "" : ", ") crashed " crashed"
            print text
        }' "$1"
}
