"""check_screenshots.py finds what it promises to find: a small repository and build folder are
written to a scratch folder, the build's "program" a stand-in that copies a picture (so no
display and no build are needed), and on the sheets: a picture that matches, the same pixels
written as RGB instead of RGBA (must match), a copy with one pixel changed, a caption with no
command, and a caption naming a program that is not built. The check must name every mistake
and nothing else.

    python3 -m unittest discover -s tests/docs -p 'test_*.py'
"""
import contextlib
import io
import os
import pathlib
import sys
import tempfile
import unittest
from unittest import mock

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_screenshots  # noqa: E402 (found through the line above)

PNG = check_screenshots.compare_png  # the pictures' one reader and writer (Pillow)

WIDTH, HEIGHT = 7, 5
# Draws the picture named by --from (beside this stand-in) into --screenshot's file.
STAND_IN = """#!/usr/bin/env python3
import pathlib, shutil, sys
source = pathlib.Path(__file__).parent / sys.argv[sys.argv.index("--from") + 1]
shutil.copyfile(source, sys.argv[sys.argv.index("--screenshot") + 1])
"""


def picture():
    """A small RGBA picture: every pixel a different colour."""
    return bytes(b for i in range(WIDTH * HEIGHT) for b in (i * 7 % 256, i * 13 % 256, i * 29 % 256, 255))


def write_rgb_png(path, rgba):
    """The same pixels as an RGB PNG (every alpha is 255): other bytes, the same picture."""
    image = PNG.pillow_image().frombytes("RGBA", (WIDTH, HEIGHT), bytes(rgba))
    image.convert("RGB").save(path, format="PNG")


def sheet(caption):
    return f"# A lab\n\n![A lab, finished](screenshot.png)\n\n*{caption}*\n\n**What it teaches**\n"


SHEETS = {  # folder: (caption, what the committed picture is)
    "labs/01_same": (sheet("Drawn. (`lab_fake --from drawn.png --screenshot screenshot.png`)"), "same"),
    "labs/02_as_rgb": (sheet("Drawn, the command over\ntwo lines. (`lab_fake --from drawn.png\n"
                             "--screenshot screenshot.png`)"), "rgb"),
    "labs/03_stale": (sheet("Drawn. (`lab_fake --from drawn.png --screenshot screenshot.png`)"), "one pixel"),
    "labs/04_no_command": (sheet("Drawn, and `F1` shows the boxes."), "same"),
    "labs/05_not_built": (sheet("Drawn. (`lab_fakee --from drawn.png --screenshot screenshot.png`)"), "same"),
}
PLANTED = [
    "labs/03_stale/README.md: screenshot.png is stale (1 of 35 pixels differ); re-take it: (cd labs/03_stale && "
    "xvfb-run -a ../../build/labs/00_fake/lab_fake --from drawn.png --screenshot screenshot.png)",
    "labs/04_no_command/README.md: the caption under screenshot.png names no command that draws it; end it "
    "with (`PROGRAM OPTIONS --screenshot screenshot.png`)",
    "labs/05_not_built/README.md: lab_fakee (the caption's program) is not in BUILD: misspelt, or not built",
]


class PlantedMistakes(unittest.TestCase):
    def setUp(self):
        scratch = tempfile.TemporaryDirectory()
        self.addCleanup(scratch.cleanup)
        self.root = pathlib.Path(scratch.name) / "repo"
        self.build = self.root / "build"  # inside the repository, as build/debug is
        program = self.build / "labs" / "00_fake" / "lab_fake"
        program.parent.mkdir(parents=True)
        (self.build / "CMakeCache.txt").write_text("")
        program.write_text(STAND_IN)
        program.chmod(0o755)
        PNG.write_png(program.parent / "drawn.png", WIDTH, HEIGHT, picture())
        for folder, (text, committed) in SHEETS.items():
            (self.root / folder).mkdir(parents=True)
            (self.root / folder / "README.md").write_text(text)
            pixels = bytearray(picture())
            if committed == "rgb":
                write_rgb_png(self.root / folder / "screenshot.png", pixels)
                continue
            if committed == "one pixel":
                pixels[4 * 17 + 1] ^= 0x01  # one channel of one pixel, one step
            PNG.write_png(self.root / folder / "screenshot.png", WIDTH, HEIGHT, bytes(pixels))
        (self.root / "pong").mkdir()
        (self.root / "pong" / "README.md").write_text("# Pong\n\nNo picture here.\n")

    def run_check(self, *arguments, display=":99"):
        output = io.StringIO()
        environment = {"PATH": os.environ.get("PATH", ""), **({"DISPLAY": display} if display else {})}
        with mock.patch.dict(os.environ, environment, clear=True), contextlib.redirect_stdout(output), \
                contextlib.redirect_stderr(output):
            try:
                status = check_screenshots.main([*arguments, "--root", str(self.root), str(self.build)])
            except SystemExit as exit_:
                status = exit_.code
        return status, output.getvalue().replace(str(self.build.resolve()), "BUILD")

    def test_names_every_planted_mistake_and_nothing_else(self):
        status, output = self.run_check()
        self.assertEqual(status, 1)
        self.assertEqual(output.splitlines()[:-1], PLANTED)
        self.assertIn("5 pictures on 6 sheets, 2 match", output.splitlines()[-1])

    def test_the_rgb_picture_is_read_as_the_same_pixels(self):
        rgb = PNG.pixels(self.root / "labs/02_as_rgb/screenshot.png")
        self.assertEqual(rgb, (WIDTH, HEIGHT, picture()))

    def test_update_retakes_the_stale_picture_and_then_it_matches(self):
        status, output = self.run_check("--update")
        self.assertEqual(status, 1)
        self.assertIn("labs/03_stale/README.md: screenshot.png was stale (1 of 35 pixels differ); re-taken", output)
        status, output = self.run_check()
        self.assertEqual(output.splitlines()[:-1], PLANTED[1:])
        self.assertEqual(status, 1)

    def test_without_a_display_it_says_so_and_exits_2(self):
        status, output = self.run_check(display=None)
        self.assertEqual(status, 2)
        self.assertIn("xvfb-run -a", output)

    def test_a_folder_that_is_no_build_exits_2(self):
        (self.build / "CMakeCache.txt").unlink()
        status, output = self.run_check()
        self.assertEqual(status, 2)
        self.assertIn("is not a build folder", output)


if __name__ == "__main__":
    unittest.main()
