#!/usr/bin/env python3
"""Writes framework/compat/course-framework-hashes.json: the SHA-256 of every copy of the
course's own Framework/ files that the lab folders in tests/course/ carry, per generation.

The course-lab build (framework/cmake/HitboxCourseLabFramework.cmake) compares a lab's
Framework/ files against this table and names, in one line, each one a student edited.
Left out: the files whose lab copy the build always uses (GameState.h and GameState.cpp,
which students are invited to edit; the build says which), and fixture files marked
"Student edit" (the edits being tested).

    tests/course/write_framework_hashes.py          rewrite the table
    tests/course/write_framework_hashes.py --check  exit 1 if the table is out of date
"""
import hashlib
import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
FIXTURES = ROOT / "tests" / "course"
TABLE = ROOT / "framework" / "compat" / "course-framework-hashes.json"
MODULE = ROOT / "framework" / "cmake" / "HitboxCourseLab.cmake"
EDIT_MARKER = b"Student edit"


def ask_the_build(definition: str) -> str:
    """What HitboxCourseLab.cmake prints in script mode: the build's rules have one home."""
    result = subprocess.run(["cmake", f"-D{definition}", "-P", str(MODULE)],
                            check=True, capture_output=True, text=True)
    return result.stdout.strip()


def generation_of(lab: pathlib.Path) -> str:
    return ask_the_build(f"HITBOX_PRINT_GENERATION_OF={lab}")


def build_table() -> dict:
    always_the_labs_own = set(ask_the_build("HITBOX_PRINT_ALWAYS_OWN=ON").splitlines())
    generations: dict = {}
    for lab in sorted(p for p in FIXTURES.iterdir() if (p / "Main.cpp").is_file()):
        framework = lab / "Framework"
        if not framework.is_dir():
            continue
        files = generations.setdefault(generation_of(lab), {})
        for path in sorted(framework.iterdir()):
            data = path.read_bytes()
            if f"Framework/{path.name}" in always_the_labs_own or EDIT_MARKER in data:
                continue
            hashes = files.setdefault(f"Framework/{path.name}", [])
            digest = hashlib.sha256(data).hexdigest()
            if digest not in hashes:
                hashes.append(digest)
    for files in generations.values():
        for hashes in files.values():
            hashes.sort()
    return {
        "about": "SHA-256 of the course's shipped Framework/ files, per generation; written by "
                 "tests/course/write_framework_hashes.py from the fixtures in tests/course/",
        "generations": {g: dict(sorted(f.items())) for g, f in sorted(generations.items())},
    }


def main() -> int:
    text = json.dumps(build_table(), indent=2) + "\n"
    if sys.argv[1:] == ["--check"]:
        if not TABLE.is_file() or TABLE.read_text() != text:
            print(f"{TABLE.relative_to(ROOT)} is out of date: run tests/course/write_framework_hashes.py",
                  file=sys.stderr)
            return 1
        return 0
    if sys.argv[1:]:
        print("usage: write_framework_hashes.py [--check]", file=sys.stderr)
        return 2
    tmp = TABLE.with_suffix(".json.tmp")
    tmp.write_text(text)
    tmp.replace(TABLE)  # never half-written
    return 0


if __name__ == "__main__":
    sys.exit(main())
