#!/usr/bin/env python3
"""Every repository path and every relative link named in README.md and docs/*.md exists.

A link [text](target) is taken from the page's own folder (as GitHub shows it); a path in
backticks that starts with one of the repository's top folders (`framework/...`) is taken
from the repository's root. Placeholders are skipped: a path holding <...>, *, NN, NAME or
an ellipsis stands for many files, and build/ output is made by a build, not kept here.
Prints one line per missing path, exit 1 if any; exit 0 when all exist.
"""
import pathlib
import re
import sys

REPO = pathlib.Path(__file__).resolve().parents[2]
TOP = ("framework/", "labs/", "tests/", "scripts/", "pong/", "slides/", "docs/", "assets/", ".ci/",
       "CMakeLists.txt", "CMakePresets.json", ".clang-format")
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
CODE = re.compile(r"`([^`\n]+)`")
PLACEHOLDER = re.compile(r"[<>*…]|\.\.\.|\bNN|NAME|\$")


def pages():
    yield REPO / "README.md"
    yield from sorted((REPO / "docs").glob("*.md"))


def named_paths(text):
    """(kind, path) for each link target and each repository path in backticks."""
    for target in LINK.findall(text):
        if re.match(r"[a-z]+:", target) or target.startswith("#"):
            continue  # a web address or an anchor on the same page
        yield "link", target.split("#", 1)[0]
    for span in CODE.findall(text):
        for word in span.split():
            word = word.rstrip(".,;:)")
            word = re.sub(r":\d+(-\d+)?$", "", word)  # Ball.h:12 names a line of Ball.h
            if word.startswith(TOP) and not PLACEHOLDER.search(word):
                yield "path", word.split("#", 1)[0]


def main():
    missing = 0
    checked = 0
    for page in pages():
        text = page.read_text(encoding="utf-8")
        for kind, name in named_paths(text):
            base = page.parent if kind == "link" else REPO
            checked += 1
            if not (base / name).exists():
                print(f"{page.relative_to(REPO)}: {kind} {name} does not exist")
                missing += 1
    if checked == 0:
        print("check_paths: no path found in README.md and docs/*.md; is the parser broken?")
        return 1
    print(f"check_paths: {checked} paths and links checked, {missing} missing")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
