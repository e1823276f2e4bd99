"""Every file the engine writes, each with a real writer: JUnit XML (ElementTree), the
gradebook (csv), Gradescope's results.json (json), Markdown feedback. Files are written to a
temporary name and renamed, so a reader never sees half a file and two runs never mix."""
import csv
import json
import os
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

from .engine import task_rows
from .markers import task_of_test as task_of_name
from .submission import printable_name

GRADEBOOK_COLUMNS = ["student", "lab", "task", "tests passed", "tests total", "mark", "reason"]


def write_atomically(path, text):
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        with os.fdopen(handle, "w", encoding="utf-8", newline="") as out:
            out.write(text)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def junit(suites_name, labs_results):
    """labs_results: [(lab name, [TestResult])]."""
    root = ET.Element("testsuites", name=suites_name)
    for lab_name, results in labs_results:
        suite = ET.SubElement(root, "testsuite", name=lab_name, tests=str(len(results)),
                              failures=str(sum(not r.passed for r in results)))
        for result in results:
            test_suite, test_name = result.name.split(".", 1)
            case = ET.SubElement(suite, "testcase", classname=f"{lab_name}.{test_suite}", name=test_name,
                                 time=f"{result.seconds:.3f}")
            if not result.passed:
                failure = ET.SubElement(case, "failure", message=result.reason or "failed")
                failure.text = result.message
    ET.indent(root)
    return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"


def lab_reason(graded):
    """Why a whole lab got nothing, for the gradebook's reason column ("" when it was graded)."""
    return graded.get("reason", "")


def task_reason(graded, failures):
    if lab_reason(graded):
        return lab_reason(graded)
    reasons = []
    for result in failures:
        if result.reason not in reasons:
            reasons.append(result.reason)
    return "; ".join(reasons)


def gradebook_rows(student, lab, graded):
    rows = []
    for task, passed, total, mark, failures in task_rows(lab.tasks_for_grading, graded["results"]):
        rows.append([student, lab.name, task, passed, total, "" if mark is None else mark,
                     task_reason(graded, failures)])
    return rows


def write_gradebook(path, rows):
    """grades.csv: one row per student x lab x task, then a total per lab and per student."""
    rows = sorted(rows, key=lambda r: (r[0], r[1], r[2] == "-", str(r[2]).zfill(4)))
    totals = []
    for student in sorted({r[0] for r in rows}):
        mine = [r for r in rows if r[0] == student and r[5] != ""]
        for lab in sorted({r[1] for r in mine}):
            of_lab = [r for r in mine if r[1] == lab]
            totals.append([student, lab, "total", "", "", sum(r[5] for r in of_lab), f"of {len(of_lab)} tasks"])
        totals.append([student, "total", "total", "", "", sum(r[5] for r in mine), f"of {len(mine)} tasks"])
    with tempfile.NamedTemporaryFile("w", newline="", encoding="utf-8", dir=Path(path).parent,
                                     prefix=".grades.", delete=False) as out:
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(GRADEBOOK_COLUMNS)
        writer.writerows(rows + totals)
    os.replace(out.name, path)


def feedback(student, labs, report):
    """Markdown for the student: per lab a table, then each failed test once, then notes."""
    lines = [f"# Feedback: {student}", ""]
    for lab in labs:
        graded = report["labs"][lab.name]
        lines += [f"## {lab.name}", ""]
        if lab_reason(graded):
            lines += [f"**No marks for this lab: {lab_reason(graded)}.**", ""]
        lines += [f"- {note}" for note in graded.get("notes", [])]
        lines += ["", "| task | tests passed | mark | why not |", "| --- | --- | --- | --- |"]
        rows = task_rows(lab.tasks_for_grading, graded["results"])
        for task, passed, total, mark, failures in rows:
            shown = "not marked" if mark is None else mark
            lines.append(f"| {task} | {passed}/{total} | {shown} | {task_reason(graded, failures) if mark != 1 else ''} |")
        lines.append("")
        if lab_reason(graded):
            continue  # one line said it: no list of tests that never ran
        hidden = lab.hidden
        for task, passed, total, mark, failures in rows:
            for result in failures:
                if result.name in hidden:
                    continue  # shown after the grades are published (Gradescope), never here
                lines += [f"**{result.name}** (task {task}): {result.reason}", ""]
                if result.message.strip():
                    lines += ["```", result.message.strip(), "```", ""]
            hidden_failed = sum(r.name in hidden for r in failures)
            if hidden_failed:
                lines += [f"Task {task}: {hidden_failed} hidden check(s) failed (shown when the grades are published).", ""]
    if report.get("ignored"):
        lines += ["## Files not used", "", "Only the files with a task in them are graded; these were ignored:", ""]
        lines += [f"- `{printable_name(f)}`" for f in report["ignored"][:50]]
        if len(report["ignored"]) > 50:
            lines.append(f"- ... and {len(report['ignored']) - 50} more")
    if report.get("error"):
        lines += ["", f"**Not graded:** {report['error']}"]
    return "\n".join(lines) + "\n"


def gradescope(labs, report, feedback_text):
    """results.json: one visible test per task (1 point), and per task with hidden checks one
    more, after_published, with their failures; output_format md."""
    results = {"score": 0, "output": feedback_text, "output_format": "md", "stdout_visibility": "hidden",
               "tests": []}
    for lab in labs:
        graded = report["labs"][lab.name]
        for task, passed, total, mark, failures in task_rows(lab.tasks_for_grading, graded["results"]):
            if mark is None:
                continue
            results["score"] += mark
            visible = [r for r in failures if r.name not in lab.hidden]
            hidden = [r for r in failures if r.name in lab.hidden]
            text = lab_reason(graded) or "".join(
                f"- {r.name}: {r.reason}" + (f"\n\n```\n{r.message.strip()}\n```\n" if r.message.strip() else "\n")
                for r in visible)
            if hidden and not lab_reason(graded):
                text += f"- {len(hidden)} hidden check(s) failed: details when the grades are published\n"
            results["tests"].append({"name": f"{lab.name} task {task}", "score": mark, "max_score": 1,
                                     "status": "passed" if mark else "failed", "visibility": "visible",
                                     "output": text or "every test passed", "output_format": "md"})
            if any(r.name in lab.hidden for r in graded["results"] if task_of_name(r.name) == task):
                results["tests"].append({
                    "name": f"{lab.name} task {task}: hidden checks", "score": 0, "max_score": 0,
                    "visibility": "after_published", "output_format": "md",
                    "output": "".join(f"- {r.name}: {r.reason}\n\n```\n{r.message.strip()}\n```\n" for r in hidden)
                    or "every hidden check passed"})
    return json.dumps(results, indent=1) + "\n"


def failed_gradescope(reason):
    """results.json when grading itself failed: score 0, the reason, for the instructor."""
    return json.dumps({"score": 0, "output_format": "md", "tests": [],
                       "output": f"**Grading failed, not your code:** {reason}\n\nYour instructor has been told; "
                                 "this submission will be graded again."}, indent=1) + "\n"
