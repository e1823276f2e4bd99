# shellcheck shell=bash
# lab-tests.sh - small shell helpers shared by the course's bash scripts (paths, the lab list).
# Source it; it is not a program:   source "$(dirname "$0")/lab-tests.sh"
# Running tests is not here: every script runs them through scripts/lab.py (one engine).

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
