"""The checks CI makes of the lab tool's own output (check-grading.sh, check-gradescope.sh):
what a grader writes must be what Gradescope and GitHub Classroom read. Each check returns
the problems it found (empty: all is well) and the line to print when there are none."""
import json
from pathlib import Path

from .labs import all_labs


def class_results(students):
    """The tricks class's reports: Gradescope's format, hidden tests after_published and never
    named before; the feedback says why a submission was refused."""
    students, problems = Path(students), []
    solution = json.loads((students / "solution.results.json").read_text(encoding="utf-8"))
    if solution["score"] != 3 or solution["output_format"] != "md":
        problems.append(f"the solution scored {solution['score']} in format {solution['output_format']}, not 3 in md")
    hidden = [t for t in solution["tests"] if t["visibility"] == "after_published"]
    if not hidden or any(t["max_score"] != 0 for t in hidden):
        problems.append("hidden checks must be after_published and worth 0")
    starter = json.loads((students / "starter.results.json").read_text(encoding="utf-8"))
    shown = "".join(t["output"] for t in starter["tests"] if t["visibility"] == "visible") + starter["output"]
    if "Hidden" in shown or "labs-hidden" in shown:
        problems.append("a hidden test is named before release")
    if "symbolic link" not in (students / "symlink-to-solution.md").read_text(encoding="utf-8"):
        problems.append("symlink-to-solution.md does not say it was refused for a symbolic link")
    own = (students / "disabled-own-tests.md").read_text(encoding="utf-8")
    if "tests/labs/02_bouncing_balls/BallsGradingTests.cpp" not in own:
        problems.append("disabled-own-tests.md does not name the instructor's test file")
    return problems, "results.json: md, hidden checks after_published and unnamed before; feedback says why"


def classroom_workflow(path):
    """The handout's GitHub Classroom workflow parses as YAML, has one 1-point test per task, and
    every step runs even after a failed one (a lab that does not compile costs that lab only)."""
    import yaml  # PyYAML (Debian: python3-yaml)
    tasks = sum(len(lab.tasks()) for lab in all_labs())
    steps = yaml.safe_load(Path(path).read_text(encoding="utf-8"))["jobs"]["grade"]["steps"]
    graders = [s for s in steps if str(s.get("uses", "")).startswith("classroom-resources/autograding-command-grader")]
    reporter = [s for s in steps if str(s.get("uses", "")).startswith("classroom-resources/autograding-grading-reporter")]
    problems = []
    if len(graders) != tasks:
        problems.append(f"{len(graders)} Classroom tests for {tasks} tasks")
    if not all(g["with"]["max-score"] == 1 and "lab.py mark" in g["with"]["command"] for g in graders):
        problems.append("a Classroom test is not 1 point of 'lab.py mark'")
    if not all(s.get("if") == "always()" for s in steps[2:]):
        problems.append("a step that does not always run")
    if len(reporter) != 1 or reporter[0]["with"]["runners"].split(",") != [g["id"] for g in graders]:
        problems.append("the reporter does not list every Classroom test once, in order")
    else:
        problems += [f"the reporter has no {g['id'].upper()}_RESULTS" for g in graders
                     if f"{g['id'].upper()}_RESULTS" not in reporter[0]["env"]]
    return problems, (f"the Classroom workflow parses: {len(graders)} tests of 1 point, one per task, "
                      "every step always runs")


def gradescope_results(path, expected):
    """A results.json Gradescope wrote: every test complete, the score expected."""
    results = json.loads(Path(path).read_text(encoding="utf-8"))
    tests, problems = results["tests"], []
    problems += [f"a test lacks a field: {t}" for t in tests if not {"name", "score", "max_score", "output"} <= set(t)]
    if results["score"] != int(expected):
        problems.append(f"score {results['score']}, expected {expected}")
    return problems, (f"results.json: score {results['score']}/{sum(t.get('max_score', 0) for t in tests)}: "
                      + ", ".join(f"{t.get('name')} {t.get('score')}" for t in tests))


CHECKS = {"class-results": class_results, "classroom-workflow": classroom_workflow,
          "gradescope-results": gradescope_results}
