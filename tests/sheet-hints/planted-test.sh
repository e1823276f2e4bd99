#!/usr/bin/env bash
# planted-test.sh - check-sheet-hints.sh fails on a hint that only compiles on SFML 2.
# Lab 11's sheet with task 1's hint written against sf::FloatRect's SFML 2 members
# (`court.top - getCollisionBox().top`: SFML 3's FloatRect has position and size, no top):
# SFML 2 must pass, SFML 3 must fail naming the sheet's line. --sfml2-only: only the first.
set -euo pipefail
cd "$(dirname "$0")/../.."
work=build/sheet-hints-planted
rm -rf "$work" && mkdir -p "$work/11_pong"
sed 's/`court.top - box.top`/`court.top - getCollisionBox().top`/' labs/11_pong/README.md >"$work/11_pong/README.md"
grep -q 'getCollisionBox().top' "$work/11_pong/README.md" || { echo "FAIL: could not plant the hint" >&2; exit 1; }
scripts/check-sheet-hints.sh --sfml2-only --labs "$work" >/dev/null ||
    { echo "FAIL: the planted hint should compile on SFML 2" >&2; exit 1; }
if [[ ${1:-} == --sfml2-only ]]; then echo "planted-test: SFML 2 passes (SFML 3 not tried)"; exit 0; fi
status=0
output=$(scripts/check-sheet-hints.sh --labs "$work" 2>&1) || status=$?
if [[ $status -ne 0 && $output == *"FAIL SFML 3"*"$work/11_pong/README.md:59"* ]]; then
    echo "planted-test: the SFML 2-only hint fails on SFML 3, naming its line"
else
    echo "FAIL: expected SFML 3 to fail on $work/11_pong/README.md:59, got (exit $status): $output" >&2
    exit 1
fi
