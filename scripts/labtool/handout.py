"""The student handout: a tree of its own with the framework, the EXERCISE version of every lab
(each task block replaced by "// TASK n: ... — see README.md" and its starter code), the lab
sheets, the grading tests and the lab tool. No solution code goes in it.

The tree is written into a hidden folder beside OUT and renamed to OUT only once every check
has passed: a write error, a failed check or Ctrl-C leaves nothing behind. Any failure is one
line (and the line saying why before it), exit 1; a bad OUT is one line, exit 2.
Its README and the file that tells the build "this is a handout" are files beside this one
(scripts/labtool/handout/), not text kept in code.
"""
import fnmatch
import os
import re
import shutil
import string
import subprocess
import sys
import tempfile
from pathlib import Path

from . import limits, markers
from .labs import REPO, all_labs

NAME = "make-handout"  # how every line starts (scripts/make-handout.sh calls this)
TEMPLATES = Path(__file__).resolve().parent / "handout"

# What a student gets, first match wins (a pattern's * crosses folders, as a shell `case`).
# Everything else (the README for instructors, CI, Pong, benchmarks, the slides, docs/, the
# other scripts) stays out.
KEEP = (
    ("tests/labs/*/hidden/*", False),  # hidden grading variants and the packs' own checks
    ("tests/course/*/*", False),  # course lab folders (scripts/check-course-labs.sh)
    ("tests/support/vcxproj/*", False),  # the course-lab build's .vcxproj reader's fixture
    ("framework/*", True), ("assets/*", True), ("tests/support/*", True), ("tests/geometry/*", True),
    ("tests/labs/*", True), ("tests/sfml/*", True), ("tests/objects/*", True), ("tests/app/*", True),
    ("tests/debug/*", True),
    ("tests/course/*.cpp", True),
    ("CMakeLists.txt", True), ("CMakePresets.json", True), (".clang-format", True), (".gitignore", True),
    ("tests/CMakeLists.txt", True),
    ("scripts/grade.sh", True), ("scripts/lab-tests.sh", True), ("scripts/install-deps.sh", True),
    ("scripts/labtool/tricks.py", False),  # (check-grading's class of tricks)
    ("scripts/labtool/handout.py", False),  # (this writer: the instructor's)
    ("scripts/labtool/courselab*.py", False),  # (check-course-labs: needs tests/course/, left out)
    ("scripts/lab.py", True), ("scripts/labtool/*.py", True),  # the lab tool: self-check, Classroom
    ("labs/CMakeLists.txt", True), ("labs/[0-9][0-9]_*/*", True),
)
LAB_SOURCE = "labs/[0-9][0-9]_*/*"
# The lecture's slide markers ("// [slide:name]", "// [/slide]") mean nothing to a student.
SLIDE_MARKER = re.compile(r"^\s*//\s*\[(slide:[^\]]*|/slide)\]\s*$")
TARGET = re.compile(r"\blab[0-9]{2}_[A-Za-z0-9_]+")


class Failed(Exception):
    """A check of the finished tree failed; the lines before it said which."""


def kept(path):
    for pattern, keep in KEEP:
        if fnmatch.fnmatchcase(path, pattern):
            return keep
    return False


def tree_files():
    """The files of this tree (tracked or new, not ignored), so a lab being written is included."""
    try:
        listed = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard"], cwd=REPO,
                                capture_output=True, text=True, check=True).stdout.splitlines()
    except (OSError, subprocess.CalledProcessError):
        listed = [p.relative_to(REPO).as_posix() for p in REPO.rglob("*")
                  if p.is_file() and not p.relative_to(REPO).as_posix().startswith(("build", ".git/"))]
    return sorted(set(listed))


def strip_slide_markers(text):
    return "".join(line for line in text.splitlines(keepends=True) if not SLIDE_MARKER.match(line.rstrip("\r\n")))


def copy_tree(out, solved):
    """Copies and generates every kept file into out; returns (generated, copied)."""
    generated = copied = 0
    for relative in tree_files():
        source, target = REPO / relative, out / relative
        if not source.is_file() or not kept(relative):
            continue  # (deleted but not yet committed, or not the student's)
        target.parent.mkdir(parents=True, exist_ok=True)
        is_source = relative.endswith(markers.SOURCE_SUFFIXES)
        if is_source:
            text = source.read_text(encoding="utf-8")
            if fnmatch.fnmatchcase(relative, LAB_SOURCE):
                text = markers.make_exercise(text, solved, relative)
                generated += 1
            else:
                copied += 1
            with open(target, "w", encoding="utf-8", newline="") as handle:
                handle.write(strip_slide_markers(text))
        else:
            shutil.copy2(source, target)
            copied += 1
    return generated, copied


def write_workflow(out, labs):
    """GitHub Classroom: on every push the grader grades the repository once, then one Classroom
    test per task (1 point each) reads that task's mark from the gradebook."""
    import yaml  # PyYAML (Debian: python3-yaml); only the instructor's machine writes handouts
    always = "always()"
    steps = [
        {"uses": "actions/checkout@v4"},
        {"name": "Install the compiler, CMake, SFML and GoogleTest",
         "run": "sudo apt-get update -qq && sudo apt-get install -y -qq g++ cmake pkg-config libsfml-dev "
                "libgtest-dev libgmock-dev"},
        {"name": "Grade every lab", "if": always,
         "run": 'python3 scripts/lab.py grade-class --one "$GITHUB_WORKSPACE" --no-cage --out grades '
                "--build build/grading"},
        {"name": "Feedback", "if": always, "run": 'cat grades/students/*.md >>"$GITHUB_STEP_SUMMARY"'},
    ]
    runners = []
    for lab in labs:
        for task in lab.tasks():
            runner = f"{lab.name.split('_')[0]}_task_{task}"
            runners.append(runner)
            steps.append({"name": f"{lab.name} task {task}", "id": runner, "if": always,
                          "uses": "classroom-resources/autograding-command-grader@v1",
                          "with": {"test-name": f"{lab.name} task {task}",
                                   "command": f"python3 scripts/lab.py mark grades/grades.csv {lab.name} {task}",
                                   "timeout": 1, "max-score": 1}})
    steps.append({"name": "Report the points", "if": always,
                  "uses": "classroom-resources/autograding-grading-reporter@v1",
                  "env": {f"{r.upper()}_RESULTS": f"${{{{ steps.{r}.outputs.result }}}}" for r in runners},
                  "with": {"runners": ",".join(runners)}})
    workflow = {
        "name": "Autograding",
        "on": ["push", "workflow_dispatch", "repository_dispatch"],
        "permissions": {"checks": "write", "actions": "read", "contents": "read"},
        "jobs": {"grade": {"runs-on": "ubuntu-latest", "if": "github.actor != 'github-classroom[bot]'",
                           "timeout-minutes": 30, "steps": steps}},
    }
    header = ("# GitHub Classroom autograding (written by scripts/lab.py handout): grades every lab on each push\n"
              "# with the lab tool (scripts/lab.py) and reports one test per task, 1 point each. Every step\n"
              "# runs even when one before it failed: a lab that does not compile costs that lab only.\n")
    path = out / ".github" / "workflows" / "classroom.yml"
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(header)
        yaml.safe_dump(workflow, handle, sort_keys=False, width=1000, allow_unicode=True)


def write_readme(out, labs):
    lines = []
    for lab in labs:
        sheet = REPO / lab.folder / "README.md"
        first = sheet.read_text(encoding="utf-8").splitlines()[:1] if sheet.is_file() else []
        title = first[0].lstrip("#").strip() if first and first[0].startswith("#") else ""
        lines.append(f"- `{lab.folder}/` — {title or lab.name} (program `{lab.name}`)")
    template = string.Template((TEMPLATES / "README.md").read_text(encoding="utf-8"))
    text = template.substitute(labs="\n".join(lines), test_seconds=limits.TEST_SECONDS)
    (out / "README.md").write_text(text, encoding="utf-8")


def rewrite_sheets(out):
    """The lab sheets speak of the course repository's targets too (<lab>_exercise, the solution
    <lab>); in the handout the student's program is <lab> and its tests <lab>_tests."""
    for sheet in sorted(out.glob("labs/[0-9][0-9]_*/README.md")):
        text = sheet.read_text(encoding="utf-8")
        text = re.sub(r"\(In the course repository[^)]*\)[ \t]*\n?", "", text)
        text = re.sub(r"^.*# the solution\n", "", text, flags=re.M)
        text = re.sub(r"(lab\d\d_\w+?)_exercise_tests\b", r"\1_tests", text)
        text = re.sub(r"(lab\d\d_\w+?)_exercise\b", r"\1", text)
        sheet.write_text(text, encoding="utf-8", newline="")


def say(line):
    print(f"{NAME}: {line}", file=sys.stderr)


def check_targets(out, labs):
    """Every target the handout's text names must exist there."""
    known = {lab.name for lab in labs} | {f"{lab.name}_tests" for lab in labs}
    pages = [out / "README.md"] + sorted(out.glob("labs/*/README.md"))
    for page in pages:
        for target in sorted(set(TARGET.findall(page.read_text(encoding="utf-8")))):
            if target not in known:
                say(f"the handout names a target it does not have: {target} ({page.relative_to(out)})")
                raise Failed


def solution_only_lines():
    """Lines inside a BEGIN TASK block that appear nowhere else in any lab, not even as starter
    code (whole lines, blanks around them ignored; 12 characters or more)."""
    solution, elsewhere, state = set(), set(), ""
    for path in sorted(REPO.glob(LAB_SOURCE)):
        if not (path.is_file() and path.name.endswith(markers.SOURCE_SUFFIXES)):
            continue
        for line in path.read_text(encoding="utf-8", errors="replace").splitlines():
            trimmed = line.rstrip("\r").strip(" \t")
            marker = markers.ANY_MARKER.match(line)
            if marker:
                state = {"BEGIN": "solution", "STARTER": "starter", "END": ""}[marker.group(1)]
            elif state == "solution":
                solution.add(trimmed)
            elif state == "starter":
                elsewhere.add(re.sub(r"^// ?", "", trimmed))
            else:
                elsewhere.add(trimmed)
    return {line for line in solution if len(line) >= 12 and line not in elsewhere}


def check_no_solution(out):
    """No solution line, task marker or slide marker in the handout; returns the lines checked."""
    wanted, seen, leaks = solution_only_lines(), set(), 0
    for path in sorted(p for p in (out / "labs").rglob("*") if p.is_file()):
        text = path.read_bytes().decode("utf-8", errors="replace")
        for number, line in enumerate(text.splitlines(), start=1):
            trimmed = line.rstrip("\r").strip(" \t")
            where = f"{path.relative_to(out)}:{number}"
            if trimmed in wanted and trimmed not in seen:
                seen.add(trimmed)
                say(f"solution line leaked into the handout: {trimmed} ({where})")
                leaks += 1
            if markers.MARKER_ANYWHERE.search(line):
                say(f"a task marker left in the handout: {where}: {trimmed}")
                leaks += 1
    for path in sorted(p for p in out.rglob("*") if p.is_file() and p.name.endswith(markers.SOURCE_SUFFIXES)):
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
            if SLIDE_MARKER.match(line):
                say(f"a slide marker left in the handout: {path.relative_to(out)}:{number}")
                leaks += 1
    if leaks:
        say("solution code in the handout (see above)")
        raise Failed
    return len(wanted)


def write(out, solved):
    labs = all_labs()
    generated, copied = copy_tree(out, solved)
    (out / "framework" / "cmake").mkdir(parents=True, exist_ok=True)
    shutil.copyfile(TEMPLATES / "HitboxHandout.cmake", out / "framework" / "cmake" / "HitboxHandout.cmake")
    # The files a student edits, from the solution's task markers (the grader's one list; the
    # handout has no markers left to derive it from).
    listed = "".join(f"{lab.folder}/{relative}\n" for lab in labs for relative in lab.student_files)
    (out / "scripts" / "labtool").mkdir(parents=True, exist_ok=True)
    (out / "scripts" / "labtool" / "student-files.txt").write_text(listed, encoding="utf-8")
    write_workflow(out, labs)
    write_readme(out, labs)
    rewrite_sheets(out)
    check_targets(out, labs)
    checked = check_no_solution(out)
    return labs, generated, copied, checked


def run(options):
    given = Path(options.out)
    out = Path(os.path.abspath(given))  # a relative OUT is the caller's folder's, not the repository's
    if out.exists() and (not out.is_dir() or any(out.iterdir())):
        say(f"{out} exists and is not empty; give a new folder (or delete it first).")
        return 2
    # (HANDOUT_SOLVED_TASKS=1,2 keeps those tasks solved: only for testing that the leak check
    # catches solution code.)
    solved = {int(t) for t in os.environ.get("HANDOUT_SOLVED_TASKS", "").split(",") if t.strip()}
    scratch = None
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
        scratch = Path(tempfile.mkdtemp(prefix=f".{out.name}.writing-", dir=out.parent))
        labs, generated, copied, checked = write(scratch, solved)
        if out.exists():
            out.rmdir()  # it was empty
        scratch.rename(out)
        scratch = None
    except (OSError, markers.MarkerError, UnicodeDecodeError) as error:
        say(str(error))
        return fail(out)
    except Failed:
        return fail(out)
    finally:
        if scratch is not None:
            shutil.rmtree(scratch, ignore_errors=True)
    print(f"{NAME}: wrote {out}: {len(labs)} labs ({' '.join(lab.name for lab in labs)}), {generated} exercise "
          f"sources, {copied} other files; {checked} solution-only lines checked absent")
    return 0


def fail(out):
    say(f"FAILED (see the line above: a write error? is the disk full?); nothing was left in {out}")
    return 1
