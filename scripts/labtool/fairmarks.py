"""One mistake costs one task (scripts/check-fair-marks.sh): for each task n of each lab, a
submission with every task solved but n, which is left as the starter code (a wrong answer:
check-exercises.sh proves task n's tests fail on it). The class grader must give it every
mark of its lab but task n's; a cascade (task n's mistake failing another task's tests)
fails the check, naming the lab, the task and the tests."""
import csv
from pathlib import Path

from . import markers
from .labs import REPO


def student(lab, task):
    return f"{lab.name}-without-{task}"


def make_class(folder, labs):
    """Writes one submission per lab and task into folder: '<lab>-without-<n>'."""
    for lab in labs:
        tasks = lab.tasks()
        for task in tasks:
            into = Path(folder) / student(lab, task) / lab.folder
            for relative in lab.student_files:
                source = REPO / lab.folder / relative
                text = markers.make_exercise(source.read_text(encoding="utf-8"), set(tasks) - {task}, str(source))
                markers.write_if_changed(into / relative, text)


def check(grades, labs):
    """The problems: each submission whose marks are not every task of its lab but the one undone."""
    with open(Path(grades) / "grades.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    problems = []
    for lab in labs:
        tasks = lab.tasks()
        for task in tasks:
            who = student(lab, task)
            marked = [int(r["task"]) for r in rows
                      if r["student"] == who and r["lab"] == lab.name and r["task"] != "total" and r["mark"] == "1"]
            expected = [t for t in tasks if t != task]
            if marked != expected:
                problems.append(f"{lab.name} with only task {task} undone got marks for tasks "
                                f"'{','.join(map(str, marked))}', expected '{','.join(map(str, expected))}'")
                feedback = Path(grades) / "students" / f"{who}.md"
                lines = feedback.read_text(encoding="utf-8").splitlines() if feedback.exists() else []
                problems += [f"    failed: {line}" for line in lines
                             if line.startswith("**Task") and f"(task {task})" not in line]
    return problems
