#!/usr/bin/env python3
"""Every repository path, relative link and located name in the project's pages exists.

The pages: README.md, docs/*.md, every lab sheet (labs/*/README.md) and pong/README.md.
A link [text](target) is taken from the page's own folder (as GitHub shows it). A path in backticks is taken from the repository's root when it starts with a top
folder (`framework/...`), from framework/hitbox/ when it starts with one of Hitbox's layers
(`objects/World.cpp`, as the docs name a layer's file), and from framework/ when it starts
with `hitbox/` or `compat/` (an include path). A name said to be in a file (`stepsPerSecond`
in `framework/hitbox/app/Loop.h`, also `a`, `b` and `c` in `...`) must occur in that file.
Placeholders are skipped: a path holding <...>, *, NN, NAME or an ellipsis stands for many
files, and build/ output is made by a build, not kept here.
Prints one line per missing path or name, exit 1 if any; exit 0 when all exist.
Usage: check_paths.py [ROOT]   (ROOT: the repository, default: this file's)
"""
import pathlib
import re
import sys

TOP = ("framework/", "labs/", "tests/", "scripts/", "pong/", "slides/", "docs/", "assets/", ".ci/",
       "CMakeLists.txt", "CMakePresets.json", ".clang-format")
INCLUDE_ROOTS = ("hitbox/", "compat/")  # as an #include names them: under framework/
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
CODE = re.compile(r"`([^`\n]+)`")
PLACEHOLDER = re.compile(r"[<>*…]|\.\.\.|\bNN|NAME|\$")
NAME = r"`[A-Za-z_][\w:]*(?:\(\))?`"
# `name` in `path`, and lists of names: `a`, `b`, ... and `c` in `path`.
NAMES_IN = re.compile(rf"((?:{NAME}(?:,\s*|\s+and\s+|\s+or\s+))*{NAME})(?:,\s*\.\.\.)?(?:\s+\([^()`]{{0,80}}\))?"
                      r"\s+in\s+`([^`\n]+)`")


def pages(root):
    yield root / "README.md"
    yield from sorted((root / "docs").glob("*.md"))
    yield from sorted((root / "labs").glob("*/README.md"))
    yield root / "pong" / "README.md"


def layers(root):
    """Hitbox's layer folders, as a short path starts: ('app/', 'objects/', ...)."""
    folder = root / "framework" / "hitbox"
    return tuple(sorted(f"{p.name}/" for p in folder.iterdir() if p.is_dir())) if folder.is_dir() else ()


def resolve(root, word, short):
    """The file a backticked word names, or None when it names no repository path."""
    word = word.rstrip(".,;:)")
    word = re.sub(r":\d+(-\d+)?$", "", word).split("#", 1)[0]  # Ball.h:12 names a line of Ball.h
    if not word or PLACEHOLDER.search(word):
        return None
    if word.startswith(TOP):
        return root / word
    if word.startswith(short):
        return root / "framework" / "hitbox" / word
    if word.startswith(INCLUDE_ROOTS):
        return root / "framework" / word
    return None


def problems(root, page):
    """(how many paths, links and names `page` names; a line for each that does not exist)."""
    short, found, missing = layers(root), 0, []
    text = page.read_text(encoding="utf-8")
    for target in LINK.findall(text):
        if re.match(r"[a-z]+:", target) or target.startswith("#") or PLACEHOLDER.search(target):
            continue  # a web address, an anchor on the same page or a placeholder
        found += 1
        if not (page.parent / target.split("#", 1)[0]).exists():
            missing.append(f"link {target} does not exist")
    for span in CODE.findall(text):
        for word in span.split():
            path = resolve(root, word, short)
            found += path is not None
            if path is not None and not path.exists():
                missing.append(f"path {word.rstrip('.,;:)')} does not exist ({path.relative_to(root)})")
    for names, where in NAMES_IN.findall(" ".join(text.split())):
        path = resolve(root, where, short)
        if path is None and (page.parent / where).is_file():
            path = page.parent / where  # a lab sheet's `Ball.h`: the lab's own file
        if path is None or not path.is_file():
            continue  # not a file (a folder, a placeholder): the path check above reports it
        source = path.read_text(encoding="utf-8", errors="replace")
        for name in re.findall(r"`([^`]+)`", names):
            last = re.sub(r"\(\)$", "", name).split("::")[-1]
            found += 1
            if not re.search(rf"\b{re.escape(last)}\b", source):
                missing.append(f"name {name} is not in {where}")
    return found, missing


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
    checked, missing = 0, 0
    for page in pages(root):
        if not page.is_file():
            continue
        found, problems_here = problems(root, page)
        checked += found
        missing += len(problems_here)
        for problem in problems_here:
            print(f"{page.relative_to(root)}: {problem}")
    if checked == 0:
        print(f"check_paths: no path, link or name found under {root}; is the parser broken?")
        return 1
    print(f"check_paths: {checked} paths, links and names checked, {missing} missing")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
