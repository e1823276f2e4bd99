"""check_paths.py finds what it promises to find: a small repository is written to a scratch
folder with one mistake of each kind planted in its pages (a short framework path, a full
path, a link, a name said to be in a file, each on a page of each kind), next to correct ones
of the same kinds, and the check must name every mistake and nothing else.

    python3 -m unittest discover -s tests/docs -p 'test_*.py'
"""
import contextlib
import io
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_paths  # noqa: E402 (found through the line above)

FILES = {
    "framework/hitbox/objects/World.cpp": "void World::add() {}\n",
    "framework/hitbox/app/Loop.h": "constexpr float stepsPerSecond = 120.f;\n",
    "framework/hitbox/geometry/Overlap.h": "bool boxVsBox();\n",
    "labs/02_balls/Ball.h": "constexpr float ballSpeed = 300.f;\n",
    "pong/Ball.h": "struct BallSettings {};\n",
    "README.md": "Start with [the docs](docs/guide.md), then [the missing page](docs/gone.md).\n",
    "docs/guide.md": ("The World is `objects/World.cpp`; not `objects/Wrold.cpp`.\n"
                      "The step: `stepsPerSecond` in `framework/hitbox/app/Loop.h`, and\n"
                      "`stepsPerMinute` in `app/Loop.h`; `hitbox/app/Loop.h` as included.\n"),
    "labs/02_balls/README.md": ("`ballSpeed` in `Ball.h`; `ballRadius` in `Ball.h`.\n"
                                "See `labs/02_balls/Ball.cpp` and `labs/NN_name/` (a placeholder).\n"),
    "pong/README.md": "`BallSettings` and `PaddleSettings` in `Ball.h`; `geometry/Sweep.h`.\n",
}
PLANTED = [
    "README.md: link docs/gone.md does not exist",
    "docs/guide.md: path objects/Wrold.cpp does not exist (framework/hitbox/objects/Wrold.cpp)",
    "docs/guide.md: name stepsPerMinute is not in app/Loop.h",
    "labs/02_balls/README.md: path labs/02_balls/Ball.cpp does not exist (labs/02_balls/Ball.cpp)",
    "labs/02_balls/README.md: name ballRadius is not in Ball.h",
    "pong/README.md: name PaddleSettings is not in Ball.h",
    "pong/README.md: path geometry/Sweep.h does not exist (framework/hitbox/geometry/Sweep.h)",
]


class CheckPathsTest(unittest.TestCase):
    def run_check(self, files):
        with tempfile.TemporaryDirectory() as scratch:
            root = pathlib.Path(scratch)
            for name, text in files.items():
                (root / name).parent.mkdir(parents=True, exist_ok=True)
                (root / name).write_text(text, encoding="utf-8")
            printed = io.StringIO()
            old_argv = sys.argv
            sys.argv = ["check_paths.py", str(root)]
            try:
                with contextlib.redirect_stdout(printed):
                    status = check_paths.main()
            finally:
                sys.argv = old_argv
        return status, printed.getvalue().splitlines()

    def test_every_planted_mistake_is_named_and_nothing_else(self):
        status, lines = self.run_check(FILES)
        self.assertEqual(status, 1)
        self.assertEqual(sorted(lines[:-1]), sorted(PLANTED))
        self.assertIn(f"{len(PLANTED)} missing", lines[-1])

    def test_pages_without_mistakes_pass(self):
        correct = dict(FILES)
        correct["README.md"] = "Start with [the docs](docs/guide.md).\n"
        correct["docs/guide.md"] = "`stepsPerSecond` in `app/Loop.h`; `hitbox/app/Loop.h`.\n"
        correct["labs/02_balls/README.md"] = "`ballSpeed` in `Ball.h`; `labs/02_balls/Ball.h`.\n"
        correct["pong/README.md"] = "`BallSettings` in `Ball.h`; `objects/World.cpp`.\n"
        status, lines = self.run_check(correct)
        self.assertEqual(status, 0, lines)


if __name__ == "__main__":
    unittest.main()
