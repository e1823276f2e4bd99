"""Unit tests of check-course-labs' rules (scripts/labtool/courselabs.py) that need no display and
no build: a folder's check-course-lab.txt, the flood summary, the arguments, where a lab is
placed. (The whole check, building and running every folder in tests/course/, is CI's stage 8.)

    python3 -m unittest discover -s tests/scripts      (ctest: scripts.LabTool)
"""
import contextlib
import io
import os
import shutil
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.dont_write_bytecode = True
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from labtool import courselabs  # noqa: E402

REPO = Path(__file__).resolve().parents[2]


class Expectations(unittest.TestCase):
    def read(self, text):
        with tempfile.TemporaryDirectory() as folder:
            (Path(folder) / courselabs.EXPECTATIONS_FILE).write_text(text, encoding="utf-8")
            return courselabs.read_expectations(folder)

    def test_every_key_is_read_in_order_and_comments_are_not(self):
        expected = self.read("# run says: a comment\ncmake: -DA=1\ncmake:-DB=2\nconfigure says:   spaced  \n"
                             "hold the mouse at: 600 350\nrun says: first\nrun says: second")
        self.assertEqual(expected.cmake, ["-DA=1", "-DB=2"])
        self.assertEqual(expected.configure_says, ["spaced  "])  # leading spaces go, the rest is the text
        self.assertEqual(expected.run_says, ["first", "second"])
        self.assertEqual(expected.mouse_at, "600 350")
        self.assertFalse(expected.build_fails)

    def test_build_fails_is_a_whole_line(self):
        self.assertTrue(self.read("configure says: x\nbuild fails\n").build_fails)
        self.assertFalse(self.read("# build fails\nbuild fails later\n").build_fails)

    def test_a_folder_without_the_file_expects_nothing_more(self):
        with tempfile.TemporaryDirectory() as folder:
            expected = courselabs.read_expectations(folder)
        self.assertEqual((expected.cmake, expected.run_says, expected.mouse_at, expected.build_fails),
                         ([], [], "", False))


class FloodSummary(unittest.TestCase):
    LOG = b"spam\nalpha\nspam\nbeta\nalpha\nspam\nbeta\nlast line, no newline"  # alpha seen first

    def test_the_most_repeated_lines_come_first_ties_as_sort_breaks_them(self):
        self.assertEqual(courselabs.most_printed(courselabs.log_lines(self.LOG), 3),
                         b"      3 spam\n      2 beta\n      2 alpha\n")

    @unittest.skipUnless(shutil.which("sort") and shutil.which("uniq"), "needs sort and uniq")
    def test_the_same_as_the_shell_pipeline(self):
        shell = subprocess.run("sort | uniq -c | sort -rn | head -n 3", shell=True, input=self.LOG,
                               stdout=subprocess.PIPE, env={**os.environ, "LC_ALL": "C"}, check=True).stdout
        self.assertEqual(courselabs.most_printed(courselabs.log_lines(self.LOG), 3), shell)

    def test_a_last_line_without_its_newline_is_still_a_line(self):
        self.assertEqual(courselabs.log_lines(b"a\n\nb"), [b"a\n", b"\n", b"b"])


class Arguments(unittest.TestCase):
    def parse(self, *words):
        with contextlib.redirect_stderr(io.StringIO()) as said, contextlib.redirect_stdout(io.StringIO()):
            return courselabs.parse(words), said.getvalue()

    def test_every_other_word_is_a_folder_even_one_starting_with_a_dash(self):
        (screenshots, labs, status), _ = self.parse("a", "-x", "b/")
        self.assertEqual((screenshots, labs, status), ("", ["a", "-x", "b/"], None))

    def test_screenshots_without_a_folder_is_bad_input_on_one_line(self):
        (_, _, status), said = self.parse("a", "--screenshots")
        self.assertEqual(status, 2)
        self.assertEqual(said.count("\n"), 1)

    def test_help_says_how_and_runs_nothing(self):
        (_, labs, status), _ = self.parse("--help", "a")
        self.assertEqual((labs, status), ([], 0))


@unittest.skipUnless(shutil.which("cmake"), "needs cmake (the generation comes from HitboxCourseLab.cmake)")
class Placing(unittest.TestCase):
    def place(self, lab, sfml_here):
        here = os.getcwd()
        os.chdir(REPO)
        try:
            with contextlib.redirect_stderr(io.StringIO()) as said:
                verdict, place = courselabs.place_lab(str(lab), sfml_here)
        finally:
            os.chdir(here)
        return verdict, place, said.getvalue()

    def test_a_folder_without_main_cpp_fails_on_one_line(self):
        with tempfile.TemporaryDirectory() as folder:
            verdict, _, said = self.place(folder, "2")
        self.assertEqual(verdict, courselabs.FAIL)
        self.assertIn("not a lab folder", said)

    def test_a_2025_lab_outside_the_checkout_cannot_use_the_sfml3_root(self):
        with tempfile.TemporaryDirectory() as folder:
            lab = Path(folder) / "week5"
            shutil.copytree(REPO / "tests/course/week5_2025_states", lab)
            verdict, _, said = self.place(lab, "2")
        self.assertEqual(verdict, courselabs.FAIL)
        self.assertIn("needs SFML 3, not installed here", said)

    def test_a_2025_lab_in_the_checkout_goes_to_the_root_and_a_2019_lab_stays_here(self):
        verdict, place, _ = self.place("tests/course/week5_2025_states", "2")
        self.assertEqual((verdict, place.inside, place.lab_path), (courselabs.GO, courselabs.INSIDE_ROOT,
                                                                   "tests/course/week5_2025_states"))
        verdict, place, _ = self.place("tests/course/week9_pong/", "2")
        self.assertEqual((verdict, place.name, place.inside, place.build), (courselabs.GO, "week9_pong", [],
                                                                            "build/course-sfml2"))


if __name__ == "__main__":
    unittest.main()
