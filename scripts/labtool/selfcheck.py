"""lab.py grade: a student's self-check of labs in their checkout or handout.

Configures with the debug preset when needed, builds each lab's tests on its own (a lab that
does not compile costs that lab), checks the student's compiled objects as class grading does
(inspect.py: no main, nothing of GoogleTest, no symbol the harness owns, no call that ends the
program or writes files; where GNU binutils are missing, as with Visual Studio, it says so in
one line and goes on), runs every test with the engine's rule and limits (the same as class
grading) and prints a table per task. Writes BUILD/grade-results/<lab>.xml (JUnit)
and the build log; only a finished run writes, so Ctrl-C records nothing. Two runs in one
folder take turns (a lock). Exit status: 0 every test passed, 1 some test failed or a lab did
not build, 2 bad input (or a build folder that cannot be written).
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from . import cmakeapi, engine, inspect, limits, procs, reports
from .labs import REPO, BadInput, all_labs, find_lab, is_handout


class Stop(Exception):
    """Stops the run with one line and exit status 2."""


def lock(folder):
    """Holds an exclusive lock on folder/.grade.lock until the process ends (both OSes)."""
    handle = open(Path(folder) / ".grade.lock", "a+")
    if os.name == "nt":
        import msvcrt
        while True:
            try:
                msvcrt.locking(handle.fileno(), msvcrt.LK_LOCK, 1)
                break
            except OSError:
                time.sleep(1)
    else:
        import fcntl
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            print(f"grade: another grade run is using {folder}; waiting for it", flush=True)
            fcntl.flock(handle, fcntl.LOCK_EX)
    return handle


def writable(folder):
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as error:
        raise Stop(f"cannot write in {folder}: {error.strerror} (a read-only folder or a full disk?);"
                   " give another build folder with --build DIR") from None


def configure(build, default_build):
    if (build / "CMakeCache.txt").exists():
        return
    print(f"grade: configuring {build}", flush=True)
    if build == default_build:
        command = ["cmake", "--preset", "debug"]
    else:
        command = ["cmake", "-S", str(REPO), "-B", str(build), "-DCMAKE_BUILD_TYPE=Debug"]
    done = subprocess.run(command, cwd=REPO, capture_output=True, text=True, errors="replace")
    if done.returncode != 0:
        sys.stderr.write(done.stdout[-4000:] + done.stderr[-4000:])
        if disk_full(build):
            raise Stop(f"cmake could not configure {build}: the disk is full")
        raise Stop(f"cmake could not configure {build} (its messages are above)")


def disk_full(folder, margin=4 * 1024 * 1024):
    """True when the disk holding folder has less than margin bytes free."""
    try:
        return shutil.disk_usage(folder).free < margin
    except OSError:
        return False


def find_program(build, target):
    names = {target, target + ".exe"}
    for path in sorted(build.rglob(target + "*")):
        if path.name in names and path.is_file() and "CMakeFiles" not in path.parts:
            return path
    return None


BINUTILS = ("nm", "objdump", "c++filt")


def object_check(lab, build, target):
    """(why the lab is refused or "", a note): inspect.py on the student's objects in `build`.
    The harness is what the test program links besides them (its link command from CMake's
    file API, cmakeapi.py; where CMake cannot say, the framework's archives). No binutils
    (Windows with Visual Studio): nothing refused, a note."""
    if os.name == "nt":
        return "", ("the object check reads GNU object files (nm, objdump): not done on Windows "
                    "(class grading does it)")
    missing = [tool for tool in (*BINUTILS, "gcc") if shutil.which(tool) is None]
    if missing:
        return "", (f"the object check needs {', '.join(missing)} (GNU binutils), not found here: "
                    "not done (class grading does it)")
    level = "_exercise_level" if target.endswith("_exercise_tests") else "_level"
    level_dir = build / lab.folder / "CMakeFiles" / f"{lab.name}{level}.dir"
    own = {Path(relative).name + ".o" for relative in lab.student_files if relative.endswith(".cpp")}
    if not own:
        return "", ""
    student, others = {}, []
    for obj in sorted(level_dir.rglob("*.o")):
        if obj.name in own:
            student[obj.name[:-2]] = obj
        else:
            others.append(str(obj))
    test_dir = build / "tests" / lab.folder / "CMakeFiles" / f"{target}.dir"
    others += [str(o) for o in test_dir.rglob("*.o")]
    try:
        link = cmakeapi.link_command(build, target)
        archives = [link.path(w) for w in link.libraries if w.endswith(".a")]
        others += [str(a) for a in archives if a.is_file() and not a.name.startswith(f"lib{lab.name}")]
    except cmakeapi.LinkError:
        others += [str(a) for a in sorted((build / "framework").glob("*.a"))]
    if not student:
        return "", f"no object files of {', '.join(sorted(own))} in {level_dir}: the object check was not done"
    return inspect.refusal(student, inspect.harness_symbols(tuple(others))), ""


def grade_lab(lab, build, target, results_dir, work):
    """Builds and runs one lab; returns {"results": [...], "reason": why the lab got nothing}."""
    print(f"grade: building {target}...", flush=True)
    log = results_dir / f".{lab.name}.build.log.part"
    done = procs.run_limited(["cmake", "--build", str(build), "--config", "Debug", "--parallel", "2",
                              "--target", target], log, seconds=1800)
    graded = {"log": log}
    expected = lab.visible_tests()
    if done.status != 0:
        text = done.output
        sys.stderr.write(text[-6000:])
        why = "did not build (the compiler's messages are above)"
        if "No space left on device" in text or disk_full(build):
            why = "did not build: the disk is full"
        elif not text.strip():
            why = f"did not build (cmake --build stopped with status {done.status} and said nothing)"
        graded.update(reason=why, results=[engine.TestResult(t, False, why) for t in expected])
        return graded
    program = find_program(build, target)
    if program is None:
        graded.update(reason=f"{target} was not built", results=[])
        return graded
    refused, note = object_check(lab, build, target)
    if note:
        print(f"grade: {lab.name}: {note}", flush=True)
    if refused:
        why = f"refused: {refused}"
        graded.update(reason=why, results=[engine.TestResult(t, False, why) for t in expected])
        return graded
    # The student's code is in this program (its static initialisers run at the listing), so
    # the listing is held to a test's limits, not LIST_SECONDS (limits.py).
    listing = procs.run_limited([str(program), "--gtest_list_tests"], work / "list.out", limits.TEST_SECONDS,
                                env=engine.test_environment(), memory=limits.TEST_MEMORY,
                                file_bytes=limits.OUTPUT_BYTES, set_limits_here=True)
    listed = engine.list_tests(listing.output) if listing.status == 0 else []
    tests = listed + [t for t in expected if t not in listed]
    print(f"grade: running {lab.name} ({len(tests)} tests, each in its own process)...", flush=True)
    results = []
    for test in tests:
        if test not in listed:
            results.append(engine.TestResult(test, False, "not in the test program (did it start?)"))
            continue
        results.append(engine.run_test(program, test, work))
    graded["results"] = results
    return graded


def print_table(graded_labs, results_dir):
    print()
    print(f"{'LAB':<28} {'TASK':<5} {'PASSED':<7} {'FAILED':<7}")
    for lab, graded in graded_labs:
        if graded.get("reason"):
            log = "" if graded["reason"].startswith("refused") else f"  <- see {results_dir / (lab.name + '.build.log')}"
            print(f"{lab.name:<28} {'-':<5} {graded['reason']}{log}")
            continue
        for task, passed, total, mark, failures in engine.task_rows(lab.tasks(), graded["results"]):
            why = "; ".join(dict.fromkeys(f"{r.name.split('.', 1)[1]}: {r.reason}" for r in failures[:3]))
            more = f" (+{len(failures) - 3} more)" if len(failures) > 3 else ""
            print(f"{lab.name:<28} {task!s:<5} {passed:<7} {total - passed:<7}" + (f"  <- {why}{more}" if why else ""))


def run(options):
    labs = all_labs()
    if not labs:
        raise BadInput("no labs here (labs/NN_name/CMakeLists.txt): run it in a handout or the course repository")
    chosen = labs if options.all or not options.labs else [find_lab(given, labs) for given in options.labs]
    if options.exercise and is_handout():
        raise BadInput("--exercise is for the course repository; in a handout the labs are the exercise already")
    default_build = REPO / "build" / "debug"
    build = Path(options.build).resolve() if options.build else default_build  # against the caller's folder
    try:
        writable(build)
        held = lock(build)
        configure(build, default_build)
        results_dir = build / "grade-results"
        results_dir.mkdir(exist_ok=True)
        work = Path(tempfile.mkdtemp(prefix=".grade-", dir=build))
    except Stop as stop:
        print(f"grade: {stop}", file=sys.stderr)
        return 2
    except OSError as error:
        print(f"grade: cannot write in {build}: {error.strerror or error}", file=sys.stderr)
        return 2
    try:
        graded_labs = []
        for lab in chosen:
            suffix = "_exercise_tests" if options.exercise else "_tests"
            graded_labs.append((lab, grade_lab(lab, build, lab.name + suffix, results_dir, work)))
        for lab, graded in graded_labs:  # only a finished run writes its results
            os.replace(graded["log"], results_dir / f"{lab.name}.build.log")
            reports.write_atomically(results_dir / f"{lab.name}.xml", reports.junit(lab.name, [(lab.name, graded["results"])]))
    except OSError as error:
        print(f"grade: cannot write in {build}: {error.strerror or error}"
              + (" (the disk is full)" if getattr(error, "errno", 0) == 28 else ""), file=sys.stderr)
        return 2
    finally:
        shutil.rmtree(work, ignore_errors=True)
        for leftover in results_dir.glob(".*.part"):
            leftover.unlink(missing_ok=True)
        held.close()
    print_table(graded_labs, results_dir)
    print(f"JUnit XML: {results_dir / '<lab>.xml'}")
    passed = all(not g.get("reason") and g["results"] and all(r.passed for r in g["results"]) for _, g in graded_labs)
    print("grade: every test passed" if passed else "grade: some tests failed")
    return 0 if passed else 1
