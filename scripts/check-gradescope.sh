#!/usr/bin/env bash
# Tries the Gradescope autograder the way Gradescope runs it, in a fresh Debian root laid
# out like Gradescope's image: the zip unpacked in /autograder/source, setup.sh run there
# as root, the submission in /autograder/submission, /autograder/run_autograder run, and
# /autograder/results/results.json checked (the solution gets every task, the starter none).
# Needs root and a network mirror; not part of CI (it installs packages: minutes).
# Usage: scripts/check-gradescope.sh ROOT [LAB]
#   ROOT  an empty folder for the Debian root, or one made earlier by
#         debootstrap --variant=minbase bookworm ROOT http://deb.debian.org/debian
#   LAB   default lab02_bouncing_balls
set -euo pipefail
HITBOX_CALLER=$PWD # relative paths on the command line are the caller's (from_caller)
cd "$(dirname "$0")/.."
source scripts/lab-tests.sh
root=$(realpath -m "$(from_caller "${1:?usage: $0 ROOT [LAB]}")")
lab=${2:-lab02_bouncing_balls}
folder=$(lab_folder "$lab")
if [[ ! -x $root/bin/bash ]]; then
    mirror=$(sed -n 's/^URIs: //p' /etc/apt/sources.list.d/debian.sources | head -n 1)
    debootstrap --variant=minbase bookworm "$root" "${mirror:-http://deb.debian.org/debian}"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"

# grade SOLVED_TASKS EXPECTED_SCORE: one Gradescope run on a submission of the lab's student
# files (uploaded flat, as students upload files to Gradescope).
first=yes
grade() {
    rm -rf "$root/autograder/submission" "$root/autograder/results"
    mkdir -p "$root/autograder/submission" "$root/autograder/results"
    while IFS= read -r source; do
        python3 scripts/lab.py exercise "$source" "$root/autograder/submission/$(basename "$source")" --solved "$1"
    done < <(lab_sources "$folder")
    local inside='/autograder/run_autograder'
    if [[ $first == yes ]]; then
        # Gradescope's image build: the zip in /autograder/source, setup.sh run from there.
        rm -rf "$root/autograder/source" "$root/autograder/build"
        mkdir -p "$root/autograder/source"
        ./scripts/make-gradescope.sh "$lab" "$root/autograder/autograder.zip"
        (cd "$root/autograder/source" && unzip -q ../autograder.zip)
        cp "$root/autograder/source/run_autograder" "$root/autograder/run_autograder"
        inside="cd /autograder/source && bash ./setup.sh && $inside"
        first=no
    fi
    unshare --mount --propagation private bash -c '
        set -e
        for fs in proc sys dev dev/pts; do mount --bind "/$fs" "$0/$fs"; done
        chroot "$0" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
            bash -c "$1"' "$root" "$inside"
    python3 scripts/lab.py check gradescope-results "$root/autograder/results/results.json" "$2"
}
tasks=$(lab_tasks "$folder" | paste -sd, -)
grade "$tasks" "$(lab_tasks "$folder" | wc -l)"
grade "" 0
echo "check-gradescope: the autograder installs, builds and grades $lab in a fresh Debian root"
