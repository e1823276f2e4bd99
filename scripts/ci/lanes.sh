# Sourced by .ci/run. After stage 1, CI's stages run in lanes side by side: while one lane
# waits (tests one at a time, wine, Xvfb, a download) the others use the two cores.
# A lane is a shell function; its output goes to build/ci/NAME.log and is printed whole when
# the lane ends, so no two lanes' lines are mixed. A failed lane fails CI; when CI stops early,
# the lanes still running are stopped and what they printed so far is shown.
declare -A lane_pids=()
stage() { echo "== [${SECONDS}s] $*"; }
# lane NAME FUNCTION: runs FUNCTION in the background (set -e holds inside it).
lane() {
    mkdir -p build/ci
    set -m # its own process group, so stop_lanes can end everything it started
    (set -euo pipefail; "$2") >"build/ci/$1.log" 2>&1 &
    lane_pids[$1]=$!
    set +m
    stage "lane '$1' started (output: build/ci/$1.log, printed when it ends)"
}
# join_lanes: waits for every lane in turn and prints its output; fails if one failed.
join_lanes() {
    local name status=0
    for name in $(printf '%s\n' "${!lane_pids[@]}" | sort); do
        if wait "${lane_pids[$name]}"; then
            stage "lane '$name' passed; its output:"
        else
            stage "lane '$name' FAILED; its output:"
            status=1
        fi
        unset "lane_pids[$name]"
        cat "build/ci/$name.log"
    done
    return $status
}
stop_lanes() {
    local name
    for name in "${!lane_pids[@]}"; do
        kill -- "-${lane_pids[$name]}" 2>/dev/null || true
        echo "== lane '$name' stopped because CI failed elsewhere; its output so far:"
        cat "build/ci/$name.log"
    done
}
trap stop_lanes EXIT
