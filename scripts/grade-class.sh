#!/usr/bin/env bash
# Grades a whole class against this (the instructor's) tree: one folder, .zip or git
# repository per student in SUBMISSIONS_DIR; the student's name is the entry's name.
#
# Usage: scripts/grade-class.sh SUBMISSIONS_DIR [--lab NAME]... [--out DIR] [--jobs N] [--build DIR]
#   --lab NAME  grade only this lab (repeat for more; default every lab)
#   --out DIR   where the results go (default grades/)
#   --jobs N    submissions graded at once (default: the machine's cores)
#   --build DIR the instructor's build (default build/grading; kept between runs)
#
# The engine is scripts/lab.py grade-class (scripts/labtool/classgrade.py says what it trusts):
# student code is built and run caged (bubblewrap), under the limits of scripts/labtool/limits.py.
# Writes DIR/grades.csv (student, lab, task, tests passed, tests total, mark, reason; totals)
# and per student DIR/students/<student>.md, .junit.xml and .results.json (Gradescope).
set -euo pipefail
if [[ $# -lt 1 || $1 == -h || $1 == --help ]]; then
    sed -n '4,10p' "$0" | sed 's/^# \{0,1\}//' >&2
    exit 2
fi
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(cd "$(dirname "$0")/../.." && pwd)}
exec python3 "$(dirname "$0")/lab.py" grade-class "$@"
