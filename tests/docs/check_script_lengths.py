#!/usr/bin/env python3
"""No shell script in the repository is over 60 lines (issue 29: a bash script is a thin
caller; logic that is a table or a loop is Python, where a reader can follow it).

Checks every tracked `*.sh` file and the extension-less `.ci/run` (git ls-files; without git,
the same files found by walking the tree, build folders and node_modules left out). Prints one
line per script that is too long, with its length, and exits 1 if any; exit 0 when none is.
Usage: check_script_lengths.py [ROOT]   (ROOT: the repository, default: this file's)
"""
import os
import pathlib
import subprocess
import sys

MAX_LINES = 60
EXTENSIONLESS = (".ci/run",)  # shell scripts without the .sh ending
SKIPPED = ("build", "node_modules", ".git", "dist")  # made by a build or a tool, not kept here


def scripts(root):
    """The repository's shell scripts, as paths relative to ROOT."""
    try:
        listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--", "*.sh", *EXTENSIONLESS],
                                capture_output=True, check=True).stdout
        return sorted(name for name in os.fsdecode(listed).split("\0") if name)
    except (OSError, subprocess.CalledProcessError):
        found = [str(path.relative_to(root)) for path in root.rglob("*.sh")
                 if not set(path.relative_to(root).parts) & set(SKIPPED)]
        return sorted(found + [name for name in EXTENSIONLESS if (root / name).is_file()])


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
    too_long, names = 0, scripts(root)
    for name in names:
        path = root / name
        if not path.is_file():
            continue  # deleted in the working tree, not yet in the index
        with open(path, "rb") as script:
            lines = script.read().count(b"\n")
        if lines > MAX_LINES:
            too_long += 1
            print(f"{name}: {lines} lines; a shell script may have at most {MAX_LINES} (move its steps "
                  "into scripts of their own, or its table or loop into Python)")
    print(f"shell scripts: {len(names)} checked, {too_long} over {MAX_LINES} lines")
    return 1 if too_long else 0


if __name__ == "__main__":
    sys.exit(main())
