#!/usr/bin/env bash
# check-sheet-hints.sh [--sfml2-only] [--labs DIR] - every code hint in every lab sheet
# compiles, on this machine's SFML 2 and on SFML 3 (the Debian unstable root,
# scripts/sid-root.sh), so a student on either gets no compiler error from the sheet.
#
# scripts/sheet_hints.py writes each sheet's hints as lambdas in a small file, with the names
# they use from tests/sheet-hints/<lab>.h; each file is compiled with -fsyntax-only (nothing
# is linked), warnings as errors; an error names the sheet's line (#line). About 20 s on
# each SFML (CI stage 1b).
# --sfml2-only: skip the SFML 3 root (a machine without it). --labs DIR: sheets from DIR
# instead of labs/ (the lab's code still comes from labs/; tests/sheets-hint-test.sh plants
# a hint that only compiles on SFML 2 this way).
set -euo pipefail
cd "$(dirname "$0")/.."
labs=labs
sfml3=true
while [[ $# -gt 0 ]]; do
    case $1 in
    --sfml2-only) sfml3=false; shift ;;
    --labs) labs=$2; shift 2 ;;
    *) echo "usage: scripts/check-sheet-hints.sh [--sfml2-only] [--labs DIR]" >&2; exit 2 ;;
    esac
done
out=build/sheet-hints
rm -rf "$out"
python3 scripts/sheet_hints.py --labs "$labs" --contexts tests/sheet-hints --out "$out"

# compile_all ROOT_PREFIX: compiles every generated file; the compiler runs where it is called.
compile_all='
    status=0
    while read -r lab; do
        [[ -n $lab ]] || continue
        if ! c++ -std=c++17 -fsyntax-only -Wall -Wextra -Wpedantic -Werror \
            -Iframework -Ilabs/"$lab" -Itests/sheet-hints "$0/$lab.cpp" 2>"$0/$lab.log"; then
            echo "FAIL $1: a hint in labs/$lab/README.md does not compile:" >&2
            grep -m 5 -E "error" "$0/$lab.log" >&2 || cat "$0/$lab.log" >&2
            status=1
        fi
    done <"$0/labs.txt"
    exit $status'

status=0
echo "check-sheet-hints: SFML 2"
bash -c "$compile_all" "$out" "SFML 2" || status=1
if $sfml3; then
    echo "check-sheet-hints: SFML 3 (Debian unstable root)"
    scripts/sid-root.sh run bash -c "$compile_all" "$out" "SFML 3" || status=1
fi
[[ $status -eq 0 ]] && echo "check-sheet-hints: every sheet's code hints compile"
exit $status
