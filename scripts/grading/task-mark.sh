#!/usr/bin/env bash
# Exits 0 when the gradebook gives LAB's TASK its mark: one GitHub Classroom test per task.
# Usage: scripts/grading/task-mark.sh GRADES_CSV LAB TASK
set -euo pipefail
awk -F, -v lab="$2" -v task="$3" '$2 == lab && $3 == task { print "task " task ": " $4 "/" $5 " tests passed"; ok = ($6 == 1) }
    END { exit !ok }' "$1"
