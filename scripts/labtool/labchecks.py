"""The course's own checks of its labs, run with the grading engine (engine.run_test: each test
in its own process, judged by its JUnit report), so "passed" means here what it means to a
student (lab.py grade) and to a grader (lab.py grade-class).

    lab.py check-exercises [--build DIR]     every solution passes; every task has a test that
                                             fails on the generated exercise
    lab.py check-handout [--lab L]... [--out DIR]
        1. make-handout.sh writes the handout; 2. it configures and builds alone; 3. untouched,
        only task tests fail and every task has a failing one; 4. with the solution of tasks
        1..n pasted in (markers.make_exercise), every test of tasks 1..n passes, n = 1, 2, ...

Exit status: 0 every check passed, 1 a check failed, 2 bad input.
"""
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from . import engine, limits, markers, procs
from .labs import REPO, BadInput, all_labs, find_lab
from .selfcheck import find_program


def run_all(program, work):
    """{Suite.Name: TestResult} of every test of a built GoogleTest program, one process each."""
    if program is None:
        raise RuntimeError("a test program that was just built is missing")
    listing = procs.run_limited([str(program), "--gtest_list_tests"], Path(work) / "list.out", limits.LIST_SECONDS,
                                env=engine.test_environment(), set_limits_here=True)
    tests = engine.list_tests(listing.output) if listing.status == 0 else []
    return {test: engine.run_test(program, test, work) for test in tests}


def tally(results, task):
    """(passed, failed) of the tests of `task` (suites Task<n>...); task None: of no task."""
    mine = [r for name, r in results.items() if markers.task_of_test(name) == task]
    passed = sum(r.passed for r in mine)
    return passed, len(mine) - passed


def failed_names(results, keep=lambda task: True):
    return " ".join(n for n, r in results.items() if not r.passed and keep(markers.task_of_test(n)))


def build(build_dir, targets):
    done = subprocess.run(["cmake", "--build", str(build_dir), "--parallel", "2", "--target", *targets],
                          capture_output=True, text=True, errors="replace")
    if done.returncode != 0:
        sys.stderr.write(done.stdout[-6000:] + done.stderr[-6000:])
        raise RuntimeError(f"{' '.join(targets[:3])}{'...' if len(targets) > 3 else ''} did not build "
                           "(the messages are above)")


def check_exercises(options):
    build_dir = Path(options.build or REPO / "build" / "debug").resolve()
    if not (build_dir / "CMakeCache.txt").exists():
        raise BadInput(f"{build_dir} is not a configured build folder (run: cmake --preset debug)")
    labs = all_labs()
    targets = [t for lab in labs for t in (f"{lab.name}_tests", f"{lab.name}_exercise_tests")]
    print(f"check-exercises: building {len(targets)} test programs", flush=True)
    build(build_dir, targets)
    problems = []
    print(f"{'LAB':<28} {'TASK':<5} {'SOLUTION PASSES':<16} {'EXERCISE FAILS':<15} VERDICT")
    with tempfile.TemporaryDirectory(prefix="check-exercises-") as work:
        for lab in labs:
            solution = run_all(find_program(build_dir, f"{lab.name}_tests"), work)
            exercise = run_all(find_program(build_dir, f"{lab.name}_exercise_tests"), work)
            if not all(r.passed for r in solution.values()):
                problems.append(f"{lab.name}: the solution fails {failed_names(solution)}")
            tasks = lab.tasks()
            if not tasks:
                problems.append(f"{lab.name}: no '// BEGIN TASK n: title' markers in {lab.folder}")
            for task in tasks:
                passed, failed = tally(solution, task)
                exercise_passed, exercise_failed = tally(exercise, task)
                verdict = "ok"
                if exercise_passed + exercise_failed == 0:
                    verdict = "NO TESTS"
                    problems.append(f"{lab.name} task {task}: no test suite named Task{task}... in its grading tests")
                elif exercise_failed == 0:
                    verdict = "PASSES VACUOUSLY"
                    problems.append(f"{lab.name} task {task}: every Task{task} test passes on the unmodified exercise")
                elif failed:
                    verdict = "SOLUTION FAILS"
                print(f"{lab.name:<28} {task!s:<5} {f'{passed}/{passed + failed}':<16} "
                      f"{f'{exercise_failed} of {exercise_passed + exercise_failed}':<15} {verdict}")
            for task in sorted({markers.task_of_test(n) for n in solution} - set(tasks) - {None}):
                problems.append(f"{lab.name}: tests for task {task}, but no '// BEGIN TASK {task}:' in {lab.folder}")
    return report("check-exercises", problems,
                  "every solution passes and every task has a test that fails on the exercise")


def report(what, problems, success):
    if problems:
        print(f"\n{what}: FAILED", file=sys.stderr)
        for problem in problems:
            print(f"  - {problem}", file=sys.stderr)
        return 1
    print(f"\n{what}: {success}")
    return 0


def check_handout(options):
    labs = all_labs()
    chosen = [find_lab(given, labs) for given in options.lab] if options.lab else labs
    out = Path(options.out).resolve()
    print(f"== 1. Writing the handout to {out}", flush=True)
    shutil.rmtree(out, ignore_errors=True)
    subprocess.run([str(REPO / "scripts" / "make-handout.sh"), str(out)], check=True)
    print("== 2. Building it on its own (lab programs and lab tests only)", flush=True)
    # ccache, when installed, comes from the handout's own HitboxCcache.cmake: it takes paths
    # relative to the handout's folder, so what the repository's build compiled is a hit here.
    subprocess.run(["cmake", "--preset", "debug"], cwd=out, check=True, stdout=subprocess.DEVNULL)
    build_dir = out / "build" / "debug"
    build(build_dir, [t for lab in chosen for t in (lab.name, f"{lab.name}_tests")])
    problems = []
    with tempfile.TemporaryDirectory(prefix="check-handout-") as work:
        print("== 3. The untouched handout: only task tests fail, every task has a failing test")
        print(f"{'LAB':<28} {'TASK':<5} FAILING (of all)")
        for lab in chosen:
            results = run_all(find_program(build_dir, f"{lab.name}_tests"), work)
            for task in lab.tasks():
                passed, failed = tally(results, task)
                print(f"{lab.name:<28} {task!s:<5} {failed} of {passed + failed}")
                if not failed:
                    problems.append(f"{lab.name} task {task}: no test fails on the untouched handout")
            others = failed_names(results, keep=lambda task: task is None)
            if others:
                problems.append(f"{lab.name}: tests that belong to no task fail on the handout: {others}")
        print("== 4. Pasting the solution in, one task more at a time")
        print(f"{'LAB':<28} {'SOLVED':<12} RESULT")
        for step in range(1, max(len(lab.tasks()) for lab in chosen) + 1):
            solved = {lab: lab.tasks()[:step] for lab in chosen if step <= len(lab.tasks())}
            for lab, tasks in solved.items():
                paste_solution(lab, out, tasks)
            build(build_dir, [f"{lab.name}_tests" for lab in solved])
            for lab, tasks in solved.items():
                results = run_all(find_program(build_dir, f"{lab.name}_tests"), work)
                result = "ok"
                for task in tasks:
                    if tally(results, task)[1]:
                        result = "FAIL"
                        problems.append(f"{lab.name}: with tasks {tasks} pasted in, tests of task {task} fail: "
                                        f"{failed_names(results, keep=lambda t, task=task: t == task)}")
                later = sum(tally(results, t)[1] for t in lab.tasks()[step:])
                print(f"{lab.name:<28} {','.join(map(str, tasks)):<12} {result} ({later} tests of later tasks still fail)")
    return report("check-handout", problems, "the handout builds alone, fails only on unfinished tasks, "
                  "and passes each task once its solution is in")


def paste_solution(lab, out, tasks):
    """Writes the lab's sources into the handout with `tasks` solved (what a student has then)."""
    for source in sorted((REPO / lab.folder).rglob("*")):
        if source.suffix in markers.SOURCE_SUFFIXES and source.is_file():
            relative = source.relative_to(REPO)
            text = source.read_text(encoding="utf-8")
            markers.write_if_changed(out / relative, markers.make_exercise(text, set(tasks), str(relative)))
