#!/usr/bin/env bash
# Grades a whole class against this (the instructor's) tree: one folder, .zip or git
# repository per student in SUBMISSIONS_DIR; the student's name is the entry's name.
#
# Usage: scripts/grade-class.sh SUBMISSIONS_DIR [--lab NAME]... [--out DIR] [--jobs N]
#   --lab NAME  grade only this lab (repeat for more; default every lab)
#   --out DIR   where the results go (default grades/)
#   --jobs N    submissions graded at once (default: the machine's cores)
#   --build DIR the instructor's build (default build/grading; kept between runs)
#
# Builds the framework and the instructor's tests once; for each submission only the files
# a student edits (the lab sources with a "// BEGIN TASK n:" marker) are taken and compiled.
# Writes DIR/grades.csv (student, lab, task, tests passed, tests total, mark) and, per
# student, DIR/students/<student>.md (feedback), .junit.xml and .results.json (Gradescope).
# How a result is decided, and what the grader does not defend against: README.md,
# "Grading a class", and scripts/grading/grader.py.
set -euo pipefail
if [[ $# -lt 1 || $1 == -h || $1 == --help ]]; then
    sed -n '4,10p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
fi
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(cd "$(dirname "$0")/../.." && pwd)}
exec python3 "$(dirname "$0")/grading/grader.py" --class "$@"
