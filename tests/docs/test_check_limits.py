"""check_limits.py names every quoted limit that disagrees with limits.py, and only those:
a scratch repository holds a limits.py and a page quoting right and wrong values.

    python3 -m unittest discover -s tests/docs -p 'test_*.py'
"""
import contextlib
import io
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_limits  # noqa: E402 (found through the line above)

LIMITS = '''TEST_SECONDS = 5
TEST_MEMORY = 1024 * 1024 * 1024
TEST_PROCESSES = 64


def megabytes(count):
    return f"{count // (1024 * 1024 * 1024)} GiB"
'''
PAGE = ("A test may take 5 s (`TEST_SECONDS`) and 1 GiB (`TEST_MEMORY`), not 4 s (`TEST_SECONDS`);\n"
        "64 processes (`TEST_PROCESSES`), 2 s (`TEST_MINUTES`).\n")


class CheckLimitsTest(unittest.TestCase):
    def test_every_wrong_quote_is_named_and_nothing_else(self):
        with tempfile.TemporaryDirectory() as scratch:
            root = pathlib.Path(scratch)
            (root / "scripts" / "labtool").mkdir(parents=True)
            (root / "scripts" / "labtool" / "limits.py").write_text(LIMITS, encoding="utf-8")
            (root / "docs").mkdir()
            (root / "docs" / "grading.md").write_text(PAGE, encoding="utf-8")
            (root / "README.md").write_text("No limit here.\n", encoding="utf-8")
            printed, old_argv = io.StringIO(), sys.argv
            sys.argv = ["check_limits.py", str(root)]
            try:
                with contextlib.redirect_stdout(printed):
                    status = check_limits.main()
            finally:
                sys.argv = old_argv
        lines = printed.getvalue().splitlines()
        self.assertEqual(status, 1)
        self.assertEqual(lines[:-1], ["docs/grading.md: '4 s (`TEST_SECONDS`)' but limits.py says 5 s",
                                      "docs/grading.md: TEST_MINUTES is not a limit in scripts/labtool/limits.py"])
        self.assertIn("5 quoted limits checked, 2 disagree", lines[-1])


if __name__ == "__main__":
    unittest.main()
