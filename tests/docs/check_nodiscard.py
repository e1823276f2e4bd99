#!/usr/bin/env python3
"""Every query in Hitbox's public headers is [[nodiscard]], as SFML 3 marks its own (issue 29).

A query is a function that returns a value: a declaration in framework/hitbox/**/*.h (not
app/private/) whose return type is not void, outside a private: section. Not queries: the
constructors, conversion operators (`explicit operator bool`), compound assignments
(`operator+=` returns *this), and the actions below, whose result may be ignored. Prints each
query without the attribute, exit 1; reads the headers as text (one declaration a line, which
clang-format keeps), so it needs no build.
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2] / "framework" / "hitbox"
# Actions that also return something, each documented on its declaration.
ACTIONS = {
    ("objects/World.h", "checkCollisions"),  # one step of events; the count is extra
    ("app/Rewind.h", "show"),  # shows a step; returns the one it clamped to
}
NOT_DECLARATIONS = ("//", "#", ":", "return", "using", "typedef", "class", "struct", "enum", "namespace", "template")
SPECIFIERS = {"static", "inline", "constexpr", "virtual", "friend"}
DECLARATION = re.compile(
    r"^\s*(?P<head>(?:[\w:]+(?:<[^;()]*>)?[\s*&]+)+?)(?P<name>operator\s*\S+?|~?[A-Za-z_]\w*)\s*\(")


def queries_without_nodiscard(header, relative):
    found, private, previous = [], False, ""
    for number, line in enumerate(header.read_text(encoding="utf-8").splitlines(), start=1):
        stripped = line.strip()
        if re.match(r"^(private|protected)\s*:", stripped):
            private = True
        elif re.match(r"^public\s*:", stripped) or re.match(r"^(class|struct)\b", line):
            private = False  # a top-level class starts public enough (a nested one stays)
        match = DECLARATION.match(line)
        if private or stripped.startswith(NOT_DECLARATIONS) or not match:
            previous = stripped
            continue
        words = [w for w in re.split(r"[\s*&]+", match.group("head")) if w]
        name = match.group("name")
        ret = [w for w in words if w not in SPECIFIERS]
        skip = (not ret or "explicit" in words or ret == ["void"] or ret[0] in {"else", "new", "delete", "case", "throw", "__asm__"}
                or re.match(r"operator\s*([-+*/|&^]?=|bool)$", name) or (relative, name) in ACTIONS
                or "[[nodiscard]]" in line or previous.endswith("[[nodiscard]]"))
        if not skip:
            found.append(f"framework/hitbox/{relative}:{number}: {stripped}")
        previous = stripped
    return found


def main():
    missing = []
    for header in sorted(ROOT.rglob("*.h")):
        relative = header.relative_to(ROOT).as_posix()
        if not relative.startswith("app/private/"):
            missing += queries_without_nodiscard(header, relative)
    for line in missing:
        print(f"{line}   <- a query: mark it [[nodiscard]]")
    print(f"check_nodiscard: {len(missing)} queries without [[nodiscard]]")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
