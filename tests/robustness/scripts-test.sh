#!/usr/bin/env bash
# The instructor's scripts (issue 25, items 4, 10 and 27): a write error ends make-handout.sh
# with one line and nothing half-written; a relative path means the caller's folder; no
# `... | grep -q` pipeline that SIGPIPE can fail at random under pipefail. About 3 s.
# Usage: scripts-test.sh SOURCE_DIR
set -uo pipefail
source_dir=$(cd "$1" && pwd)
work=$(mktemp -d)
name="handout-path-test-$$"
trap 'rm -rf "$work" "${source_dir:?}/$name"' EXIT
failures=0
fail() { failures=$((failures + 1)); echo "FAIL: $*" >&2; }

# Item 4: a disk that takes no more than 16 KiB per file (SIGXFSZ ignored, so writes fail).
(cd "$work" && trap '' XFSZ && ulimit -f 16 &&
    "$source_dir/scripts/make-handout.sh" "$work/full") >"$work/out" 2>"$work/err"
code=$?
last=$(tail -n 1 "$work/err")
if [[ $code -ne 1 || $last != "make-handout: FAILED (see the line above: a write error? is the disk full?); nothing was left in $work/full" || -e $work/full ]]; then
    fail "make-handout.sh on a full disk: exit $code, last line '$last', left behind: $(ls "$work/full" 2>/dev/null | head -n 3 | paste -sd' ')"
fi

# Item 10: OUT_DIR relative to the caller's folder (there it exists and is not empty, so the
# script refuses at once; before, it looked in the repository and wrote the handout there).
mkdir -p "$work/$name"
touch "$work/$name/mine"
(cd "$work" && "$source_dir/scripts/make-handout.sh" "$name") >"$work/out" 2>"$work/err"
code=$?
if [[ $code -ne 2 || $(cat "$work/err") != "make-handout: $work/$name exists and is not empty; give a new folder (or delete it first)." || -e $source_dir/$name ]]; then
    fail "make-handout.sh $name from $work: exit $code, $(head -n 2 "$work/err")"
fi

# Item 27: no producer piped into `grep -q` in the scripts (grep exits at the first match,
# the producer dies of SIGPIPE, pipefail fails the test).
# (grep -r: a glob that matches no file would make grep fail and the check pass unseen.)
if found=$(grep -rnE --include='*.sh' '\|[[:space:]]*grep[[:space:]]+-[A-Za-z]*q' "$source_dir/scripts" |
    grep -vE '^[^:]*:[0-9]+:[[:space:]]*#'); then
    fail "a pipe into grep -q (use is_one_of from scripts/lab-tests.sh, or match a variable):"
    echo "$found" >&2
fi
# is_one_of answers for a list far longer than a pipe's buffer, every time.
source "$source_dir/scripts/lab-tests.sh"
mapfile -t many < <(seq 1 20000)
for _ in 1 2 3; do
    is_one_of 1 "${many[@]}" || fail "is_one_of missed the first of 20000"
    ! is_one_of 0 "${many[@]}" || fail "is_one_of found a word that is not there"
done
echo "scripts: $failures failed"
[[ $failures -eq 0 ]]
