#!/usr/bin/env python3
"""A right answer never fails for following the sheet: change the numbers a lab sheet invites
students to change (lab 11's Court.h "as you like", ballSpeed = 6000; lab 2's Ball.h), rebuild
that lab's solution and grading tests with them, and run every test: all must still pass.

The lab's sources and tests are copied to a scratch folder with the numbers changed there,
compiled with the commands in compile_commands.json (the lab's folder replaced by the copy)
and linked with the lab's own link command (read from CMake's file API by scripts/labtool/
cmakeapi.py); the source tree is never written.

Usage: scripts/check-sheet-numbers.py [--build build/debug]     exit 1 naming what failed
"""
import argparse
import json
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
from labtool.cmakeapi import LinkError, link_command  # noqa: E402
# Variants: (lab folder, [(file, the line's start, its new value)...]), what each sheet says to
# play with. Lab 11's sheet suggests ballSpeed = 6000; the slow ball and the smaller court are
# the other way a student plays with Court.h "as you like".
VARIANTS = [
    ("11_pong", [("Court.h", "constexpr float ballSpeed =", "6000.f;")]),
    ("11_pong", [("Court.h", "constexpr float ballSpeed =", "200.f;"),
                 ("Court.h", "constexpr float paddleHeight =", "130.f;"),
                 ("Court.h", "inline const Court court", "{0.f, 60.f, 1200.f, 600.f};")]),
    ("02_bouncing_balls", [("Ball.h", "constexpr float ballRadius =", "18.f;"),
                           ("Ball.h", "constexpr float ballSpeed =", "700.f;")]),
]


def changed_copy(folder, changes, into):
    """Copies the lab folder and its tests into `into`, with the sheet's numbers changed."""
    lab_copy, test_copy = into / "lab", into / "tests"
    shutil.copytree(ROOT / "labs" / folder, lab_copy)
    shutil.copytree(ROOT / "tests/labs" / folder, test_copy)
    for file, start, value in changes:
        path = lab_copy / file
        text, count = re.subn(rf"^({re.escape(start)})\s*[^;]*;", lambda m: f"{m.group(1)} {value}",
                              path.read_text(encoding="utf-8"), flags=re.MULTILINE)
        if count != 1:
            raise SystemExit(f"check-sheet-numbers: labs/{folder}/{file} has no line '{start} ...;'")
        path.write_text(text, encoding="utf-8")
    return lab_copy, test_copy


def check_lab(build, folder, lab, changes, scratch):
    lab_copy, test_copy = changed_copy(folder, changes, scratch)
    commands = json.loads((build / "compile_commands.json").read_text(encoding="utf-8"))
    lab_dir, test_dir = str(ROOT / "labs" / folder), str(ROOT / "tests/labs" / folder)
    hidden_dir = str(ROOT / "tests/labs-hidden" / folder)  # compiled as they are, against the copy
    objects, test_objects = [], []
    for entry in commands:
        command = entry["command"]
        source = entry["file"]
        into_lab = f"{lab}_level.dir" in command and source.startswith(lab_dir + "/")
        into_tests = f"{lab}_tests.dir" in command and (
            source.startswith(test_dir + "/") or source.startswith(hidden_dir + "/"))
        if not (into_lab or into_tests):
            continue
        words = [w.replace("-I" + lab_dir, "-I" + str(lab_copy)) for w in shlex.split(command)]
        copy = source.replace(lab_dir, str(lab_copy)).replace(test_dir, str(test_copy))
        words[words.index("-c") + 1] = copy
        out = scratch / f"{len(objects) + len(test_objects)}.o"
        words[words.index("-o") + 1] = str(out)
        subprocess.run(words, cwd=entry["directory"], check=True)
        (objects if into_lab else test_objects).append(str(out))
    # The test program's link command with the objects compiled here in place of its own
    # objects and of the lab's archive.
    link = link_command(build, f"{lab}_tests")
    archive = build / "labs" / folder / f"lib{lab}_level.a"
    program = scratch / "grading-tests"
    link = replace(link.swap_library(archive, test_objects + objects), objects=(), output=str(program))
    subprocess.run(link.words(), cwd=link.directory, check=True)
    result = subprocess.run([str(program), "--gtest_brief=1", "--gtest_color=no"], capture_output=True,
                            text=True, timeout=300)
    return result.returncode == 0, result.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default="build/debug")
    build = Path(parser.parse_args().build).resolve()
    if not (build / "compile_commands.json").exists():
        print(f"check-sheet-numbers: {build} is not a configured build folder (cmake --preset debug)",
              file=sys.stderr)
        return 2
    failed = []
    for folder, changes in VARIANTS:
        lab = re.search(r"hitbox_add_lab\(\s*(\w+)", (ROOT / "labs" / folder / "CMakeLists.txt").read_text()).group(1)
        subprocess.run(["cmake", "--build", str(build), "--target", f"{lab}_tests", "--parallel", "2"],
                       check=True, stdout=subprocess.DEVNULL)
        with tempfile.TemporaryDirectory(prefix="sheet-numbers-") as scratch:
            try:
                ok, output = check_lab(build, folder, lab, changes, Path(scratch))
            except LinkError as error:
                print(f"check-sheet-numbers: {error}", file=sys.stderr)
                return 2
        described = ", ".join(f"{start.split()[-2] if start.endswith('=') else start.split()[-1]} {value}"
                              for _, start, value in changes)
        print(f"check-sheet-numbers: {folder} with {described} {'every test passes' if ok else 'FAILS'}")
        if not ok:
            print(output)
            failed.append(f"{folder} ({described})")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
