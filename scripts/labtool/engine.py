"""The one meaning of "passed": how one grading test is run and judged, on every path.

A test runs in a process of its own (program --gtest_filter=Suite.Name) with GoogleTest's XML
report written to a fresh folder the engine chose, under the limits of limits.py. On Linux and
macOS the report's path is never on the command line: it goes through a pipe the test program
reads before any lab code runs (tests/support/TestMain.cpp), into a folder of a random name;
caged (class grading), inside a folder the test's user cannot list. So lab code cannot learn
where the report goes, and cannot write one of its own there. It passes
only when the process (and everything it started) is gone, it exited with status 0, no limit
stopped it, and the report parses, names exactly that one test, says it ran and completed,
and records no failure. Nothing it printed is read for the verdict. A task earns its mark when
every one of its tests (suites Task<n>...) passed.
"""
import os
import re
import shutil
import tempfile
import xml.etree.ElementTree as ET
import secrets
from dataclasses import dataclass
from pathlib import Path

from . import limits, markers, procs
from .labs import REPO


@dataclass
class TestResult:
    name: str  # Suite.Name
    passed: bool
    reason: str  # one line: "" when passed, else e.g. "failed", "took longer than 10 s"
    message: str = ""  # the failure's details (assertion messages)
    seconds: float = 0.0


# The variable naming the report pipe's descriptor (tests/support/TestMain.cpp reads it).
REPORT_PIPE = "HITBOX_GRADING_REPORT_FD"


def test_environment():
    env = {k: v for k, v in os.environ.items() if not k.startswith("GTEST_")}
    env["ALSOFT_DRIVERS"] = "null"
    return env


def list_tests(listing):
    """Suite.Name of each test --gtest_list_tests prints; disabled ones are not graded."""
    tests, suite = [], None
    for line in listing.splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            suite = line.split("#")[0].strip().rstrip(".")
        else:
            name = line.split("#")[0].strip()
            if not suite.startswith("DISABLED_") and not name.startswith("DISABLED_"):
                tests.append(f"{suite}.{name}")
    return tests


def run_test(program, test, work, slot=None, threaded=False):
    """Runs one test and judges it (see the module's description). slot: run caged as that
    grading slot's user (Linux class grading); None: run here with the same limits."""
    report_dir = Path(tempfile.mkdtemp(prefix="test-", dir=work))
    hidden = report_dir / secrets.token_hex(16)  # a name lab code cannot guess
    hidden.mkdir(mode=0o700)
    report = hidden / "report.xml"
    arguments = [f"--gtest_filter={test}", "--gtest_color=no", "--gtest_also_run_disabled_tests=0"]
    output = Path(work) / f"{report_dir.name}.out"
    env, pipe = test_environment(), None
    if os.name == "posix":  # the path through a pipe (TestMain.cpp), never on the command line
        import fcntl  # (POSIX only)
        read_end, write_end = os.pipe()
        os.write(write_end, str(report).encode())
        os.close(write_end)
        if read_end < 3:  # TestMain takes no standard descriptor
            read_end, low = fcntl.fcntl(read_end, fcntl.F_DUPFD, 3), read_end
            os.close(low)
        pipe = (read_end,)
        env[REPORT_PIPE] = str(read_end)
    else:  # the self-check on Windows: a student's own run, nothing to hide
        arguments.append(f"--gtest_output=xml:{report}")
    if slot is not None:
        from . import sandbox  # (Linux only: class grading; the self-check runs on Windows too)
        report_dir.chmod(0o711)  # the test's user may pass through, not list
        sandbox.give_to_slot(hidden, slot)
        assets = [REPO / "assets"] if (REPO / "assets").is_dir() else []
        command = sandbox.test_command(program, arguments, report_dir, slot, assets)
    elif threaded:  # (limits from a thread: set by prlimit, not in the child)
        command = procs.prlimit_prefix(limits.TEST_MEMORY, limits.OUTPUT_BYTES, limits.TEST_SECONDS) + [str(program), *arguments]
    else:
        command = [str(program), *arguments]
    try:
        outcome = procs.run_limited(command, output, limits.TEST_WALL_SECONDS + (2 if slot is not None else 0),
                                    cwd=report_dir, env=env, memory=limits.TEST_MEMORY,
                                    file_bytes=limits.OUTPUT_BYTES, cpu_seconds=limits.TEST_SECONDS,
                                    set_limits_here=slot is None and not threaded,
                                    pass_fds=(pipe[0],) if pipe else ())
        if slot is not None:
            if outcome.status > 128:
                outcome.status = 128 - outcome.status  # the cage reports a signal as 128 + n
            if not sandbox.wait_until_slot_is_empty(slot):
                return TestResult(test, False, "a process of the test would not end", seconds=outcome.seconds)
        return judge(test, outcome, report)
    finally:
        if pipe:
            os.close(pipe[0])
        shutil.rmtree(report_dir, ignore_errors=True)
        output.unlink(missing_ok=True)


def judge(test, outcome, report):
    """The verdict on one finished test process (and all it started: already gone)."""
    result = TestResult(test, False, "", seconds=outcome.seconds)
    stopped = procs.why_stopped(outcome, limits.TEST_SECONDS, limits.OUTPUT_BYTES,
                                wall_seconds=limits.TEST_WALL_SECONDS)
    if stopped:
        result.reason, result.message = stopped, tail(outcome.output)
        return result
    if not report.is_file():
        result.reason = (f"ended (exit status {outcome.status}) before reporting this test: "
                         "e.g. exit() called from the lab code")
        return result
    try:
        root = ET.parse(report).getroot()
    except ET.ParseError:
        result.reason = "its report is unreadable"
        return result
    suite, name = test.split(".", 1)
    cases = root.findall("./testsuite/testcase")
    if len(cases) != 1 or cases[0].get("classname") != suite or cases[0].get("name") != name:
        result.reason = "this test was not in the program built with the submission"
        return result
    case = cases[0]
    if case.get("status") != "run" or case.get("result", "completed") != "completed":
        result.reason = f"did not run ({case.get('status')}, {case.get('result')})"
        return result
    failures = case.findall("failure")
    if failures:
        result.reason = "failed"
        text = "\n".join(f.get("message", "") for f in failures)
        result.message = re.sub(r"(\.\./)+tests/", "tests/", text)
        return result
    if outcome.status != 0:
        result.reason = f"the test program exited with status {outcome.status} after the test"
        return result
    result.passed = True
    return result


def tail(text, lines=20):
    return "\n".join(text.splitlines()[-lines:])


def task_of(test):
    return markers.task_of_test(test)


def task_rows(tasks, results):
    """(task, passed, total, mark, failed results) per task, then ("-", ...) for tests of no
    task (mark None: not marked). mark is 1 when the task has tests and all passed."""
    rows = []
    for task in sorted(set(tasks) | {task_of(r.name) for r in results if task_of(r.name) is not None}):
        mine = [r for r in results if task_of(r.name) == task]
        passed = sum(r.passed for r in mine)
        rows.append((task, passed, len(mine), int(bool(mine) and passed == len(mine)),
                     [r for r in mine if not r.passed]))
    others = [r for r in results if task_of(r.name) is None]
    if others:
        rows.append(("-", sum(r.passed for r in others), len(others), None, [r for r in others if not r.passed]))
    return rows
