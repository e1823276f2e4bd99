#!/usr/bin/env bash
# Checks the class grader (scripts/grade-class.sh) against the ways a mark could be faked,
# on lab 2: a class of made-up submissions is graded and each must get exactly its marks.
#   solution, solution-zip, solution-git   the reference solution (a folder, a zip, a git
#                                          repository): every task
#   starter                                the untouched exercise: no task
#   exit-in-constructor                    starter + exit(0) in Ball's constructor: no task
#   exit-in-update                         starter + exit(0) at the start of update: no task
#   fake-ok-lines                          starter + prints "[       OK ] Task..." lines for
#                                          every test, then exit(0) before main: no task
#   disabled-tests                         solution of task 1 only, and its own copy of the
#                                          grading tests with every test renamed DISABLED_
#                                          (ignored): task 1 only
#   touching-wall                          the solution with the wall test written <= / >=
#                                          (touching counts as a hit): tasks 2 and 3 only
#   define-test                            starter + "#define TEST(...)" in Ball.h (ignored)
#                                          and in BallsLevel.cpp (refused): no task
# Then runs scripts/check-fair-marks.sh on the labs listed in fair_labs below.
# Usage: scripts/check-grading.sh [--build DIR] [WORK_DIR]    (default build/check-grading)
#   --build DIR  the instructor's build to grade with (default build/grading; CI: build/debug)
set -euo pipefail
HITBOX_CALLER=$PWD # relative paths on the command line are the caller's (from_caller)
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh
work=build/check-grading
build_options=()
while [[ $# -gt 0 ]]; do
    case $1 in
        --build) build_options=(--build "$(from_caller "$2")"); shift 2 ;;
        *) work=$(from_caller "$1"); shift ;;
    esac
done
lab=labs/02_bouncing_balls
generator=framework/cmake/HitboxMakeExercise.cmake
rm -rf "$work/class" "$work/grades"
mkdir -p "$work/class"
class=$work/class

# submission NAME SOLVED_TASKS: a folder like a student's handout copy of lab 2, with the
# given tasks solved ("" = the starter).
submission() {
    local folder=$class/$1/$lab source
    mkdir -p "$folder"
    cp "$lab"/CMakeLists.txt "$lab"/README.md "$folder/"
    for source in "$lab"/*.cpp "$lab"/*.h; do
        cmake "-DINPUT=$source" "-DOUTPUT=$folder/$(basename "$source")" "-DSOLVED_TASKS=$2" -P "$generator"
    done
}
submission solution 1,2,3
(cd "$class/solution" && zip -qr ../solution-zip.zip .)
git init -q "$class/solution-git.src"
cp -r "$class/solution/labs" "$class/solution-git.src/"
git -C "$class/solution-git.src" add -A
git -C "$class/solution-git.src" -c user.name=student -c user.email=student@example.com commit -qm work
git clone -q --bare "$class/solution-git.src" "$class/solution-git.git"
rm -rf "$class/solution-git.src"
submission starter ""

submission exit-in-constructor ""
sed -i 's/^    setSize({2.f \* ballRadius/    std::exit(0);\n&/' "$class/exit-in-constructor/$lab/Ball.cpp"
submission exit-in-update ""
sed -i 's/^    move(velocity \* dt);/    std::exit(0);\n&/' "$class/exit-in-update/$lab/Ball.cpp"
grep -q 'std::exit(0)' "$class/exit-in-constructor/$lab/Ball.cpp" "$class/exit-in-update/$lab/Ball.cpp"

submission fake-ok-lines ""
{
    echo '#include <cstdio>'
    echo '#include <cstdlib>'
    echo 'namespace {'
    echo 'struct FakeResults {'
    echo '    FakeResults() {'
    grep -hoE 'TEST\((Task[0-9]+[A-Za-z]*|[A-Za-z]+), [A-Za-z]+\)' tests/labs/02_bouncing_balls/*.cpp |
        sed -E 's/TEST\(([^,]+), ([^)]+)\)/        std::printf("[ RUN      ] \1.\2\\n[       OK ] \1.\2 (0 ms)\\n");/'
    echo '        std::printf("[  PASSED  ] every test.\\n");'
    echo '        std::exit(0);'
    echo '    }'
    echo '} fakeResults;'
    echo '}'
} >>"$class/fake-ok-lines/$lab/Ball.cpp"

submission disabled-tests 1
mkdir -p "$class/disabled-tests/tests/labs/02_bouncing_balls"
sed -E 's/^TEST\(([A-Za-z0-9]+), /TEST(\1, DISABLED_/' tests/labs/02_bouncing_balls/BallsGradingTests.cpp \
    >"$class/disabled-tests/tests/labs/02_bouncing_balls/BallsGradingTests.cpp"

# The edge rule: a wall test written <= / >= (touching counts as a hit) must fail task 1.
submission touching-wall 1,2,3
sed -i -E 's/center\.(x|y) < radius \|\| center\.(x|y) > /center.\1 <= radius || center.\2 >= /' \
    "$class/touching-wall/$lab/Ball.cpp"
[[ $(grep -c '<= radius ||' "$class/touching-wall/$lab/Ball.cpp") -eq 2 ]]

submission define-test ""
sed -i 's/^#pragma once/&\n#define TEST(suite, name) void suite##name()/' "$class/define-test/$lab/Ball.h"
sed -i '1i #define TEST(suite, name) void suite##name()' "$class/define-test/$lab/BallsLevel.cpp"

./scripts/grade-class.sh "$class" --lab lab02_bouncing_balls --out "$work/grades" "${build_options[@]}"

# expect STUDENT TASKS_WITH_A_MARK: the marks in the gradebook are exactly those.
problems=0
expect() {
    local marked
    marked=$(awk -F, -v student="$1" '$1 == student && $6 == 1 { print $3 }' "$work/grades/grades.csv" | paste -sd, -)
    if [[ $marked != "$2" ]]; then
        echo "check-grading: $1 got marks for tasks '${marked}', expected '$2'" >&2
        problems=$((problems + 1))
    fi
}
for student in solution solution-zip solution-git starter exit-in-constructor exit-in-update fake-ok-lines define-test; do
    case $student in
        solution*) expect "$student" 1,2,3 ;;
        *) expect "$student" "" ;;
    esac
done
expect disabled-tests 1
expect touching-wall 2,3
grep -q 'ignored' "$work/grades/students/disabled-tests.md" &&
    grep -q 'tests/labs/02_bouncing_balls/BallsGradingTests.cpp' "$work/grades/students/disabled-tests.md" ||
    { echo "check-grading: the feedback does not list the ignored test file" >&2; problems=$((problems + 1)); }
grep -q 'touches the test framework' "$work/grades/students/define-test.md" ||
    { echo "check-grading: the feedback does not say why define-test got nothing" >&2; problems=$((problems + 1)); }
python3 -c "import json, sys; d = json.load(open(sys.argv[1])); assert d['score'] == 3 and len(d['tests']) == 3" \
    "$work/grades/students/solution.results.json"
if [[ $problems -gt 0 ]]; then
    echo "check-grading: FAILED ($problems problems; the gradebook: $work/grades/grades.csv)" >&2
    exit 1
fi
echo "check-grading: every faked submission got no marks for the tasks it faked; the solution got all"

# The handout's GitHub Classroom workflow parses as YAML and has one 1-point test per task.
rm -rf "$work/handout"
./scripts/make-handout.sh "$work/handout" >/dev/null
python3 - "$work/handout/.github/workflows/classroom.yml" "$(for lab in $(lab_names); do lab_tasks "$(lab_folder "$lab")"; done | wc -l)" <<'EOF'
import sys
import yaml  # Debian: python3-yaml
workflow = yaml.safe_load(open(sys.argv[1]))
steps = workflow["jobs"]["grade"]["steps"]
graders = [s for s in steps if str(s.get("uses", "")).startswith("classroom-resources/autograding-command-grader")]
reporter = [s for s in steps if str(s.get("uses", "")).startswith("classroom-resources/autograding-grading-reporter")]
assert len(graders) == int(sys.argv[2]), f"{len(graders)} Classroom tests for {sys.argv[2]} tasks"
assert all(g["with"]["max-score"] == 1 and g["with"]["command"] for g in graders)
assert len(reporter) == 1 and reporter[0]["with"]["runners"].split(",") == [g["id"] for g in graders]
for g in graders:
    assert f"{g['id'].upper()}_RESULTS" in reporter[0]["env"], g["id"]
print(f"check-grading: the Classroom workflow parses: {len(graders)} tests of 1 point, one per task")
EOF

# The labs whose tests are proven fair (one mistake costs one task): check-fair-marks.sh
# leaves each of their tasks undone in turn. Add a lab here once its tests pass that check.
fair_labs=(
    lab01_point_in_box
    lab02_bouncing_balls
    lab03_bouncing_squares
    lab04_bullet_through_paper
    lab05_ray_caster
    lab06_rotated_boxes
    lab07_swept_circles
    lab08_many_objects
    lab09_platformer
    lab10_top_down
    lab11_pong
    lab12_broad_phase
    lab13_fast_movers
    lab14_resting_stack
    lab15_world
)
./scripts/check-fair-marks.sh "${fair_labs[@]/#/--lab=}" "${build_options[@]}" "$work/fair-marks"
