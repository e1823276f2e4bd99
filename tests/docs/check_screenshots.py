#!/usr/bin/env python3
"""Every screenshot a sheet shows is what its caption's command draws today (issue 26).

The sheets: every lab sheet (labs/NN_*/README.md) and pong/README.md. Under each picture
`![...](FILE.png)` the caption ends in the command that draws it, in backticks:
(`lab05_ray_caster --frames 300 --debug --screenshot FILE.png`). For each picture this runs
that program from BUILD_DIR with the caption's options, drawing into a scratch file, and
compares the result with the committed picture pixel for pixel. A picture made with
--screenshot is repeatable (hitbox::Options::repeatablePicture: fixed step, fixed seed, no
wall clock), so any difference means the program draws something else now: the picture is
stale, or the caption's command is not the one that drew it. Pictures are compared on the
SFML 2 build: SFML 3 draws letters a little differently, and CI compares the two builds'
pictures separately (scripts/compare-png.py).

Prints one line per stale picture naming the sheet and the command that re-takes it, one line
per picture whose caption names no such command; exit 1 if any, 0 when all match.
--update re-takes each stale picture: its caption's command, run in the sheet's folder (the
lines and exit status stay those of the check, so a re-taken picture is a change to look at).
Programs draw, so this needs a display: run it under `xvfb-run -a`. Exit 2 on bad usage.
Usage: xvfb-run -a check_screenshots.py [--update] [--root ROOT] BUILD_DIR
Pictures are read with Pillow through scripts/compare-png.py, their one reader: Debian's
python3-pil (scripts/install-deps.sh). Under a python3 without it the check restarts under
Debian's /usr/bin/python3 as it starts; exit 2 when neither has Pillow.
"""
import argparse
import importlib.util
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile

PROGRAM_SECONDS = 300  # the slowest picture (lab 13, 1300 steps, debug build) takes ~10 s
PICTURE = re.compile(r"^!\[[^\]]*\]\(([^)\s:]+\.png)\)\s*$")  # a local picture on its own line
CODE = re.compile(r"`([^`]+)`")  # may run over a line break, as Markdown allows


def sheets(root):
    """The pages that show screenshots, relative to ROOT."""
    found = sorted(root.glob("labs/[0-9][0-9]_*/README.md"))
    return found + [page for page in [root / "pong" / "README.md"] if page.is_file()]


def pictures(page):
    """(picture file, caption text) for each picture on a page; the caption is the paragraph
    under the picture, its lines joined."""
    lines = page.read_text(encoding="utf-8").splitlines()
    for number, line in enumerate(lines):
        match = PICTURE.match(line.strip())
        if not match:
            continue
        caption, rest = [], iter(lines[number + 1:])
        for text in rest:
            if text.strip() or caption:
                if not text.strip():
                    break
                caption.append(text.strip())
        yield match.group(1), " ".join(caption)


def caption_command(caption, picture):
    """The caption's command drawing PICTURE, as words; None when it names none."""
    for code in reversed(CODE.findall(caption)):
        words = shlex.split(code)
        if "--screenshot" in words[:-1] and words[words.index("--screenshot") + 1] == picture:
            return words
    return None


def load_compare_png():
    """scripts/compare-png.py (beside this file's repository, whatever --root says): pixels(),
    differing_pixels(), write_png(). Under a python3 without Pillow, this restarts the command."""
    path = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "compare-png.py"
    spec = importlib.util.spec_from_file_location("compare_png", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.pillow_image()
    return module


# Loaded on import, before anything runs, so a restart under Debian's python3 repeats nothing
# (test_check_screenshots.py imports this file under unittest).
compare_png = load_compare_png()


def find_program(build, name):
    """The program NAME in BUILD (labs/NN_*/NAME, pong/NAME), or None."""
    for pattern in (f"*/{name}", f"*/*/{name}"):
        for path in sorted(build.glob(pattern)):
            if path.is_file() and os.access(path, os.X_OK):
                return path
    return None


def draw(program, words, picture_path, folder):
    """Runs the caption's command with its picture drawn into PICTURE_PATH, in FOLDER; the
    program's last error line, or None when it succeeded."""
    arguments = list(words[1:])
    arguments[arguments.index("--screenshot") + 1] = str(picture_path)
    environment = dict(os.environ, ALSOFT_DRIVERS="null")  # no sound device needed
    try:
        run = subprocess.run([str(program), *arguments], cwd=folder, env=environment, capture_output=True,
                             text=True, timeout=PROGRAM_SECONDS)
    except subprocess.TimeoutExpired:
        return f"ran over {PROGRAM_SECONDS} s"
    if run.returncode != 0 or not (pathlib.Path(folder) / picture_path).is_file():
        last = (run.stderr.strip().splitlines() or [f"exit {run.returncode}, no picture"])[-1]
        return f"exit {run.returncode}: {last}"
    return None


def check_picture(root, build, page, picture, caption, update, scratch):
    """One line saying what is wrong with one picture, or None when it matches."""
    sheet, folder = page.relative_to(root), page.parent
    words = caption_command(caption, picture)
    if words is None:
        return (f"{sheet}: the caption under {picture} names no command that draws it; end it with "
                f"(`PROGRAM OPTIONS --screenshot {picture}`)")
    program = find_program(build, words[0])
    if program is None:
        return f"{sheet}: {words[0]} (the caption's program) is not in {build}: misspelt, or not built"
    shown = os.path.relpath(program, folder) if program.is_relative_to(root) else program  # a build outside ROOT
    retake = f"(cd {folder.relative_to(root)} && xvfb-run -a {shown} {shlex.join(words[1:])})"
    committed = folder / picture
    fresh = scratch / f"{folder.name}-{picture}"
    failed = draw(program, words, fresh, scratch)
    if failed:
        return f"{sheet}: {words[0]} failed to draw {picture}: {failed}"
    if not committed.is_file():
        return f"{sheet}: {picture} is not committed; take it: {retake}"
    if committed.read_bytes() == fresh.read_bytes():
        return None  # the usual case, and fast: the same program writes the same bytes
    counted = compare_png.differing_pixels(committed, fresh)  # (an RGB file of the same picture matches)
    if counted is not None and counted[0] == 0:
        return None
    amount = "another size" if counted is None else f"{counted[0]} of {counted[1]} pixels differ"
    if update:  # the caption's own command, in the sheet's folder, as a reader would run it
        failed = draw(program, words, picture, folder)
        return f"{sheet}: {words[0]} failed to re-take {picture}: {failed}" if failed else \
            f"{sheet}: {picture} was stale ({amount}); re-taken: {retake}"
    return f"{sheet}: {picture} is stale ({amount}); re-take it: {retake}"


def main(argv):
    parser = argparse.ArgumentParser(description="Every sheet's screenshot is what its caption's command draws.")
    parser.add_argument("build", type=pathlib.Path, help="the SFML 2 build folder, e.g. build/debug")
    parser.add_argument("--root", type=pathlib.Path, default=pathlib.Path(__file__).resolve().parents[2],
                        help="the repository whose sheets are checked (default: this file's)")
    parser.add_argument("--update", action="store_true", help="re-take the stale pictures in place")
    options = parser.parse_args(argv)  # exits 2 on bad usage
    root, build = options.root.resolve(), options.build.resolve()
    if not (build / "CMakeCache.txt").is_file():
        print(f"check_screenshots: {options.build} is not a build folder (cmake --preset debug makes build/debug)",
              file=sys.stderr)
        return 2
    if not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        print("check_screenshots: the programs draw, so a display is needed: run it under xvfb-run -a",
              file=sys.stderr)
        return 2
    checked, problems = 0, []
    with tempfile.TemporaryDirectory(prefix="check-screenshots-") as scratch:
        for page in sheets(root):
            for picture, caption in pictures(page):
                checked += 1
                problem = check_picture(root, build, page, picture, caption, options.update, pathlib.Path(scratch))
                if problem:
                    print(problem)
                    problems.append(problem)
    print(f"check_screenshots: {checked} pictures on {len(sheets(root))} sheets, {checked - len(problems)} match "
          "what their captions' commands draw")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
