#!/usr/bin/env bash
# Checks the class grader (scripts/lab.py grade-class) against the ways a mark could be
# faked, on lab 2: scripts/labtool/tricks.py writes a class of made-up submissions (own
# main(), a GoogleTest listener behind a split #include, a redefined testing:: function,
# atexit/_exit, exit(0) before the tests, fake OK lines, the instructor's Ball.cpp included
# or symlinked, a framework function redefined, a signal handler, a raw system call, a report
# written from a destructor, its own DISABLED_ tests, #define TEST, an output flood, a
# touching-wall mistake) and the honest solution with a testing:: comment and its own
# TEST_SLOW_MOTION macro; each must get exactly the marks it may earn. Then the handout's
# Classroom workflow is checked, and scripts/check-fair-marks.sh runs on every lab.
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
rm -rf "$work/grades"
python3 scripts/lab.py same-exercise # the build's exercise generator follows markers.py
python3 scripts/lab.py tricks make "$work/class"
./scripts/grade-class.sh "$work/class" --lab 02 --out "$work/grades" "${build_options[@]}"
python3 scripts/lab.py tricks check "$work/grades/grades.csv"
python3 scripts/lab.py check class-results "$work/grades/students"
echo "check-grading: every faked submission got no marks for the tasks it faked; the honest ones got all"

# The handout's GitHub Classroom workflow parses as YAML, has one 1-point test per task, and
# every step runs even after a failed one (a lab that does not compile costs that lab only).
rm -rf "$work/handout"
./scripts/make-handout.sh "$work/handout" >/dev/null
python3 scripts/lab.py check classroom-workflow "$work/handout/.github/workflows/classroom.yml"

# The Classroom path on the handout: lab 1 does not compile, lab 2 is solved; the workflow's own
# grading command must still give lab 2 every mark (a lab that does not compile costs that lab only).
classroom=$work/handout
echo "int broken = ;" >>"$classroom/labs/01_point_in_box/PointInBoxLevel.cpp"
for source in $(lab_sources labs/02_bouncing_balls); do
    python3 scripts/lab.py exercise "$source" "$classroom/$source" --solved "$(lab_tasks 02 | paste -sd, -)"
done
(cd "$classroom" && python3 scripts/lab.py grade-class --one . --no-cage --lab 01 --lab 02 --out grades --build build/grading >/dev/null &&
    python3 scripts/lab.py mark grades/grades.csv lab02_bouncing_balls 3 &&
    ! python3 scripts/lab.py mark grades/grades.csv lab01_point_in_box 1) ||
    { echo "check-grading: on the Classroom path a broken lab 1 cost more than lab 1" >&2; exit 1; }
echo "check-grading: Classroom: lab 1 does not compile, lab 2 still earns every task"

# The labs whose tests are proven fair (one mistake costs one task): check-fair-marks.sh
# leaves each of their tasks undone in turn. Add a lab here once its tests pass that check.
fair_labs=(lab01_point_in_box lab02_bouncing_balls lab03_bouncing_squares lab04_bullet_through_paper
    lab05_ray_caster lab06_rotated_boxes lab07_swept_circles lab08_many_objects lab09_platformer
    lab10_top_down lab11_pong lab12_broad_phase lab13_fast_movers lab14_resting_stack lab15_world
    lab16_find_the_bug)
./scripts/check-fair-marks.sh "${fair_labs[@]/#/--lab=}" "${build_options[@]}" "$work/fair-marks"
