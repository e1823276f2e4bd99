#!/usr/bin/env bash
# The student's self-check, kept for old habits: the engine is scripts/lab.py, which also runs
# on Windows without bash:   python3 scripts/lab.py grade 02      (or --all; --help for more)
# Usage: scripts/grade.sh [--lab NAME] [--build DIR] [--exercise]   (every lab without --lab)
set -euo pipefail
arguments=()
labs=()
while [[ $# -gt 0 ]]; do
    case $1 in
        --lab) [[ $# -ge 2 ]] || { echo "usage: $0 [--lab NAME] [--build DIR] [--exercise]" >&2; exit 2; }
            labs+=("$2"); shift 2 ;;
        --build) [[ $# -ge 2 ]] || { echo "usage: $0 [--lab NAME] [--build DIR] [--exercise]" >&2; exit 2; }
            arguments+=(--build "$2"); shift 2 ;;
        *) arguments+=("$1"); shift ;;
    esac
done
[[ ${#labs[@]} -gt 0 ]] || arguments+=(--all)
exec python3 "$(dirname "$0")/lab.py" grade "${labs[@]}" "${arguments[@]}"
