#!/usr/bin/env python3
"""The grading tests measure with code the student cannot change.

A lab's grading tests (tests/labs/<lab>/, tests/labs-hidden/<lab>/) may call, of the free
functions a student's file defines, only the tasks: a function given to the student but
defined in a file the student submits (one with a task marker) is the student's to change,
so a test that measures with it (a reference answer, a depth, a count) could be fooled by
that change. Such functions belong in the lab's Given.cpp, which the grader always takes
from the course. Reads the sources as text (definitions start a line, clang-format's
style); members of classes are out of its reach. Exit 1 with one line per call found.
"""
import re
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "scripts"))
from labtool import labs, markers  # noqa: E402

# A free function's definition: at the start of a line, maybe [[nodiscard]], a return type,
# a name (or an operator), "(". A return type on a line of its own is not recognised.
DEFINITION = re.compile(r"^(?:\[\[nodiscard\]\]\s*)?(?!return\b|else\b)[A-Za-z_][\w:<>,*& ]*?[\s*&]"
                        r"((?:\w+::)*(?:operator\s*[^\s(]+|[A-Za-z_]\w*))\s*\(")


def defined_functions(source, outside_tasks):
    """Names of the free functions `source` defines; with outside_tasks, only those with no
    task marker around them or in their body (given to the student, not a task)."""
    found, name, depth, marked, in_task = set(), None, 0, False, False
    for line in source.read_text(encoding="utf-8").splitlines():
        if depth == 0 and name is None:
            if markers.BEGIN.match(line):
                in_task = True
            elif re.match(r"^\s*//\s*END TASK", line):
                in_task = False
            match = DEFINITION.match(line)
            if match and not line.rstrip().endswith(";") and "::" not in match.group(1):
                name, marked = match.group(1), in_task
        if name is not None:
            if depth == 0 and "{" not in line and line.rstrip().endswith(";"):
                name = None  # a declaration over several lines, not a definition
                continue
            marked = marked or bool(markers.MARKER_ANYWHERE.search(line))
            depth += line.count("{") - line.count("}")
            if depth == 0 and "}" in line:
                if not (outside_tasks and marked):
                    found.add(name)
                name = None
    return found


def calls_of_student_code(repo):
    """One line per grading-test call of a function a student's file gives outside its tasks."""
    problems = []
    for lab in labs.all_labs(repo):
        given = {}
        for relative in lab.student_files:
            if relative.endswith(".cpp"):
                source = repo / lab.folder / relative
                given.update(dict.fromkeys(defined_functions(source, outside_tasks=True), source))
        folder = Path(lab.folder).name
        tests = [path for where in ("labs", "labs-hidden") for pattern in ("*.cpp", "*.h")
                 for path in sorted((repo / "tests" / where / folder).glob(pattern))]
        for name, source in sorted(given.items()):
            if name.startswith("operator") and tests:  # used without its name: always a ruler
                problems.append(f"{source.relative_to(repo)}: defines {name} outside any task, "
                                "which tests compare or sort with; move it to the lab's Given.cpp")
        given = {name: source for name, source in given.items() if not name.startswith("operator")}
        for test in tests:
            text = test.read_text(encoding="utf-8")
            own = defined_functions(test, outside_tasks=False)  # a test's own helper of that name
            for name, source in sorted(given.items()):
                if name in own:
                    continue
                for number, line in enumerate(text.splitlines(), start=1):
                    if re.search(rf"(?<![\w.>])(?<!\w::){re.escape(name)}\s*\(", line):
                        problems.append(f"{test.relative_to(repo)}:{number}: calls {name}, which "
                                        f"{source.relative_to(repo)} defines outside any task: the "
                                        "student can change it; move it to the lab's Given.cpp")
                        break
    return problems


def main():
    problems = calls_of_student_code(REPO)
    for problem in problems:
        print(problem)
    print(f"check_given_code: {len(problems)} grading-test calls of code a student can change")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
