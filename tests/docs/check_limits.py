#!/usr/bin/env python3
"""Every grading limit the pages quote agrees with its one home, scripts/labtool/limits.py.

A page quotes a limit with its name right after the value: "5 s (`TEST_SECONDS`)",
"1 GiB (`TEST_MEMORY`)", "64 processes (`TEST_PROCESSES`)". The value must be the constant's,
shown the way the grader shows it (seconds as "N s", bytes by limits.megabytes), and the name
must be one of limits.py's. Pages: README.md and docs/*.md.
Prints one line per quote that disagrees, exit 1 if any (or if no page quotes a limit).
Usage: check_limits.py [ROOT]   (ROOT: the repository, default: this file's)
"""
import importlib.util
import pathlib
import re
import sys

QUOTE = re.compile(r"(\d[\d,.]*(?: [A-Za-z]+)?) \(`([A-Z][A-Z_]*)`\)")


def load_limits(root):
    spec = importlib.util.spec_from_file_location("limits", root / "scripts" / "labtool" / "limits.py")
    limits = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(limits)
    return limits


def shown(limits, name):
    """How the grader shows the limit called NAME: '5 s', '1 GiB', '64 processes'."""
    value = getattr(limits, name)
    if name.endswith("SECONDS"):
        return f"{value} s"
    if name.endswith(("MEMORY", "BYTES")):
        return limits.megabytes(value)
    return f"{value} {name.split('_')[-1].lower()}"


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
    limits = load_limits(root)
    quoted = wrong = 0
    for page in [root / "README.md", *sorted((root / "docs").glob("*.md"))]:
        text = " ".join(page.read_text(encoding="utf-8").split())
        for value, name in QUOTE.findall(text):
            quoted += 1
            if not isinstance(getattr(limits, name, None), int):
                wrong += 1
                print(f"{page.relative_to(root)}: {name} is not a limit in scripts/labtool/limits.py")
            elif value != shown(limits, name):
                wrong += 1
                print(f"{page.relative_to(root)}: '{value} (`{name}`)' but limits.py says {shown(limits, name)}")
    if quoted == 0:
        print("check_limits: no page quotes a limit as '5 s (`TEST_SECONDS`)'; is the parser broken?")
        return 1
    print(f"check_limits: {quoted} quoted limits checked, {wrong} disagree with limits.py")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
