#!/usr/bin/env bash
# Builds and tests Hitbox against SFML 3 on a Debian 12 machine, whose own SFML is 2.5.
# Debian unstable ("sid") ships libsfml-dev 3.x, which replaces 2.x, so SFML 3 lives in a
# separate Debian root made with debootstrap, once (a few minutes), and kept.
#
# Usage: scripts/sid-root.sh create          make the root if it is missing (needs root)
#        scripts/sid-root.sh run COMMAND...  run COMMAND inside the root, in this
#                                            checkout (mounted at /hitbox)
# HITBOX_SID_ROOT chooses where the root lives (default /var/cache/hitbox/sid-root).
set -euo pipefail
root=${HITBOX_SID_ROOT:-/var/cache/hitbox/sid-root}
here=$(cd "$(dirname "$0")/.." && pwd)
base_packages=(git ca-certificates sudo) # what a new student installs (install-deps.sh adds the rest)
log() { echo "sid-root: $*"; }

create() {
    [[ ! -f $root/.hitbox-ready ]] || return 0
    [[ $(id -u) -eq 0 ]] || { echo "sid-root: making the root needs root (run with sudo)" >&2; exit 1; }
    command -v debootstrap >/dev/null || {
        log "installing debootstrap"
        apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null
    }
    # The same mirror this machine's apt uses.
    mirror=$(grep -rhoE '^(URIs:|deb) *https?://[^ ]+/debian/?' /etc/apt/sources.list /etc/apt/sources.list.d/ \
        2>/dev/null | head -n 1 | grep -oE 'https?://[^ ]+' || true)
    rm -rf "$root" && mkdir -p "$root"
    log "debootstrap sid into $root (a few minutes; log in $root.log)"
    debootstrap --variant=minbase sid "$root" "${mirror:-http://deb.debian.org/debian}" >"$root.log" 2>&1 ||
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

in_root() {
    # A private mount namespace: the bind mounts vanish with the command, so several runs
    # (and a crashed one) never leave mounts behind or unmount each other's.
    unshare --mount --propagation private bash -c '
        root=$1; shift
        for fs in proc sys dev dev/pts; do mount --bind "/$fs" "$root/$fs"; done
        if [[ -n ${HITBOX_SID_CHECKOUT:-} ]]; then
            mkdir -p "$root/hitbox" && mount --bind "$HITBOX_SID_CHECKOUT" "$root/hitbox"
        fi
        exec chroot "$root" "$@"' bash "$root" "$@"
}

case ${1:-} in
create) create ;;
run) # This checkout appears inside the root at /hitbox (the same files, not a copy).
    shift && create
    HITBOX_SID_CHECKOUT=$here in_root env -i HOME=/root LANG=C.UTF-8 CI="${CI:-}" \
        PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin bash -c 'cd /hitbox && "$@"' bash "$@" ;;
*) echo "usage: scripts/sid-root.sh create | run COMMAND..." >&2; exit 2 ;;
esac
