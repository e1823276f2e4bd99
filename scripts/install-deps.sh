#!/usr/bin/env bash
# Installs what Hitbox needs on Debian/Ubuntu, skipping what is already there.
# Safe to run any number of times. Other systems: see docs/windows-macos.md.
# Prints a few progress lines; apt's full output goes to a log file (named on failure).
set -euo pipefail

packages=(g++ make cmake pkg-config libsfml-dev libgtest-dev libgmock-dev libbenchmark-dev
          libbox2d-dev xvfb xauth clang-format ccache
          python3-pil python3-yaml) # pictures compared (compare-png.py); the handout's workflow

missing=()
for package in "${packages[@]}"; do
    # The status read whole, then matched: `dpkg-query | grep -q` under pipefail can fail
    # when grep exits first (SIGPIPE), calling an installed package missing.
    status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
    [[ $status == *"install ok installed"* ]] || missing+=("$package")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

command="apt-get install -y --no-install-recommends ${missing[*]}"
if ! command -v apt-get >/dev/null; then
    echo "install-deps: no apt-get here; install these yourself: ${missing[*]}" >&2
    exit 1
fi
# sudo drops most of the environment: pass DEBIAN_FRONTEND through `env` so nothing prompts.
as_root=(env DEBIAN_FRONTEND=noninteractive)
if [[ $(id -u) -ne 0 ]]; then
    if ! command -v sudo >/dev/null; then
        echo "install-deps: missing ${missing[*]}; there is no sudo here, so ask an administrator, or as root run: $command" >&2
        exit 1
    fi
    as_root=(sudo env DEBIAN_FRONTEND=noninteractive)
fi
log=$(mktemp "${TMPDIR:-/tmp}/hitbox-install-deps.XXXXXX.log")
echo "install-deps: installing ${missing[*]} (full log: $log)"
echo "install-deps: updating the package lists..."
if ! "${as_root[@]}" apt-get update >"$log" 2>&1; then
    if [[ $(id -u) -ne 0 ]] && grep -qiE "not in the sudoers|may not run sudo|password is required|incorrect password" "$log"; then
        echo "install-deps: sudo refused ($(grep -iE -m1 "sudoers|may not|password" "$log")). Ask an administrator to run: $command" >&2
    else
        echo "install-deps: apt-get update failed; see $log (last line: $(tail -n 1 "$log"))" >&2
    fi
    exit 1
fi
echo "install-deps: installing ${#missing[@]} packages (this can take a few minutes)..."
if ! "${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" >>"$log" 2>&1; then
    echo "install-deps: apt-get install failed; see $log (last line: $(tail -n 1 "$log"))" >&2
    exit 1
fi
echo "install-deps: done"
