#!/usr/bin/env bash
# Builds and tests Hitbox against SFML 3 on a Debian 12 machine, whose own SFML is 2.5.
#
# Debian unstable ("sid") ships libsfml-dev 3.x, which replaces 2.x, so SFML 3 lives in a
# separate Debian root made with debootstrap. The root is made once and kept (it takes a few
# minutes); later calls reuse it.
#
# Usage: scripts/sid-root.sh create          make the root if it is missing (needs root)
#        scripts/sid-root.sh run COMMAND...  run COMMAND inside the root, in a copy of
#                                            this checkout at /hitbox
# HITBOX_SID_ROOT chooses where the root lives (default /var/cache/hitbox/sid-root).
set -euo pipefail

root=${HITBOX_SID_ROOT:-/var/cache/hitbox/sid-root}
here=$(cd "$(dirname "$0")/.." && pwd)
# What a new student installs inside the root (install-deps.sh adds the rest itself).
base_packages=(git ca-certificates sudo)

log() { echo "sid-root: $*"; }

mirror() {
    # The same mirror this machine's apt uses.
    local uri
    uri=$(grep -rhoE '^(URIs:|deb) *https?://[^ ]+/debian/?' /etc/apt/sources.list /etc/apt/sources.list.d/ 2>/dev/null |
          head -n 1 | grep -oE 'https?://[^ ]+' || true)
    echo "${uri:-http://deb.debian.org/debian}"
}

create() {
    if [[ -f $root/.hitbox-ready ]]; then
        return 0
    fi
    [[ $(id -u) -eq 0 ]] || { echo "sid-root: making the root needs root (run with sudo)" >&2; exit 1; }
    command -v debootstrap >/dev/null || {
        log "installing debootstrap"
        apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null
    }
    rm -rf "$root"
    mkdir -p "$root"
    log "debootstrap sid into $root (a few minutes; log in $root.log)"
    debootstrap --variant=minbase sid "$root" "$(mirror)" >"$root.log" 2>&1 ||
        { tail -n 20 "$root.log" >&2; exit 1; }
    # This mirror's sid Release file is past its valid-until date.
    echo 'Acquire::Check-Valid-Until "false";' >"$root/etc/apt/apt.conf.d/99hitbox-no-valid-until"
    cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
    in_root apt-get -qq update
    in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        "${base_packages[@]}" >>"$root.log" 2>&1
    touch "$root/.hitbox-ready"
    log "ready"
}

mount_all() {
    local fs
    for fs in proc sys dev dev/pts; do
        mountpoint -q "$root/$fs" || mount --bind "/$fs" "$root/$fs"
    done
}

unmount_all() {
    local fs
    for fs in dev/pts dev sys proc; do
        mountpoint -q "$root/$fs" && umount -l "$root/$fs" || true
    done
}

in_root() {
    mount_all
    local status=0
    chroot "$root" "$@" || status=$?
    return $status
}

run() {
    create
    # A fresh copy of the checkout (tracked and untracked files, no build folders) at /hitbox,
    # so the host's build/ never mixes with the root's.
    rm -rf "$root/hitbox"
    mkdir -p "$root/hitbox"
    (cd "$here" && git ls-files -co --exclude-standard -z | tar --null -T - -cf -) | tar -xf - -C "$root/hitbox"
    if [[ -d $here/../shared ]]; then
        rm -rf "$root/shared" && cp -r "$here/../shared" "$root/shared"
    fi
    trap unmount_all EXIT
    in_root env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        LANG=C.UTF-8 CI="${CI:-}" bash -c 'cd /hitbox && "$@"' bash "$@"
}

case ${1:-} in
create) create ;;
run) shift; run "$@" ;;
*) echo "usage: scripts/sid-root.sh create | run COMMAND..." >&2; exit 2 ;;
esac
