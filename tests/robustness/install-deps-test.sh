#!/usr/bin/env bash
# scripts/install-deps.sh as a normal user (issue 19, item 5), with apt-get, sudo and id
# replaced by stand-ins on PATH: no sudo, a sudo that refuses, and a sudo that works.
# Usage: install-deps-test.sh SOURCE_DIR
set -uo pipefail
script="$1/scripts/install-deps.sh"
work=$(mktemp -d) && trap 'rm -rf "$work"' EXIT
failures=0
fail() { failures=$((failures + 1)); echo "FAIL: $*" >&2; }

mkdir "$work/bin"
for tool in bash env grep mktemp tail cat; do ln -s "$(command -v "$tool")" "$work/bin/$tool"; done
# stub NAME BODY: a stand-in command on PATH.
stub() { printf '#!/bin/bash\n%s\n' "$2" >"$work/bin/$1" && chmod +x "$work/bin/$1"; }
stub id 'echo 1000'
stub dpkg-query 'exit 1'
# apt-get: says what DEBIAN_FRONTEND it saw, then talks as much as dpkg does.
cat >"$work/bin/apt-get" <<STUB
#!/bin/bash
echo "\${DEBIAN_FRONTEND:-unset}" >"$work/frontend"
for line in \$(seq 600); do echo "Unpacking package \$line ..."; done
STUB
ln -s "$(command -v seq)" "$work/bin/seq"
chmod +x "$work/bin/"*

run() { env -i PATH="$work/bin" TMPDIR="$work" HOME="$work" "$work/bin/bash" "$script" >"$work/out" 2>"$work/err"; }

# 1. No sudo at all: one line saying what to run instead.
run
code=$?
[[ $code -eq 1 ]] || fail "no sudo: exit $code, expected 1"
[[ $(wc -l <"$work/err") -eq 1 ]] && grep -q "there is no sudo here, so ask an administrator, or as root run: apt-get install -y --no-install-recommends g++" "$work/err" ||
    fail "no sudo: expected one line naming the command, got: $(cat "$work/err")"

# 2. sudo refuses (not in the sudoers file).
stub sudo 'echo "someone is not in the sudoers file." >&2; exit 1'
run
code=$?
[[ $code -eq 1 ]] || fail "refused: exit $code, expected 1"
grep -q "^install-deps: sudo refused (someone is not in the sudoers file.). Ask an administrator to run: apt-get install" "$work/err" ||
    fail "refused: expected the sudo message and the command, got: $(cat "$work/err")"
[[ $(wc -l <"$work/err") -eq 1 ]] || fail "refused: more than one line on stderr"

# 3. sudo works: DEBIAN_FRONTEND reaches apt-get, a few lines are shown, the rest logged.
stub sudo 'exec "$@"'
run
code=$?
[[ $code -eq 0 ]] || fail "through sudo: exit $code: $(cat "$work/err")"
[[ $(cat "$work/frontend" 2>/dev/null) == noninteractive ]] || fail "through sudo: apt-get saw DEBIAN_FRONTEND=$(cat "$work/frontend" 2>/dev/null)"
lines=$(cat "$work/out" "$work/err" | wc -l)
[[ $lines -le 5 ]] || fail "through sudo: $lines lines printed, expected a few"
log=$(ls -t "$work"/hitbox-install-deps.*.log 2>/dev/null | head -n 1)
[[ -n $log && $(grep -c Unpacking "$log") -eq 1200 ]] || fail "through sudo: the log does not hold apt's full output"

echo "install-deps: $failures failed"
[[ $failures -eq 0 ]]
