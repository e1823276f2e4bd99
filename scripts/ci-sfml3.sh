#!/usr/bin/env bash
# CI: Hitbox against SFML 3 (Debian unstable's 3.1, g++ 16, CMake 4.3), as a new user would
# meet it, and the same behaviour as this machine's SFML 2.
#
#  1. Makes the Debian unstable root if it is missing (scripts/sid-root.sh; kept between runs).
#  2. In it, a new user `student` (with sudo, as on a student's own machine) clones this
#     commit and runs the README's two commands: ./scripts/test.sh, then ./scripts/run.sh.
#  3. Runs Pong headless, draws every lab under Xvfb and runs the broadphase benchmark, on
#     SFML 3 (in the root) and on this machine's SFML 2 (HOST_BUILD), and compares: the same
#     Pong result line, the same screenshots pixel for pixel, the same benchmark pair counts.
#  4. Record and replay across the two: a match recorded on SFML 2 (this machine) is replayed
#     on SFML 3 and the other way round; each replay's final state line must equal, byte for
#     byte, the one of the run that recorded it (a few seconds).
#
# Usage: scripts/ci-sfml3.sh [HOST_BUILD]    (default build/debug, made by ./scripts/test.sh)
# Reproduce by hand: the same command, as root, on Debian 12 with this repository checked out.
set -euo pipefail
cd "$(dirname "$0")/.."
host_build=${1:-build/debug}
root=${HITBOX_SID_ROOT:-/var/cache/hitbox/sid-root}
compare=build/sfml3-compare
rm -rf "$compare" && mkdir -p "$compare/host" "$compare/sid"

echo "ci-sfml3: 1. the Debian unstable root (SFML 3)"
scripts/sid-root.sh create
git bundle create "$compare/hitbox.bundle" HEAD 2>/dev/null

echo "ci-sfml3: 2. a new user clones Hitbox and runs the README's two commands"
scripts/sid-root.sh run bash -euo pipefail -c '
    id student >/dev/null 2>&1 || useradd --create-home --shell /bin/bash student
    echo "student ALL=(ALL) NOPASSWD: ALL" >/etc/sudoers.d/student
    rm -rf /home/student/hitbox
    su student -c "git clone -q /hitbox/'"$compare"'/hitbox.bundle /home/student/hitbox"
    su student -c "cd ~/hitbox && ./scripts/test.sh"
    # No display here: run.sh must say so and stop on its own (a window would never close).
    su student -c "cd ~/hitbox && timeout 1200 ./scripts/run.sh"'

echo "ci-sfml3: 3. the same runs on SFML 3 and on SFML 2"
scripts/sid-root.sh run su student -c "cd ~/hitbox && ./scripts/same-runs.sh build/debug build/same-runs"
cp "$root/home/student/hitbox/build/same-runs/"* "$compare/sid/"
scripts/same-runs.sh "$host_build" "$compare/host"

status=0
# same FILE_A FILE_B MESSAGE: the two files must be equal; otherwise the diff and MESSAGE.
same() { diff "$1" "$2" || { echo "ci-sfml3: $3" >&2; status=1; }; }
same "$compare/host/pong.txt" "$compare/sid/pong.txt" "Pong gave another result on SFML 3 (above: < SFML 2, > SFML 3)"
same "$compare/host/pairs.txt" "$compare/sid/pairs.txt" "the broadphase found other pair counts on SFML 3"
python3 scripts/compare-png.py "$compare/host" "$compare/sid" || status=1

echo "ci-sfml3: 4. a replay recorded on SFML 2 plays the same on SFML 3, and the other way round"
# The root sees this repository as /hitbox (scripts/sid-root.sh).
replay_sid() { scripts/sid-root.sh run su student -c "cd ~/hitbox && env -u DISPLAY build/debug/pong/pong --replay /hitbox/$1 --headless"; }
replay_sid "$compare/host/match.replay" >"$compare/host-replayed-on-sfml3.txt"
env -u DISPLAY -u WAYLAND_DISPLAY "$host_build/pong/pong" --replay "$compare/sid/match.replay" --headless \
    >"$compare/sid-replayed-on-sfml2.txt"
same "$compare/host/replayed.txt" "$compare/host-replayed-on-sfml3.txt" "SFML 2's recorded match ended elsewhere when replayed on SFML 3 (< SFML 2, > SFML 3)"
same "$compare/sid/replayed.txt" "$compare/sid-replayed-on-sfml2.txt" "SFML 3's recorded match ended elsewhere when replayed on SFML 2 (< SFML 3, > SFML 2)"
[[ $status -eq 0 ]] && echo "ci-sfml3: SFML 3 builds, passes every test and behaves as SFML 2"
exit $status
