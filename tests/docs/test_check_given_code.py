"""check_given_code.py names a grading test that calls a function given in a student's file,
and nothing else: a scratch repository holds one lab whose student file defines a task, a
given function and a helper the test defines for itself, and whose Given.cpp defines another.

    python3 -m unittest discover -s tests/docs -p 'test_*.py'
"""
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_given_code  # noqa: E402 (found through the line above)

STUDENT = '''#include "Crates.h"

int settle(std::vector<Crate>& crates,
           int passes);

bool operator<(const Crate& a, const Crate& b)
{
    return a.top < b.top;
}

[[nodiscard]] float deepest(const std::vector<Crate>& crates)
{
    return crates.empty() ? 0.f : 1.f;
}

// BEGIN TASK 1: push them apart
void pushApart(std::vector<Crate>& crates)
{
    crates.clear();
}
// END TASK 1

int settle(std::vector<Crate>& crates)
{
    // BEGIN TASK 2: settle
    return static_cast<int>(crates.size());
    // END TASK 2
}

static float helper(float x)
{
    return x;
}
'''
GIVEN = '''#include "Crates.h"

void fall(std::vector<Crate>& crates, float dt)
{
    (void)crates;
}
'''
TEST = '''namespace
{
float helper(float x)
{
    return x;
}
} // namespace

TEST(Task1Push, Apart)
{
    fall(crates, 0.1f);
    pushApart(crates);
    EXPECT_EQ(settle(crates), 0);
    EXPECT_LT(deepest(crates), helper(1.f));
}
'''


class CheckGivenCodeTest(unittest.TestCase):
    def test_only_the_given_function_in_the_student_file_is_named(self):
        with tempfile.TemporaryDirectory() as scratch:
            root = pathlib.Path(scratch)
            lab = root / "labs" / "14_crates"
            lab.mkdir(parents=True)
            (lab / "CMakeLists.txt").write_text("hitbox_add_lab(lab14_crates\n    MAIN main.cpp)\n")
            (lab / "Crates.cpp").write_text(STUDENT, encoding="utf-8")
            (lab / "Given.cpp").write_text(GIVEN, encoding="utf-8")
            (root / "tests" / "labs" / "14_crates").mkdir(parents=True)
            (root / "tests" / "labs" / "14_crates" / "CratesTests.cpp").write_text(TEST, encoding="utf-8")
            problems = check_given_code.calls_of_student_code(root)
        self.assertEqual(len(problems), 2, problems)
        self.assertIn("Crates.cpp: defines operator<", problems[0])
        self.assertIn("CratesTests.cpp:14: calls deepest", problems[1])


if __name__ == "__main__":
    unittest.main()
