#!/usr/bin/env python3
"""Hitbox's lab tool: one program for the labs' rules, grading and files (Python 3.9+,
standard library only; Linux, macOS and Windows).

    python3 scripts/lab.py grade 02            self-check lab 02 here (02, 2, 02_bouncing_balls,
                                               lab02_bouncing_balls); --all: every lab
    python3 scripts/lab.py grade-class DIR     grade a class (instructor; Linux, caged)
    python3 scripts/lab.py gradescope          Gradescope's run_autograder (always writes results.json)
    python3 scripts/lab.py mark CSV LAB TASK   exit 0 when the gradebook gives LAB's TASK its mark
    python3 scripts/lab.py labs | tasks LAB | folder LAB | student-files
    python3 scripts/lab.py exercise IN OUT [--solved 1,2]   write a solution file's exercise version
    python3 scripts/lab.py check-exercises | check-handout     the course's checks of its labs (labchecks.py)
    python3 scripts/lab.py check WHAT ARG...   CI: check the grader's output (check-grading.sh)
    python3 scripts/lab.py check-course-labs [--screenshots DIR] [FOLDER...]   old course lab folders
                                               build on Hitbox and run (check-course-labs.sh; courselabs.py)
    python3 scripts/lab.py handout OUT         write the student handout (instructor; needs PyYAML)

Exit status: 0 success, 1 a test failed (grade) or the mark is missing (mark), 2 bad input.
"""
import argparse
import sys
from pathlib import Path

sys.dont_write_bytecode = True  # (a read-only handout, and no __pycache__ in anyone's tree)
sys.path.insert(0, str(Path(__file__).resolve().parent))
from labtool import labs as lablist  # noqa: E402
from labtool.labs import BadInput  # noqa: E402


def command_labs(options):
    for lab in lablist.all_labs():
        print(lab.name)
    return 0


def command_tasks(options):
    lab = lablist.find_lab(options.lab, lablist.all_labs())
    for task in lab.tasks():
        print(task)
    return 0


def command_folder(options):
    print(lablist.find_lab(options.lab, lablist.all_labs()).folder)
    return 0


def command_student_files(options):
    for lab in lablist.all_labs():
        for relative in lab.student_files:
            print(f"{lab.folder}/{relative}")
    return 0


def command_exercise(options):
    from labtool import markers
    solved = {int(t) for t in options.solved.split(",") if t.strip()} if options.solved else set()
    try:
        text = Path(options.input).read_text(encoding="utf-8")
    except OSError as error:
        raise BadInput(f"{options.input}: {error.strerror}") from None
    markers.write_if_changed(Path(options.output), markers.make_exercise(text, solved, options.input))
    return 0


def command_same_exercise(options):
    """Proves HitboxMakeExercise.cmake (the build's generator) writes what markers.py says,
    for every lab file with a task, with no task solved and with the first one solved."""
    import subprocess
    import tempfile
    from labtool import markers
    problems = 0
    generator = lablist.REPO / "framework" / "cmake" / "HitboxMakeExercise.cmake"
    with tempfile.TemporaryDirectory() as scratch:
        output = Path(scratch) / "exercise"
        for lab in lablist.all_labs():
            for relative in lab.student_files:
                source = lablist.REPO / lab.folder / relative
                tasks = lab.tasks()
                for solved in ((), tuple(tasks[:1])):
                    output.unlink(missing_ok=True)
                    subprocess.run(["cmake", f"-DINPUT={source}", f"-DOUTPUT={output}",
                                    f"-DSOLVED_TASKS={','.join(map(str, solved))}", "-P", str(generator)], check=True)
                    text = source.read_text(encoding="utf-8")
                    if output.read_text(encoding="utf-8") != markers.make_exercise(text, set(solved), str(source)):
                        print(f"same-exercise: {lab.folder}/{relative} (solved {solved or 'none'}): "
                              "HitboxMakeExercise.cmake and markers.py disagree", file=sys.stderr)
                        problems += 1
    print(f"same-exercise: {'FAILED' if problems else 'the CMake generator and markers.py agree on every lab file'}")
    return 1 if problems else 0


def command_mark(options):
    import csv
    try:
        with open(options.gradebook, newline="", encoding="utf-8") as handle:
            rows = list(csv.DictReader(handle))
    except OSError as error:
        print(f"mark: {options.gradebook}: {error.strerror} (did grading run?)", file=sys.stderr)
        return 1
    for row in rows:
        if row["lab"] == options.lab and row["task"] == str(options.task):
            print(f"{options.lab} task {options.task}: {row['tests passed']}/{row['tests total']} tests passed"
                  + (f" ({row['reason']})" if row["reason"] else ""))
            return 0 if row["mark"] == "1" else 1
    print(f"{options.lab} task {options.task}: not graded", file=sys.stderr)
    return 1


def command_grade(options):
    from labtool import selfcheck
    return selfcheck.run(options)


def command_grade_class(options):
    from labtool import classgrade
    return classgrade.run(options)


def command_gradescope(options):
    from labtool import classgrade
    return classgrade.run_gradescope(options)


def command_check_exercises(options):
    from labtool import labchecks
    return labchecks.check_exercises(options)


def command_check_handout(options):
    from labtool import labchecks
    return labchecks.check_handout(options)


def command_check_course_labs(options):
    from labtool import courselabs
    return courselabs.run(options.words)


def command_handout(options):
    from labtool import handout
    return handout.run(options)


def command_check(options):
    from labtool import checks
    try:
        problems, summary = checks.CHECKS[options.what](*options.paths)
    except TypeError:
        raise BadInput(f"check {options.what}: wrong arguments: {' '.join(options.paths)}") from None
    except (OSError, ValueError, KeyError) as error:
        problems, summary = [f"{options.what}: cannot read what was written: {error!r}"], ""
    for problem in problems:
        print(f"check: {problem}", file=sys.stderr)
    if not problems:
        print(f"check: {summary}")
    return 1 if problems else 0


def command_fair_marks(options):
    from labtool import fairmarks
    labs = lablist.all_labs()
    chosen = [lablist.find_lab(given, labs) for given in options.lab] if options.lab else labs
    if options.action == "make":
        fairmarks.make_class(options.path, chosen)
        return 0
    problems = fairmarks.check(options.path, chosen)
    for problem in problems:
        print(f"check-fair-marks: {problem}", file=sys.stderr)
    return 1 if problems else 0


def command_tricks(options):
    from labtool import tricks
    if options.action == "make":
        tricks.make_class(options.path)
        return 0
    if options.action == "bench":
        tricks.make_bench(options.path, options.count, options.hostile)
        return 0
    problems, table = tricks.check(options.path)
    print(f"{'SUBMISSION':<24} {'MARKS':<10} {'MAY EARN':<10} WHY")
    for student, got, earns, why in table:
        print(f"{student:<24} {','.join(map(str, got)) or '-':<10} {','.join(map(str, earns)) or '-':<10} {why}")
    for problem in problems:
        print(f"check-grading: {problem}", file=sys.stderr)
    return 1 if problems else 0


def main(argv=None):
    parser = argparse.ArgumentParser(prog="lab.py", description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    grade = commands.add_parser("grade", help="self-check labs in this checkout or handout")
    grade.add_argument("labs", nargs="*", metavar="LAB")
    grade.add_argument("--all", action="store_true", help="every lab")
    grade.add_argument("--build", help="build folder (default build/debug, configured with the debug preset)")
    grade.add_argument("--exercise", action="store_true", help="course repository: grade the generated exercise")
    grade.set_defaults(run=command_grade)

    whole = commands.add_parser("grade-class", help="grade a folder of submissions (one per student)")
    whole.add_argument("submissions", nargs="+", help="a folder of submissions, or with --one a submission")
    whole.add_argument("--one", action="store_true", help="the arguments are single submissions")
    whole.add_argument("--lab", action="append", help="grade only this lab (repeatable)")
    whole.add_argument("--out", default="grades", help="where the reports go (default grades/)")
    whole.add_argument("--build", help="the instructor's build (default build/grading)")
    whole.add_argument("--jobs", type=int, default=0, help="submissions at once (default: the cores)")
    whole.add_argument("--no-cage", action="store_true",
                       help="run without the sandbox (GitHub Classroom: the student's own repository)")
    whole.add_argument("--prepare-only", action="store_true", help="only build the instructor's tests")
    whole.set_defaults(run=command_grade_class)

    scope = commands.add_parser("gradescope", help="Gradescope's run_autograder: grade /autograder/submission")
    scope.add_argument("--root", default="/autograder")
    scope.add_argument("--prepare-only", action="store_true")
    scope.set_defaults(run=command_gradescope)

    mark = commands.add_parser("mark", help="exit 0 when the gradebook gives LAB's TASK its mark")
    mark.add_argument("gradebook")
    mark.add_argument("lab")
    mark.add_argument("task", type=int)
    mark.set_defaults(run=command_mark)

    for name, function in (("labs", command_labs), ("student-files", command_student_files),
                           ("same-exercise", command_same_exercise)):
        commands.add_parser(name).set_defaults(run=function)
    for name, function in (("tasks", command_tasks), ("folder", command_folder)):
        sub = commands.add_parser(name)
        sub.add_argument("lab")
        sub.set_defaults(run=function)
    exercise = commands.add_parser("exercise", help="write the exercise version of a solution file")
    exercise.add_argument("input")
    exercise.add_argument("output")
    exercise.add_argument("--solved", default="", help="tasks to keep solved, e.g. 1,3")
    exercise.set_defaults(run=command_exercise)

    exercises = commands.add_parser("check-exercises", help="every solution passes; every task has a test failing on its exercise")
    exercises.add_argument("--build", help="a configured build folder (default build/debug)")
    exercises.set_defaults(run=command_check_exercises)
    handout = commands.add_parser("check-handout", help="the handout builds alone and grades task by task")
    handout.add_argument("--lab", action="append", default=[], help="check only this lab (repeatable)")
    handout.add_argument("--out", default=str(lablist.REPO / "build" / "handout-check"),
                         help="where to write the handout (default build/handout-check; replaced)")
    handout.set_defaults(run=command_check_handout)
    # Its words are read as check-course-labs.sh always read them (a folder may start with "-"),
    # so argparse treats none of them as an option.
    course = commands.add_parser("check-course-labs", add_help=False, prefix_chars="+",
                                 help="old course lab folders build on Hitbox and run (-h: how)")
    course.add_argument("words", nargs="*", metavar="[--screenshots DIR] [FOLDER...]")
    course.set_defaults(run=command_check_course_labs)
    handout = commands.add_parser("handout", help="write the student handout into OUT (new or empty)")
    handout.add_argument("out", metavar="OUT", help="a relative OUT is taken from the folder you are in")
    handout.set_defaults(run=command_handout)

    check = commands.add_parser("check", help="CI: check what the grader wrote (results, Classroom workflow)")
    check.add_argument("what", choices=("class-results", "classroom-workflow", "gradescope-results"))
    check.add_argument("paths", nargs="+", metavar="ARG", help="class-results DIR | classroom-workflow FILE | "
                       "gradescope-results FILE SCORE")
    check.set_defaults(run=command_check)

    fair = commands.add_parser("fair-marks", help="check-fair-marks: make its class, or check its gradebook")
    fair.add_argument("action", choices=("make", "check"))
    fair.add_argument("path", help="make: the class folder to write; check: the grades folder")
    fair.add_argument("--lab", action="append", help="only this lab (repeatable; default every lab)")
    fair.set_defaults(run=command_fair_marks)

    tricks = commands.add_parser("tricks", help="check-grading: make the class of tricks, or check its gradebook")
    tricks.add_argument("action", choices=("make", "check", "bench"))
    tricks.add_argument("path", help="make, bench: the class folder to write; check: its grades.csv")
    tricks.add_argument("--count", type=int, default=30, help="bench: realistic submissions")
    tricks.add_argument("--hostile", action="store_true", help="bench: add the hostile submissions")
    tricks.set_defaults(run=command_tricks)

    options = parser.parse_args(argv)
    try:
        return options.run(options)
    except BadInput as error:
        print(f"{options.command}: {error}", file=sys.stderr)
        return 2
    except RuntimeError as error:  # the instructor's tree itself is broken
        print(f"{options.command}: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"\n{options.command}: interrupted: nothing recorded", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
