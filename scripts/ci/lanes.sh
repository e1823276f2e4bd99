# Sourced by .ci/run. After stage 1, CI's stages run in lanes side by side: while one lane
# waits (tests one at a time, wine, Xvfb, a download) the others use the two cores.
# A lane is a shell function; its output goes to build/ci/NAME.log and is printed whole when
# the lane ends, so no two lanes' lines are mixed. A failed lane fails CI; when CI stops early,
# the lanes still running are stopped and what they printed so far is shown. Whatever failed,
# CI's last lines name the stage and repeat the end of its output (main lane: build/ci/main.log).
# A stage line gives the CPU seconds (children's user + system) of the lane's stage before it.
declare -A lane_pids=()
cpu_mark=0 lanes_joined=
stage() { # `times` must run in the lane's own shell, not in a $(...): its lines go via a file
    local file="build/ci/.times-$BASHPID" now
    mkdir -p build/ci && times >"$file"
    now=$(awk 'NR == 2 { split($1, u, "m"); split($2, s, "m"); printf "%d", u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$file")
    echo "== [${SECONDS}s; the stage before: $((now - cpu_mark)) CPU s] $*"
    cpu_mark=$now
}
failure_summary() { # WHAT LOG [SAVED_AS]: LOG's last stage line and last 60 lines
    echo "== CI FAILED in $1, stage: $(grep '^== \[' "$2" | tail -n 1)"
    echo "== the last 60 lines of $1's output:"
    tail -n 60 "$2"
    echo "== CI FAILED in $1 (the lines above; its whole output: ${3:-$2})"
}
lane() { # NAME FUNCTION: runs FUNCTION in the background (set -e holds inside it)
    mkdir -p build/ci
    set -m # its own process group, so stop_lanes can end everything it started
    (set -euo pipefail; cpu_mark=0; "$2") >"build/ci/$1.log" 2>&1 &
    lane_pids[$1]=$!
    set +m
    stage "lane '$1' started (output: build/ci/$1.log, printed when it ends)"
}
join_lanes() { # waits for every lane in turn and prints its output; fails if one failed
    local name failed=()
    for name in $(printf '%s\n' "${!lane_pids[@]}" | sort); do
        if wait "${lane_pids[$name]}"; then
            stage "lane '$name' passed; its output:"
        else
            stage "lane '$name' FAILED; its output:"
            failed+=("$name")
        fi
        unset "lane_pids[$name]"
        cat "build/ci/$name.log"
    done
    for name in "${failed[@]}"; do failure_summary "lane '$name'" "build/ci/$name.log"; done
    lanes_joined=yes
    [[ ${#failed[@]} -eq 0 ]]
}
stop_lanes() { # on exit, when the main lane failed: the others stopped and shown, then its end
    local status=$? name saved
    [[ $status -eq 0 ]] && return
    saved=$(mktemp)
    cp build/ci/main.log "$saved" 2>/dev/null || true
    for name in "${!lane_pids[@]}"; do
        kill -- "-${lane_pids[$name]}" 2>/dev/null || true
        echo "== lane '$name' stopped because CI failed elsewhere; its output so far:"
        cat "build/ci/$name.log"
    done
    [[ -n $lanes_joined ]] || failure_summary "the main lane (exit $status)" "$saved" build/ci/main.log
    rm -f "$saved"
}
trap stop_lanes EXIT
