#!/usr/bin/env bash
# Writes the student handout: a standalone tree with the framework, the EXERCISE version of
# every lab (task blocks replaced by "// TASK n: ... — see README.md" and the starter code),
# the lab sheets, the grading tests and scripts/grade.sh. No solution code goes in it.
#
# Usage: scripts/make-handout.sh OUT_DIR      (OUT_DIR must not exist, or be empty; a relative
# OUT_DIR is taken from the folder you run it in)
#
# (HANDOUT_SOLVED_TASKS=1,2 in the environment keeps those tasks solved: only for testing
# that the leak check below catches solution code.)
#
# In the handout, `cmake --preset debug` then `cmake --build --preset debug --target <lab>`
# builds the student's program, <lab>_tests tests the student's code, and
# `./scripts/grade.sh` grades it. scripts/check-handout.sh checks all of that.
set -euo pipefail
HITBOX_CALLER=$PWD # OUT_DIR is the caller's: resolved from here (from_caller), not the repository
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh

if [[ $# -ne 1 || $1 == -h || $1 == --help ]]; then
    echo "usage: $0 OUT_DIR" >&2
    exit 2
fi
out=$(from_caller "$1")
if [[ -e $out && -n $(ls -A "$out" 2>/dev/null) ]]; then
    echo "make-handout: $out exists and is not empty; give a new folder (or delete it first)." >&2
    exit 2
fi

# Any failure (a write error on a full disk, a tool that fails) ends the run with ONE line
# and leaves no half-written handout: the folder is removed if this run made it or filled it.
solution_lines=
finished=0
existed=0
[[ -e $out ]] && existed=1
on_exit() {
    [[ -n $solution_lines ]] && rm -f "$solution_lines"
    [[ $finished -eq 1 ]] && return
    if [[ $existed -eq 1 ]]; then
        find "$out" -mindepth 1 -delete 2>/dev/null # it was empty: empty again
    else
        rm -rf "$out"
    fi
    echo "make-handout: FAILED (see the line above: a write error? is the disk full?);" \
        "nothing was left in $out" >&2
}
trap on_exit EXIT
generator=framework/cmake/HitboxMakeExercise.cmake

# The files of this tree (tracked or new, not ignored), so a lab being written is included.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files --cached --others --exclude-standard | sort -u)
else
    mapfile -t files < <(find . -type f -not -path './build*' -not -path './.git/*' | sed 's|^\./||' | sort)
fi

# What a student gets. Everything else (the README for instructors, CI, Pong, benchmarks,
# the slides, the other scripts) stays out.
keep() {
    case $1 in
        tests/labs/*/hidden/*) return 1 ;; # hidden grading variants and the packs' own checks
        tests/course/*/*) return 1 ;;      # course lab folders (scripts/check-course-labs.sh)
        framework/* | assets/* | tests/support/* | tests/geometry/* | tests/labs/*) return 0 ;;
        tests/objects/* | tests/app/* | tests/debug/* | tests/course/*.cpp) return 0 ;;
        CMakeLists.txt | CMakePresets.json | .clang-format | .gitignore | tests/CMakeLists.txt) return 0 ;;
        scripts/grade.sh | scripts/lab-tests.sh | scripts/install-deps.sh) return 0 ;;
        scripts/labtool/tricks.py) return 1 ;; # (check-grading's class of tricks)
        scripts/lab.py | scripts/labtool/*.py) return 0 ;; # the lab tool: self-check, Classroom
        labs/CMakeLists.txt | labs/[0-9][0-9]_*/*) return 0 ;;
    esac
    return 1
}

# The lecture's slide markers ("// [slide:name]" and "// [/slide]" lines) mean nothing to
# a student: they are left out of every C++ file of the handout.
slide_marker='^[[:space:]]*//[[:space:]]*\[(slide:[^]]*|/slide)\][[:space:]]*\r?$'
strip_slide_markers() {
    local stripped=$1.stripping status=0
    # Written beside the file and moved over it: a write error stops here, and never leaves
    # the file empty. grep's 1 is "no line left" (a file of markers only); 2 is an error.
    grep -Ev "$slide_marker" "$1" >"$stripped" || status=$?
    [[ $status -le 1 ]] || return 1
    mv -f "$stripped" "$1"
}

mkdir -p "$out"
copied=0
generated=0
for file in "${files[@]}"; do
    [[ -f $file ]] || continue # deleted but not yet committed
    keep "$file" || continue
    mkdir -p "$out/$(dirname "$file")"
    case $file in
        labs/[0-9][0-9]_*/*.cpp | labs/[0-9][0-9]_*/*.h | labs/[0-9][0-9]_*/*.hpp)
            cmake "-DINPUT=$file" "-DOUTPUT=$out/$file" "-DSOLVED_TASKS=${HANDOUT_SOLVED_TASKS:-}" -P "$generator"
            generated=$((generated + 1))
            ;;
        *)
            cp -p "$file" "$out/$file"
            copied=$((copied + 1))
            ;;
    esac
    case $file in
        *.cpp | *.h | *.hpp) strip_slide_markers "$out/$file" ;;
    esac
    # A writer that lost its data without failing (cmake -P on a full disk) leaves a short
    # file: a source with text must give a handout file with text.
    if [[ -s $file && ! -s $out/$file ]]; then
        echo "make-handout: $out/$file was written empty" >&2
        exit 1
    fi
done

# Tells HitboxLab.cmake that the lab folders hold the student's code: one version per lab.
cat >"$out/framework/cmake/HitboxHandout.cmake" <<'EOF'
# Written by make-handout.sh: this tree is a student handout. The lab folders hold the
# student's own code, so each lab builds once: <lab> (the program) and <lab>_tests.
set(HITBOX_HANDOUT ON)
EOF

mapfile -t labs < <(lab_names)

# The files a student edits, from the solution's task markers (the grader's one list; the
# handout has no markers left to derive it from).
python3 scripts/lab.py student-files >"$out/scripts/labtool/student-files.txt"

# GitHub Classroom: on every push the same grader grades the repository once, then one
# Classroom test per task (1 point each) reads that task's mark from the gradebook.
mkdir -p "$out/.github/workflows"
{
    cat <<'EOF'
# GitHub Classroom autograding (written by make-handout.sh): grades every lab on each push
# with the lab tool (scripts/lab.py) and reports one test per task, 1 point each. Every step
# runs even when one before it failed: a lab that does not compile costs that lab only.
name: Autograding
on: [push, workflow_dispatch, repository_dispatch]
permissions:
  checks: write
  actions: read
  contents: read
jobs:
  grade:
    runs-on: ubuntu-latest
    if: github.actor != 'github-classroom[bot]'
    timeout-minutes: 30
    steps:
      - uses: actions/checkout@v4
      - name: Install the compiler, CMake, SFML and GoogleTest
        run: sudo apt-get update -qq && sudo apt-get install -y -qq g++ cmake pkg-config libsfml-dev libgtest-dev libgmock-dev
      - name: Grade every lab
        if: always()
        run: python3 scripts/lab.py grade-class --one "$GITHUB_WORKSPACE" --no-cage --out grades --build build/grading
      - name: Feedback
        if: always()
        run: cat grades/students/*.md >>"$GITHUB_STEP_SUMMARY"
EOF
    runners=()
    for lab in "${labs[@]}"; do
        for task in $(lab_tasks "$(lab_folder "$lab")"); do
            id="${lab%%_*}_task_$task"
            runners+=("$id")
            printf '%s\n' "      - name: $lab task $task" "        id: $id" "        if: always()" \
                "        uses: classroom-resources/autograding-command-grader@v1" "        with:" \
                "          test-name: $lab task $task" \
                "          command: python3 scripts/lab.py mark grades/grades.csv $lab $task" \
                "          timeout: 1" "          max-score: 1"
        done
    done
    printf '%s\n' "      - name: Report the points" "        if: always()" \
        "        uses: classroom-resources/autograding-grading-reporter@v1" "        env:"
    for id in "${runners[@]}"; do
        echo "          ${id^^}_RESULTS: \"\${{ steps.$id.outputs.result }}\""
    done
    printf '%s\n' "        with:" "          runners: $(IFS=,; echo "${runners[*]}")"
} >"$out/.github/workflows/classroom.yml"

{
    cat <<'EOF'
# Hitbox labs — student handout

The labs of the collision-detection unit. Each lab is a folder in `labs/` with a lab sheet
(`README.md`): what the lab teaches, the keys, the numbered tasks with hints, and which
tests check each task. Look for the lines `// TASK n: ... — see README.md` in the lab's
code: that is where you write.

## Build and run (Linux; on Windows and macOS use CMake the same way)

    ./scripts/install-deps.sh                      # once: compiler, CMake, SFML, GoogleTest
    cmake --preset debug
    cmake --build --preset debug --target lab01_point_in_box
    ./build/debug/labs/01_point_in_box/lab01_point_in_box

Every lab program has the same keys: F1 shows the collision boxes, P pauses, N steps one
frame while paused, F12 saves a screenshot, Esc quits. Options: `--headless --frames 600`
runs without a window, `--screenshot out.png` saves one frame.

## Check your work

    python3 scripts/lab.py grade 01                # one lab (Windows: py scripts/lab.py grade 01)
    python3 scripts/lab.py grade --all             # every lab

builds the lab's grading tests against your code, runs each test in a process of its own
and prints, for each task, how many of its tests pass and fail, and why (JUnit XML in
`build/debug/grade-results/`). A task is done when none of its tests fail. Each test's
name says what it checks, e.g. `Task1BounceOffTheWalls.BallNeverLeavesTheWindow`. A test
that crashes, runs longer than 10 seconds (an endless loop) or prints more than 1 MB
counts as failed and the table says so: the same rule and limits your instructor grades
with. A lab that does not compile shows "did not build" (the compiler's messages are in
`build/debug/grade-results/<lab>.build.log`); the other labs are still graded. You can
also run one lab's tests directly:

    cmake --build --preset debug --target lab01_point_in_box_tests
    ./build/debug/tests/labs/01_point_in_box/lab01_point_in_box_tests

## The labs

EOF
    for lab in "${labs[@]}"; do
        folder=$(lab_folder "$lab")
        title=$(sed -n '1s/^#[[:space:]]*//p' "$folder/README.md" 2>/dev/null || true)
        echo "- \`$folder/\` — ${title:-$lab} (program \`$lab\`)"
    done
    cat <<'EOF'

The framework (`framework/hitbox/`) is yours to read: `GameObject.h`, `Collision.h` and
`Input.h` are the classes the labs use.
EOF
} >"$out/README.md"

# The lab sheets speak of the course repository's targets too (<lab>_exercise, the
# solution <lab>); in the handout the student's program is <lab> and its tests <lab>_tests.
for sheet in "$out"/labs/[0-9][0-9]_*/README.md; do
    [[ -f $sheet ]] || continue
    perl -0pi -e 's/\(In the course repository[^)]*\)[ \t]*\n?//g; s/^.*# the solution\n//mg;
        s/(lab\d\d_\w+?)_exercise_tests\b/$1_tests/g; s/(lab\d\d_\w+?)_exercise\b/$1/g' "$sheet"
done
# Every target the handout's text names must exist there.
mapfile -t named < <(grep -ohE '\blab[0-9]{2}_[A-Za-z0-9_]+' "$out/README.md" "$out"/labs/*/README.md | sort -u)
for target in "${named[@]}"; do
    if ! is_one_of "$target" "${labs[@]/%/_tests}" "${labs[@]}"; then
        echo "make-handout: the handout names a target it does not have: $target" >&2
        grep -ln "$target" "$out/README.md" "$out"/labs/*/README.md >&2
        exit 1
    fi
done

# No solution may leak: every solution-only line (a line inside a BEGIN TASK block that
# appears nowhere else in any lab, not even as starter code) must be absent from the
# handout's labs/. Whole lines are compared, blanks around them ignored.
leaks=0
solution_lines=$(mktemp)
mapfile -t sources < <(find labs -path 'labs/[0-9][0-9]_*' -type f \( -name '*.cpp' -o -name '*.h' -o -name '*.hpp' \))
if [[ ${#sources[@]} -gt 0 ]]; then
    awk '
        { text = $0; sub(/\r$/, "", text); trimmed = text; gsub(/^[ \t]+|[ \t]+$/, "", trimmed) }
        text ~ /^[ \t]*\/\/[ \t]*BEGIN TASK/ { state = "solution"; next }
        text ~ /^[ \t]*\/\/[ \t]*STARTER TASK/ { state = "starter"; next }
        text ~ /^[ \t]*\/\/[ \t]*END TASK/ { state = ""; next }
        state == "solution" { solution[trimmed] = 1; next }
        state == "starter" { sub(/^\/\/ ?/, "", trimmed); elsewhere[trimmed] = 1; next }
        { elsewhere[trimmed] = 1 }
        END { for (line in solution) if (length(line) >= 12 && !(line in elsewhere)) print line }
        ' "${sources[@]}" >"$solution_lines"
fi
checked=$(wc -l <"$solution_lines")
mapfile -t handout_files < <(find "$out/labs" -type f)
while IFS= read -r line; do
    echo "make-handout: solution line leaked into the handout: $line" >&2
    leaks=$((leaks + 1))
done < <(awk '
    FNR == NR { wanted[$0] = 1; next }
    { trimmed = $0; sub(/\r$/, "", trimmed); gsub(/^[ \t]+|[ \t]+$/, "", trimmed) }
    trimmed in wanted && !(trimmed in seen) { seen[trimmed] = 1; print trimmed " (" FILENAME ":" FNR ")" }
    ' "$solution_lines" "${handout_files[@]}")
if grep -rqE '//[[:space:]]*(BEGIN|STARTER|END) TASK' "$out/labs"; then
    echo "make-handout: task markers left in the handout:" >&2
    grep -rnE '//[[:space:]]*(BEGIN|STARTER|END) TASK' "$out/labs" >&2
    leaks=$((leaks + 1))
fi
if grep -rqE --include='*.cpp' --include='*.h' --include='*.hpp' "$slide_marker" "$out"; then
    echo "make-handout: slide markers left in the handout:" >&2
    grep -rnE --include='*.cpp' --include='*.h' --include='*.hpp' "$slide_marker" "$out" >&2
    leaks=$((leaks + 1))
fi
if [[ $leaks -gt 0 ]]; then
    echo "make-handout: solution code in the handout (see above)" >&2
    exit 1
fi
finished=1

echo "make-handout: wrote $out: ${#labs[@]} labs (${labs[*]}), $generated exercise sources," \
    "$copied other files; $checked solution-only lines checked absent"
