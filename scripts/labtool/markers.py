"""The task-marker grammar: the one place that says how a lab source marks what students write.

In the instructor's solution:

    // BEGIN TASK 2: bounce off the window edges
    ...solution lines...
    // STARTER TASK 2                 (optional; starter lines follow, each written as "// code")
    // END TASK 2

In an exercise or handout file the block has become one line, "// TASK 2: title — see README.md",
followed by the starter code. Test suites named Task<n><What> check task n.
"""
import re
from dataclasses import dataclass, field
from pathlib import Path

BEGIN = re.compile(r"^([ \t]*)//[ \t]*BEGIN TASK ([0-9]+):[ \t]*(\S.*)$")
STARTER = re.compile(r"^[ \t]*//[ \t]*STARTER TASK ([0-9]+)[ \t]*$")
END = re.compile(r"^[ \t]*//[ \t]*END TASK ([0-9]+)[ \t]*$")
# Any marker line at all (a malformed one must stop the tool, never pass as code); and a
# marker anywhere in a line, for the handout's check that none is left.
MARKER_ANYWHERE = re.compile(r"//[ \t]*(BEGIN|STARTER|END)[ \t]+TASK")
ANY_MARKER = re.compile(r"^[ \t]*" + MARKER_ANYWHERE.pattern)
# What an exercise (handout) file keeps of a task: "// TASK n: title — see README.md".
EXERCISE_TASK = re.compile(r"^[ \t]*//[ \t]*TASK ([0-9]+):")
# A grading test's suite names its task: Task2BounceOffWalls checks task 2.
TEST_SUITE_TASK = re.compile(r"^Task([0-9]+)")
SOURCE_SUFFIXES = (".cpp", ".h", ".hpp")


class MarkerError(ValueError):
    """A marker that does not pair up: the message names the file and line."""


@dataclass
class TaskRegion:
    """One task block of a solution file; line numbers are 1-based, markers included."""

    task: int
    title: str
    begin_line: int
    end_line: int
    starter_line: int = 0  # 0 when the block has no STARTER part
    solution_lines: list = field(default_factory=list)  # (line number, text) pairs


def task_regions(path):
    """The task blocks of one solution file, in order; raises MarkerError on a broken pairing."""
    regions, current, in_starter = [], None, False
    lines = Path(path).read_text(encoding="utf-8").splitlines()
    for number, raw in enumerate(lines, start=1):
        line = raw.rstrip("\r")
        where = f"{path}:{number}"
        if not ANY_MARKER.match(line):
            if current is not None and not in_starter:
                current.solution_lines.append((number, line))
            continue
        begin, starter, end = BEGIN.match(line), STARTER.match(line), END.match(line)
        if begin:
            if current is not None:
                raise MarkerError(f"{where}: BEGIN TASK {begin.group(2)} inside TASK {current.task}")
            current = TaskRegion(int(begin.group(2)), begin.group(3).strip(), number, 0)
            in_starter = False
        elif starter or end:
            task = int((starter or end).group(1))
            if current is None or current.task != task:
                raise MarkerError(f"{where}: {'STARTER' if starter else 'END'} TASK {task} with no open BEGIN TASK {task}")
            if starter:
                current.starter_line, in_starter = number, True
            else:
                current.end_line = number
                regions.append(current)
                current, in_starter = None, False
        else:
            raise MarkerError(f"{where}: a task marker must read '// BEGIN TASK n: title', '// STARTER TASK n' or '// END TASK n'")
    if current is not None:
        raise MarkerError(f"{path}:{current.begin_line}: BEGIN TASK {current.task} is never closed by // END TASK {current.task}")
    return regions


def tasks_in_text(text):
    """Task numbers a file names, in a solution (BEGIN TASK n:) or an exercise (TASK n:)."""
    found = set()
    for line in text.splitlines():
        match = BEGIN.match(line.rstrip("\r")) or EXERCISE_TASK.match(line)
        if match:
            found.add(int(match.group(2) if match.re is BEGIN else match.group(1)))
    return found


def task_of_test(name):
    """The task a test checks, from 'Suite.Test' or 'prefix.Suite.Test'; None when no Task<n> suite."""
    for part in name.split("."):
        match = TEST_SUITE_TASK.match(part)
        if match:
            return int(match.group(1))
    return None


def make_exercise(text, solved=(), where="<text>"):
    """The exercise version of a solution file's text (what HitboxMakeExercise.cmake writes):
    each unsolved task block becomes "// TASK n: title — see README.md" at the BEGIN line's
    indentation, then its starter lines un-commented; tasks in `solved` keep their solution."""
    out, state, solved_now, task = [], "code", False, None
    for number, raw in enumerate(text.splitlines(keepends=True), start=1):
        line = raw.rstrip("\r\n").rstrip("\r")
        ending = raw[len(raw.rstrip("\r\n")):]
        if ANY_MARKER.match(line):
            begin, starter, end = BEGIN.match(line), STARTER.match(line), END.match(line)
            if begin and state == "code":
                task, state = int(begin.group(2)), "solution"
                solved_now = task in solved
                if not solved_now:
                    out.append(f"{begin.group(1)}// TASK {task}: {begin.group(3).strip()} — see README.md{ending}")
            elif starter and state == "solution" and int(starter.group(1)) == task:
                state = "starter"
            elif end and state != "code" and int(end.group(1)) == task:
                state = "code"
            else:
                raise MarkerError(f"{where}:{number}: a task marker out of place: {line.strip()}")
        elif state == "code" or (state == "solution" and solved_now):
            out.append(raw)
        elif state == "starter" and not solved_now:
            match = re.match(r"^([ \t]*)// ?(.*)$", line)
            if not line.strip():
                out.append(raw)
            elif match is None:
                raise MarkerError(f"{where}:{number}: a starter line of TASK {task} must be a comment")
            else:
                out.append((match.group(1) + match.group(2) if match.group(2) else "") + ending)
    if state != "code":
        raise MarkerError(f"{where}: BEGIN TASK {task} is never closed")
    return "".join(out)


def write_if_changed(path, text):
    """Writes text to path unless it already holds it (an unchanged file does not recompile)."""
    path = Path(path)
    if path.exists() and path.read_text(encoding="utf-8") == text:
        return
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8", newline="")
