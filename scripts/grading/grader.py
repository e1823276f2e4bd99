#!/usr/bin/env python3
"""Grades students' lab submissions against the instructor's tree (this repository).

Used by scripts/grade-class.sh (a class) and the Gradescope autograder (one submission).
What it trusts and what it does not (README.md, "Grading a class", says the same):

- From a submission it takes ONLY the files a student is meant to edit: the lab sources
  that hold a task marker ("// BEGIN TASK n:") in the instructor's solution
  (student_files()). Everything else (tests, CMake files, scripts, framework, other
  headers) comes from the instructor's tree, and the feedback lists what was ignored.
- The tests are compiled from the instructor's tree, once per submission against the
  student's files. The list of tests per task comes from the instructor's own build (the
  solution), never from the student's build: a test missing from the student's program
  (a `#define TEST` trick, a renamed or disabled test) is failed.
- Each test runs in a process of its own, with GoogleTest's XML report written to a fresh
  path the grader chooses. A test passes only when that process exited with status 0
  after writing the report, the report parses, names exactly that one test, says it ran
  and completed, and records no failure. Nothing on stdout is read for the verdict, so
  printed "[       OK ]" lines and an early exit(0) earn nothing.
- Student files that define or undefine GoogleTest's macros (TEST, EXPECT_..., ...) or
  include gtest are refused: the lab gets no marks and the feedback says why.
Not defended: code that deliberately finds and forges the report file, or detects the
tests and special-cases them; an instructor sees that in the student's code.
"""
import argparse
import concurrent.futures
import csv
import hashlib
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path
from xml.sax.saxutils import escape

REPO = Path(__file__).resolve().parents[2]
TASK_MARKER = re.compile(r"//\s*(BEGIN )?TASK (\d+):")
SOURCE_SUFFIXES = {".cpp", ".h", ".hpp"}
# A student file may not touch the test framework (see the module's description).
TAMPERING = re.compile(
    r"^\s*#\s*(define|undef)\s+(TEST\w*|EXPECT_\w+|ASSERT_\w+|GTEST_\w+|FAIL|SUCCEED|ADD_FAILURE\w*|RUN_ALL_TESTS)\b"
    r"|^\s*#\s*include\s*[<\"](gtest|gmock)/|\btesting::", re.M)
# Seconds one test may run. Every grading test is bounded by step counts and takes well
# under a second on the solution and on the starter; this is only the last resort.
TEST_TIMEOUT = float(os.environ.get("LAB_TEST_TIMEOUT", "10"))
# A submission's test program is linked by lld or gold when there is one: a few times faster
# than the default linker on a test program with debug information.
FAST_LINKER = next(([f"-fuse-ld={name}"] for name in ("lld", "gold") if shutil.which(f"ld.{name}")), [])
SKIPPED_FOLDERS = {".git", "build", ".vs", ".vscode", "out", "cmake-build-debug", "__MACOSX"}


def run(command, **kwargs):
    return subprocess.run(command, check=True, **kwargs)


# --- The labs, as the instructor's tree defines them -------------------------------------

class Lab:
    """One lab: its name, folder, the files a student edits, and its tests per task."""

    def __init__(self, name, folder):
        self.name = name
        self.folder = folder  # e.g. labs/02_bouncing_balls (relative to REPO)
        self.student_files = student_files(REPO / folder)
        self.tests = []  # "Suite.Name", from the instructor's (solution) build

    def task_of(self, test):
        match = re.match(r"Task(\d+)", test)
        return match.group(1) if match else "-"

    def tasks(self):
        marked = set()
        for relative in [] if HANDOUT else self.student_files:
            marked |= {m.group(2) for m in TASK_MARKER.finditer((REPO / self.folder / relative).read_text())}
        return sorted(marked | {self.task_of(t) for t in self.tests if self.task_of(t) != "-"}, key=int)


# In a student handout the task markers are gone (a student may delete the "// TASK n:"
# lines too), so make-handout.sh writes the list student_files() derives here.
HANDOUT_LIST = REPO / "scripts" / "grading" / "student-files.txt"
HANDOUT = (REPO / "framework" / "cmake" / "HitboxHandout.cmake").exists()


def student_files(lab_dir):
    """The files a student edits: the lab's sources with a task marker, relative to lab_dir.
    The one list of them; derived from the solution, so a new task or file needs no edit."""
    if HANDOUT_LIST.exists():
        prefix = str(Path(lab_dir).relative_to(REPO)) + "/"
        return [line[len(prefix):] for line in HANDOUT_LIST.read_text().split() if line.startswith(prefix)]
    found = []
    for path in sorted(lab_dir.rglob("*")):
        if path.suffix in SOURCE_SUFFIXES and path.is_file() and TASK_MARKER.search(path.read_text()):
            found.append(str(path.relative_to(lab_dir)))
    return found


def all_labs():
    labs = []
    for cmakelists in sorted(REPO.glob("labs/[0-9][0-9]_*/CMakeLists.txt")):
        match = re.search(r"^\s*hitbox_add_lab\(\s*([A-Za-z0-9_]+)", cmakelists.read_text(), re.M)
        if match:
            labs.append(Lab(match.group(1), str(cmakelists.parent.relative_to(REPO))))
    return labs


# --- The instructor's build: the framework and the test sources, compiled once -----------

class InstructorBuild:
    def __init__(self, build_dir, labs, jobs):
        self.dir = Path(build_dir).resolve()
        self.labs = labs
        self.jobs = jobs
        self.launcher = ["ccache"] if shutil.which("ccache") else []

    def prepare(self):
        env = dict(os.environ)
        if self.launcher:
            env.setdefault("CCACHE_BASEDIR", str(REPO.parent))
        if not (self.dir / "CMakeCache.txt").exists():
            configure = ["cmake", "-S", str(REPO), "-B", str(self.dir), "-DCMAKE_BUILD_TYPE=Debug",
                         "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON", "-DHITBOX_BUILD_BENCHMARKS=OFF",
                         # A student's unused variable warns; it does not fail the lab.
                         "-DHITBOX_WARNINGS_AS_ERRORS=OFF"]
            if self.launcher:
                configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
            run(configure, env=env, stdout=subprocess.DEVNULL)
        elif not (self.dir / "compile_commands.json").exists():
            # An existing build (e.g. CI's build/debug): only ask it for the compile commands.
            run(["cmake", "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON", str(self.dir)], env=env, stdout=subprocess.DEVNULL)
        targets = []
        for lab in self.labs:
            targets += [f"{lab.name}_tests"] + ([] if HANDOUT else [f"{lab.name}_exercise_level"])
        run(["cmake", "--build", str(self.dir), "--parallel", str(self.jobs), "--target", *targets],
            env=env, stdout=subprocess.DEVNULL)
        commands = json.loads((self.dir / "compile_commands.json").read_text())
        for lab in self.labs:
            program = self.dir / "tests" / lab.folder / f"{lab.name}_tests"
            listing = subprocess.run([str(program), "--gtest_list_tests"], check=True, text=True,
                                     capture_output=True, env=test_environment()).stdout
            lab.tests = list_tests(listing)
            lab.compile = [c for c in commands if f"CMakeFiles/{lab.name}_level.dir/" in c["command"]
                           or f"CMakeFiles/{lab.name}_tests.dir/" in c["command"]]
            lab.link_dir = program.parent
            lab.link = (program.parent / "CMakeFiles" / f"{lab.name}_tests.dir" / "link.txt").read_text().strip()
            lab.level_archive = f"lib{lab.name}_level.a"
            lab.starter_dir = REPO / lab.folder if HANDOUT else self.dir / lab.folder / "exercise"


def list_tests(listing):
    """The names GoogleTest's --gtest_list_tests prints, as Suite.Name (disabled ones too:
    a test the instructor disabled is not graded, so those are left out)."""
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


def test_environment():
    env = dict(os.environ)
    env["ALSOFT_DRIVERS"] = "null"
    env.pop("GTEST_OUTPUT", None)
    env.pop("GTEST_FILTER", None)
    return env


# --- One submission ------------------------------------------------------------------------

class Submission:
    def __init__(self, source, scratch, number):
        self.source = Path(source)
        self.name = self.source.name
        for suffix in (".zip", ".git", ".bundle"):
            if self.name.endswith(suffix):
                self.name = self.name[: -len(suffix)]
        self.scratch = Path(scratch) / "students" / f"{number}-{self.name}"
        self.root = None  # the unpacked files

    def unpack(self):
        if self.scratch.exists():
            shutil.rmtree(self.scratch)
        self.scratch.mkdir(parents=True)
        files = self.scratch / "files"
        if self.source.is_file() and self.source.suffix == ".zip":
            with zipfile.ZipFile(self.source) as archive:
                for member in archive.infolist():
                    target = (files / member.filename).resolve()
                    if str(target).startswith(str(files.resolve())):  # no ../ escapes
                        archive.extract(member, files)
        elif self.source.suffix == ".bundle" or (self.source.is_dir() and (self.source / "HEAD").is_file()
                                                 and not (self.source / "labs").exists()):
            run(["git", "clone", "--quiet", str(self.source), str(files)], stderr=subprocess.DEVNULL)
        elif self.source.is_dir():
            files = self.source
        else:
            raise ValueError(f"{self.source}: not a folder, a .zip or a git repository")
        self.root = files

    def all_files(self):
        found = []
        for dirpath, dirnames, filenames in os.walk(self.root):
            dirnames[:] = [d for d in dirnames if d not in SKIPPED_FOLDERS and not d.startswith("build")]
            for filename in filenames:
                found.append(Path(dirpath, filename).relative_to(self.root).as_posix())
        return sorted(found)

    def find(self, lab, relative, files):
        """Where the student's copy of lab file `relative` is: labs/NN_name/relative, or
        NN_name/relative anywhere, or (a flat upload) a unique file of that name."""
        folder = Path(lab.folder).name
        for candidate in files:
            if candidate == f"{lab.folder}/{relative}" or candidate.endswith(f"/{lab.folder}/{relative}"):
                return candidate
        for candidate in files:
            if candidate == f"{folder}/{relative}" or candidate.endswith(f"/{folder}/{relative}"):
                return candidate
        same_name = [f for f in files if f == relative or f.endswith("/" + relative)]
        return same_name[0] if len(same_name) == 1 else None


class TestResult:
    def __init__(self, name, passed, message, seconds=0.0):
        self.name, self.passed, self.message, self.seconds = name, passed, message, seconds


shared_locks = {}
shared_locks_guard = threading.Lock()


def compile_shared(launcher, arguments, output_index, output, directory, log):
    """Compiles an object every submission with the same headers shares, once."""
    with shared_locks_guard:
        lock = shared_locks.setdefault(str(output), threading.Lock())
    with lock:
        if output.is_file():
            return True
        output.parent.mkdir(parents=True, exist_ok=True)
        arguments = list(arguments)
        arguments[output_index] = str(output) + ".part"
        compiled = subprocess.run(launcher + arguments, cwd=directory, capture_output=True, text=True)
        log.append(compiled.stdout + compiled.stderr)
        if compiled.returncode != 0:
            return False
        os.replace(str(output) + ".part", output)
        return True


def grade_lab(lab, submission, files, used, launcher, shared_dir):
    """Builds the lab's tests against the student's files and runs every instructor test.
    Returns a dict: results (TestResult per instructor test), notes (why a lab got nothing)."""
    if not any(submission.find(lab, relative, files) for relative in lab.student_files):
        return {"results": [TestResult(t, False, "not submitted") for t in lab.tests], "not_submitted": True,
                "notes": ["not submitted: none of the lab's files (" + ", ".join(lab.student_files) + ") is in the submission"]}
    work = submission.scratch / lab.name
    lab_copy = work / "src" / lab.folder  # a clean copy of the instructor's lab folder
    shutil.copytree(REPO / lab.folder, lab_copy)
    instructor_lab = str(REPO / lab.folder)
    notes = []
    for relative in lab.student_files:
        found = submission.find(lab, relative, files)
        if found is None:
            shutil.copy(lab.starter_dir / relative, lab_copy / relative)
            notes.append(f"`{relative}` was not in the submission: graded the starter code")
            continue
        used.add(found)
        shutil.copy(submission.root / found, lab_copy / relative)
        text = (lab_copy / relative).read_text(errors="replace")
        tampering = TAMPERING.search(text)
        if tampering:
            line = text[: tampering.start()].count("\n") + 1
            notes.append(f"`{found}` line {line} touches the test framework (`{tampering.group(0).strip()}`):"
                         " the lab gets no marks")
            return {"results": [TestResult(t, False, "not run: the submission touches the test framework")
                                for t in lab.tests], "notes": notes, "tampering": True}

    # Compile with the instructor's flags, the student's lab folder in place of the
    # instructor's; then link as the instructor's build links, with these objects. Only the
    # student's own .cpp files are compiled for every submission: the tests and the lab's
    # other sources depend on the student's files only through the headers among them, so
    # they are compiled once per distinct set of those headers and shared.
    headers = "".join((lab_copy / r).read_text(errors="replace") for r in lab.student_files
                      if not r.endswith(".cpp"))
    headers_key = hashlib.sha256(headers.encode()).hexdigest()[:16]
    unchanged_headers = headers == "".join((REPO / lab.folder / r).read_text(errors="replace")
                                           for r in lab.student_files if not r.endswith(".cpp"))
    own_sources = {str(lab_copy / r) for r in lab.student_files if r.endswith(".cpp")}
    level_objects, test_objects, log = [], [], []
    failed = False
    phase_started = time.monotonic()
    for entry in lab.compile:
        # (-Werror dropped: a student's unused variable warns, it does not fail the lab.)
        arguments = [a.replace(instructor_lab, str(lab_copy)) for a in shlex.split(entry["command"]) if a != "-Werror"]
        # (and no dependency files, which Ninja asks for at paths relative to its own folder)
        for flag in ("-MT", "-MF", "-MQ"):
            while flag in arguments:
                del arguments[arguments.index(flag):arguments.index(flag) + 2]
        arguments = [a for a in arguments if a not in ("-MD", "-MMD")]
        output_index = arguments.index("-o") + 1
        original_output = arguments[output_index]
        source = arguments[arguments.index("-c") + 1]
        if source in own_sources:
            output = work / "objects" / original_output
            output.parent.mkdir(parents=True, exist_ok=True)
            arguments[output_index] = str(output)
            # Compiled from inside the student's lab folder, which lies as deep as every
            # other student's: with CCACHE_BASEDIR every path in the command becomes the same
            # relative path for all of them, so ccache finds a file another submission
            # already had (an untouched starter file, or code that differs only in comments).
            compiled = subprocess.run(launcher + arguments, cwd=lab_copy, capture_output=True, text=True,
                                      env=dict(os.environ, CCACHE_NOHASHDIR="1"))
            log.append(compiled.stdout + compiled.stderr)
            ok = compiled.returncode == 0
        elif unchanged_headers:
            output = Path(entry["directory"]) / original_output  # the instructor's own object
            ok = output.is_file()
        else:
            output = shared_dir / lab.name / headers_key / original_output
            ok = compile_shared(launcher, arguments, output_index, output, entry["directory"], log)
        if not ok:
            failed = True
            break
        (level_objects if f"{lab.name}_level.dir" in original_output else test_objects).append(str(output))
    program = work / f"{lab.name}_tests"
    seconds = {"compile": time.monotonic() - phase_started}
    phase_started = time.monotonic()
    if not failed:
        linked = [shlex.split(lab.link)[0], *FAST_LINKER, *test_objects]
        arguments = shlex.split(lab.link)[1:]
        for index, argument in enumerate(arguments):
            if argument.endswith(lab.level_archive):
                linked += level_objects
            elif argument.startswith("CMakeFiles/") and argument.endswith(".o"):
                continue  # the instructor's test objects: ours are in front
            elif index > 0 and arguments[index - 1] == "-o":
                linked.append(str(program))
            else:
                linked.append(argument)
        done = subprocess.run(linked, cwd=lab.link_dir, capture_output=True, text=True)
        log.append(done.stdout + done.stderr)
        failed = done.returncode != 0
    seconds["link"] = time.monotonic() - phase_started
    (work / "build.log").write_text("\n".join(log))
    if failed:
        errors = [line for line in "\n".join(log).splitlines()
                  if re.search(r"error|undefined reference|multiple definition|cannot find", line)][:20]
        notes.append("did not build: no test of this lab ran")
        message = "did not build:\n" + "\n".join(errors).replace(str(lab_copy) + "/", "")
        return {"results": [TestResult(t, False, message) for t in lab.tests], "notes": notes, "seconds": seconds}
    results = []
    phase_started = time.monotonic()
    for test in lab.tests:
        started = time.monotonic()
        result = run_one_test(program, test, work)
        result.seconds = time.monotonic() - started
        results.append(result)
    seconds["tests"] = time.monotonic() - phase_started
    return {"results": results, "notes": notes, "seconds": seconds}


def run_one_test(program, test, work):
    """Runs one test in a process of its own. See the module's description for the rule."""
    report_dir = Path(tempfile.mkdtemp(prefix="report-", dir=work))
    report = report_dir / f"{os.urandom(8).hex()}.xml"
    try:
        finished = subprocess.run([str(program), f"--gtest_filter={test}", f"--gtest_output=xml:{report}",
                                   "--gtest_color=no", "--gtest_also_run_disabled_tests=0"],
                                  cwd=report_dir, capture_output=True, text=True, errors="replace",
                                  timeout=TEST_TIMEOUT, env=test_environment())
    except subprocess.TimeoutExpired:
        return TestResult(test, False, f"did not finish within {TEST_TIMEOUT:g} s (an endless loop?)")
    status = finished.returncode
    if status < 0:
        return TestResult(test, False, f"crashed (signal {-status})")
    if not report.is_file():
        return TestResult(test, False, f"the test program ended (exit status {status}) before reporting this "
                                       "test's result: e.g. exit() called from the lab code")
    try:
        root = ET.parse(report).getroot()
    except ET.ParseError:
        return TestResult(test, False, "the test's report is unreadable")
    suite, name = test.split(".", 1)
    cases = root.findall("./testsuite/testcase")
    if len(cases) != 1 or cases[0].get("classname") != suite or cases[0].get("name") != name:
        return TestResult(test, False, "this test was not in the program built with the submission")
    case = cases[0]
    if case.get("status") != "run" or case.get("result", "completed") != "completed":
        return TestResult(test, False, f"did not run ({case.get('status')}, {case.get('result')})")
    failures = case.findall("failure")
    if failures:
        message = "\n".join(f.get("message", "") for f in failures)
        return TestResult(test, False, re.sub(r"(\.\./)+tests/labs/", "tests/labs/", message))
    if status != 0:
        return TestResult(test, False, f"the test program exited with status {status} after the test")
    return TestResult(test, True, "")


def grade_submission(source, number, labs, scratch, launcher, shared_dir):
    submission = Submission(source, scratch, number)
    started = time.monotonic()
    report = {"student": submission.name, "labs": {}, "ignored": [], "error": None}
    try:
        submission.unpack()
        files = submission.all_files()
        used = set()
        for lab in labs:
            report["labs"][lab.name] = grade_lab(lab, submission, files, used, launcher, shared_dir)
        report["ignored"] = [f for f in files if f not in used]
    except (ValueError, OSError, subprocess.CalledProcessError, zipfile.BadZipFile) as error:
        report["error"] = str(error)
        for lab in labs:
            report["labs"][lab.name] = {"results": [TestResult(t, False, f"not graded: {error}") for t in lab.tests],
                                        "notes": [f"not graded: {error}"]}
    report["seconds"] = time.monotonic() - started
    return report


# --- Reports -------------------------------------------------------------------------------

def task_rows(lab, graded):
    """(task, passed, total, mark, failures) per task; mark 1 when every test of it passed."""
    rows = []
    for task in lab.tasks() + (["-"] if any(lab.task_of(t) == "-" for t in lab.tests) else []):
        results = [r for r in graded["results"] if lab.task_of(r.name) == task]
        passed = sum(r.passed for r in results)
        mark = "" if task == "-" else int(bool(results) and passed == len(results))
        rows.append((task, passed, len(results), mark, [r for r in results if not r.passed]))
    return rows


def write_reports(report, labs, out):
    student = report["student"]
    feedback = [f"# Feedback: {student}", ""]
    junit = ['<?xml version="1.0" encoding="UTF-8"?>', f'<testsuites name="{escape(student)}">']
    gradescope = {"score": 0, "tests": [], "output": "", "stdout_visibility": "visible"}
    csv_rows = []
    for lab in labs:
        graded = report["labs"][lab.name]
        feedback += [f"## {lab.name}", ""]
        feedback += [f"- {note}" for note in graded["notes"]]
        feedback += ["", "| task | tests passed | mark |", "| --- | --- | --- |"]
        rows = task_rows(lab, graded)
        for task, passed, total, mark, failures in rows:
            feedback.append(f"| {task} | {passed}/{total} | {mark if mark != '' else 'not marked'} |")
            csv_rows.append([student, lab.name, task, passed, total, mark])
            if task != "-":
                gradescope["score"] += mark
                gradescope["tests"].append({
                    "name": f"{lab.name} task {task}", "score": mark, "max_score": 1,
                    "status": "passed" if mark else "failed", "visibility": "visible",
                    "output": f"{passed}/{total} tests passed" + "".join(
                        f"\n- {r.name}: {r.message}" for r in failures)})
        feedback.append("")
        for task, passed, total, mark, failures in [] if graded.get("not_submitted") else rows:
            passed_names = [r.name for r in graded["results"] if r.passed and lab.task_of(r.name) == task]
            if passed_names:
                feedback += [f"Task {task}, passed: " + ", ".join(f"`{n}`" for n in passed_names), ""]
        for task, passed, total, mark, failures in [] if graded.get("not_submitted") else rows:
            for result in failures:
                feedback += [f"**{result.name}** (task {task}) failed:", "", "```", result.message.strip(), "```", ""]
        failures = sum(not r.passed for r in graded["results"])
        junit.append(f'  <testsuite name="{lab.name}" tests="{len(graded["results"])}" failures="{failures}">')
        for result in graded["results"]:
            suite, name = result.name.split(".", 1)
            junit.append(f'    <testcase classname="{lab.name}.{escape(suite)}" name="{escape(name)}" '
                         f'time="{result.seconds:.3f}">')
            if not result.passed:
                junit.append(f'      <failure message="{escape(result.message.splitlines()[0] if result.message else "failed", {chr(34): "&quot;"})}">'
                             f"{escape(result.message)}</failure>")
            junit.append("    </testcase>")
        junit.append("  </testsuite>")
    junit.append("</testsuites>")
    if report["ignored"]:
        feedback += ["## Files not used", "",
                     "Only the files with a task in them are graded; these were ignored "
                     "(the instructor's copies were used instead):", ""]
        feedback += [f"- `{f}`" for f in report["ignored"][:200]]
        if len(report["ignored"]) > 200:
            feedback.append(f"- ... and {len(report['ignored']) - 200} more")
    if report["error"]:
        feedback += ["", f"**Not graded:** {report['error']}"]
    gradescope["output"] = "\n".join(feedback)
    out.mkdir(parents=True, exist_ok=True)
    (out / f"{student}.md").write_text("\n".join(feedback) + "\n")
    (out / f"{student}.junit.xml").write_text("\n".join(junit) + "\n")
    (out / f"{student}.results.json").write_text(json.dumps(gradescope, indent=1) + "\n")
    return csv_rows, gradescope


def main():
    parser = argparse.ArgumentParser(description="Grade lab submissions against the instructor's tree.")
    parser.add_argument("submissions", nargs="*", help="a student's folder, .zip or git repository, or "
                        "with --class a folder holding one per student")
    parser.add_argument("--class", dest="whole_class", action="store_true")
    parser.add_argument("--lab", action="append", help="grade only this lab (repeatable)")
    parser.add_argument("--out", default="grades", help="where the reports go")
    parser.add_argument("--build", default=str(REPO / "build" / "grading"), help="the instructor's build")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--gradescope", help="also copy the (single) submission's results.json here")
    parser.add_argument("--prepare-only", action="store_true",
                        help="only build the framework and the instructor's tests (an autograder's setup)")
    options = parser.parse_args()

    labs = all_labs()
    if options.lab:
        unknown = set(options.lab) - {lab.name for lab in labs}
        if unknown:
            sys.exit(f"grade: no lab called {', '.join(sorted(unknown))}; the labs: {' '.join(l.name for l in labs)}")
        labs = [lab for lab in labs if lab.name in options.lab]
    if options.prepare_only:
        InstructorBuild(options.build, labs, options.jobs).prepare()
        print(f"grade: instructor build ready in {options.build}")
        return
    sources = []
    for given in map(Path, options.submissions):
        if options.whole_class:
            if not given.is_dir():
                sys.exit(f"grade-class: {given} is not a folder of submissions")
            sources += sorted(p for p in given.iterdir() if not p.name.startswith("."))
        else:
            sources.append(given)
    if not sources:
        sys.exit("grade: no submissions found")

    started = time.monotonic()
    print(f"grade: building the framework and the instructor's tests once ({options.build})", flush=True)
    build = InstructorBuild(options.build, labs, options.jobs)
    build.prepare()
    print(f"grade: instructor build ready in {time.monotonic() - started:.0f} s; grading {len(sources)} "
          f"submission(s), {options.jobs} at a time", flush=True)
    out = Path(options.out)
    out.mkdir(parents=True, exist_ok=True)
    scratch = Path(tempfile.mkdtemp(prefix="grading-", dir=build.dir))
    all_rows = []
    lock = threading.Lock()
    done = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=options.jobs) as pool:
        futures = {pool.submit(grade_submission, source, number, labs, scratch, build.launcher, scratch / "shared"): source for number, source in enumerate(sources)}
        for future in concurrent.futures.as_completed(futures):
            report = future.result()
            rows, gradescope = write_reports(report, labs, out / "students")
            with lock:
                done += 1
                all_rows += rows
                marks = sum(r[5] for r in rows if r[5] != "")
                possible = sum(1 for r in rows if r[5] != "")
                slowest = max((r for g in report["labs"].values() for r in g["results"]),
                              key=lambda r: r.seconds, default=None)
                # Where the time went (the labs together): compile, link, run the tests.
                phases = {}
                for graded in report["labs"].values():
                    for phase, seconds in graded.get("seconds", {}).items():
                        phases[phase] = phases.get(phase, 0.0) + seconds
                print(f"[{done}/{len(sources)}] {report['student']}: {marks}/{possible} tasks "
                      f"({report['seconds']:.1f} s{': ' if phases else ''}"
                      f"{', '.join(f'{phase} {seconds:.1f} s' for phase, seconds in phases.items())}"
                      f"{f'; slowest test {slowest.seconds:.1f} s' if slowest else ''})"
                      f"{' - ' + report['error'] if report['error'] else ''}", flush=True)
            if options.gradescope:
                Path(options.gradescope).parent.mkdir(parents=True, exist_ok=True)
                Path(options.gradescope).write_text(json.dumps(gradescope, indent=1) + "\n")
    if not os.environ.get("GRADING_KEEP_SCRATCH"):
        shutil.rmtree(scratch, ignore_errors=True)
    with open(out / "grades.csv", "w", newline="") as gradebook:
        writer = csv.writer(gradebook, lineterminator="\n")
        writer.writerow(["student", "lab", "task", "tests passed", "tests total", "mark"])
        writer.writerows(sorted(all_rows, key=lambda r: (r[0], r[1], r[2] == "-", r[2])))
    print(f"grade: {len(sources)} submission(s) in {time.monotonic() - started:.0f} s; gradebook "
          f"{out / 'grades.csv'}, feedback, JUnit XML and results.json in {out / 'students'}/")


if __name__ == "__main__":
    main()
