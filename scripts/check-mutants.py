#!/usr/bin/env python3
"""Mutation check: do the labs' grading tests catch the wrong answers students write?

For every "// BEGIN TASK n ... // END TASK n" block of every lab (grammar: scripts/labtool/
markers.py), single-point mutants of the solution lines (scripts/labtool/mutate.py: operator
swaps, sign flips, std::abs dropped, a constant changed, a statement dropped, a break added)
are compiled and graded one by one:

  - the mutated file is written to a scratch folder and compiled alone, with the command
    compile_commands.json holds for it; the lab's test program is relinked once with that
    object in place of the solution's (the lab library minus that one member). The source
    tree is never written, so an interrupted run (Ctrl-C) leaves nothing to restore;
  - every test runs in its own process with a time limit (--gtest_filter=Suite.Name);
  - a mutant is KILLED when a test of its own task fails, SURVIVED when none does, and costs
    COLLATERAL when a test of another task fails (one mistake must cost one task). A mutant
    that does not compile or link is not counted.

Wrong answers students really write (from the issues and the sheets) are listed in
tests/labs/wrong-answers.txt and tried as mutants of kind "sheet" in every run, sampled or not;
each must be killed by its own task's tests (a survivor fails the check even if listed as
equivalent).

Survivors that behave exactly like the solution are listed, with the reason, in
tests/labs/equivalent-mutants.txt (CSV: file,task,original,mutated,occurrence,reason; keyed by
the text of the change, not its line, so edits elsewhere do not unlist them).

The check fails (exit 1) when a task kills fewer than --threshold % (default 90) of its
non-equivalent mutants, or when any mutant fails another task's tests. Exit 2: bad arguments
or a build folder that is not configured.

Usage:
  scripts/check-mutants.py [--build build/debug] [--labs 02,11] [--sample N --seed S]
                           [--max-per-task 40] [--jobs 2] [--timeout 5] [--out DIR] [--list]
Writes DIR/mutants.csv (one row per mutant), DIR/tasks.csv and DIR/tasks.json (per task).
"""
import argparse
import csv
import io
import json
import math
import os
import random
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
from labtool.cmakeapi import LinkError, link_command  # noqa: E402
from labtool.markers import SOURCE_SUFFIXES, MarkerError, task_of_test, task_regions  # noqa: E402
from labtool.mutate import Mutant, mutants_of_region  # noqa: E402

EQUIVALENTS = ROOT / "tests/labs/equivalent-mutants.txt"
EQUIVALENT_FIELDS = ["file", "task", "original", "mutated", "occurrence", "reason"]
WRONG_ANSWERS = ROOT / "tests/labs/wrong-answers.txt"
WRONG_ANSWER_FIELDS = ["file", "task", "original", "mutated", "answer"]
LAB_CALL = re.compile(r"^\s*hitbox_add_lab\(\s*([A-Za-z0-9_]+)", re.MULTILINE)


class Refusal(Exception):
    """Bad input or an unusable build folder: one line, exit code 2."""


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build/debug", help="a configured build folder (default build/debug)")
    parser.add_argument("--labs", action="append", default=[],
                        help="labs to check: numbers or folder names, comma-separated (default every lab)")
    parser.add_argument("--sample", type=int, default=0, help="try N mutants per task, chosen with --seed")
    parser.add_argument("--seed", type=int, default=1, help="the sample's seed (default 1)")
    parser.add_argument("--max-per-task", type=int, default=40,
                        help="at most this many mutants per task in a full run (default 40)")
    parser.add_argument("--jobs", type=int, default=1, help="mutants graded at once (default 1)")
    parser.add_argument("--timeout", type=float, default=5.0, help="seconds one test may run (default 5)")
    parser.add_argument("--threshold", type=float, default=90.0, help="least kill rate per task, %% (default 90)")
    parser.add_argument("--out", default=None, help="where the CSV and JSON go (default BUILD/check-mutants)")
    parser.add_argument("--equivalents", default=str(EQUIVALENTS), help="the list of equivalent mutants")
    parser.add_argument("--list", action="store_true", help="only list the mutants that would be tried")
    args = parser.parse_args(argv)
    for name in ("sample", "max_per_task", "jobs"):
        if getattr(args, name) < 0 or (name == "jobs" and args.jobs < 1):
            raise Refusal(f"--{name.replace('_', '-')} must be a positive number")
    if args.timeout <= 0:
        raise Refusal("--timeout must be more than 0 seconds")
    return args


def all_labs():
    """(folder name, lab name) of every labs/NN_*/CMakeLists.txt calling hitbox_add_lab, in order."""
    found = []
    for cmakelists in sorted((ROOT / "labs").glob("[0-9][0-9]_*/CMakeLists.txt")):
        match = LAB_CALL.search(cmakelists.read_text(encoding="utf-8"))
        if match:
            found.append((cmakelists.parent.name, match.group(1)))
    return found


def chosen_labs(wanted):
    labs = all_labs()
    if not wanted:
        return labs
    picked = []
    for word in (w.strip() for item in wanted for w in item.split(",")):
        if not word:
            continue
        match = [lab for lab in labs if word in (lab[0], lab[1], lab[0][:2]) or word.zfill(2) == lab[0][:2]]
        if not match:
            raise Refusal(f"--labs: no lab '{word}' (labs: {', '.join(folder for folder, _ in labs)})")
        picked += [lab for lab in match if lab not in picked]
    return picked


def read_equivalents(path):
    """{mutant key: reason} from the checked-in list; '#' lines are comments."""
    path = Path(path)
    if not path.exists():
        return {}
    lines = [line for line in path.read_text(encoding="utf-8").splitlines() if line.strip() and not line.startswith("#")]
    listed = {}
    for number, row in enumerate(csv.DictReader(lines), start=1):
        if set(row) != set(EQUIVALENT_FIELDS) or not (row.get("reason") or "").strip():
            raise Refusal(f"{path}: entry {number} needs the columns {','.join(EQUIVALENT_FIELDS)} and a reason")
        key = (row["file"], int(row["task"]), row["original"], row["mutated"], int(row["occurrence"]))
        listed[key] = row["reason"].strip()
    return listed


def read_wrong_answers(path):
    """[(file, task, original lines, mutated lines, answer)]; '#' lines before the header are comments."""
    path = Path(path)
    if not path.exists():
        return []
    lines = path.read_text(encoding="utf-8").splitlines(True)
    comments = next((at for at, line in enumerate(lines) if not line.startswith("#")), len(lines))
    body = "".join(lines[comments:])  # (a listed line may start with '#': only the head is comments)
    answers = []
    for number, row in enumerate(csv.DictReader(io.StringIO(body)), start=1):
        if set(row) != set(WRONG_ANSWER_FIELDS) or not (row.get("answer") or "").strip():
            raise Refusal(f"{path}: entry {number} needs the columns {','.join(WRONG_ANSWER_FIELDS)} and an answer")
        original = [line.strip() for line in row["original"].splitlines()]
        mutated = [line.strip() for line in row["mutated"].splitlines()]
        answers.append((row["file"], int(row["task"]), original, mutated, row["answer"].strip()))
    return answers


def wrong_answer_mutant(relative, region, lines, original, mutated, answer):
    """The mutant that writes `mutated` in place of the consecutive solution lines `original`."""
    texts = [text.strip() for _, text in region.solution_lines]
    for at in range(len(texts) - len(original) + 1):
        if texts[at:at + len(original)] == original:
            first = region.solution_lines[at][0]
            indent = lines[first - 1][:len(lines[first - 1]) - len(lines[first - 1].lstrip())]
            changed = lines[:first - 1] + [indent + line for line in mutated or [""]] + \
                lines[first - 1 + len(original):]
            return Mutant(relative, region.task, first, "sheet", "\n".join(original), "\n".join(mutated),
                          text="\n".join(changed) + "\n")
    raise Refusal(f"{WRONG_ANSWERS.name}: '{answer}': {relative} task {region.task} has no lines "
                  f"{' / '.join(original)!r} (update the list)")


def compile_entry(commands, source, lab):
    """The compile command of `source` into the lab's library (not an exercise or another target)."""
    for entry in commands:
        if Path(entry["file"]).resolve() == source.resolve() and f"{lab}_level.dir" in entry.get("command", ""):
            return entry
    raise Refusal(f"{source}: not in compile_commands.json of the lab library {lab}_level; re-run cmake")


def option_value(words, option):
    index = words.index(option)
    return index, words[index + 1]


class LabRig:
    """What grading one lab's mutants needs: its test program, link command and test names."""

    def __init__(self, build, folder, lab, timeout):
        self.build, self.folder, self.lab, self.timeout = build, folder, lab, timeout
        try:
            self.link = link_command(build, f"{lab}_tests")
            self.archive = (build / "labs" / folder / f"lib{lab}_level.a").resolve()
            self.link.swap_library(self.archive, [])  # (refused here if the archive is not linked)
        except LinkError as error:
            raise Refusal(f"{lab}_tests: {error}") from error
        self.program = self.link.path(self.link.output)
        listing = run([str(self.program), "--gtest_list_tests"], timeout=60).stdout
        self.tests, suite = [], ""
        for line in listing.splitlines():
            if not line.startswith(" ") and line.strip().endswith("."):
                suite = line.strip()
            elif line.startswith("  ") and suite:
                self.tests.append(suite + line.split()[0])

    def run_tests(self, program):
        """{test name: 'pass' | 'fail' | 'timeout' | 'crash'}, each test in its own process."""
        results = {}
        for name in self.tests:
            results[name] = run_one_test(program, name, self.timeout)
        return results


def run(command, timeout, cwd=None, cpu_seconds=0):
    """Runs a command in its own process group; on a timeout the whole group is killed.
    With cpu_seconds, the process is also stopped after that much CPU time (SIGXCPU, set by
    prlimit: mutants are graded from threads, where a preexec_fn is not safe)."""
    if cpu_seconds:
        command = ["prlimit", f"--cpu={cpu_seconds}:{cpu_seconds + 1}", "--", *command]
    with subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          start_new_session=True, text=True, errors="replace") as process:
        try:
            output, _ = process.communicate(timeout=timeout)
        except BaseException:
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            process.communicate()
            raise
    return subprocess.CompletedProcess(command, process.returncode, output, "")


def run_one_test(program, name, timeout):
    # CPU time decides, as in grading (scripts/labtool/limits.py): CI's other stages running
    # beside this one must not turn a correct test of another task into a "timeout" (which
    # would read as collateral). The wall-clock guard only catches a test that waits.
    cpu = max(1, math.ceil(timeout))
    try:
        result = run([str(program), f"--gtest_filter={name}", "--gtest_color=no"], 3 * timeout,
                     cpu_seconds=cpu)
    except subprocess.TimeoutExpired:
        return "timeout"
    if result.returncode in (-signal.SIGXCPU, -signal.SIGKILL):
        return "timeout"
    if result.returncode == 0 and "[  PASSED  ] 1 test" in result.stdout:
        return "pass"
    return "fail" if result.returncode == 1 else "crash"


def choose(mutants, args, file, task):
    """The mutants tried for one task: all, a capped spread, or the fixed CI sample."""
    limit = args.sample or args.max_per_task
    if not limit or len(mutants) <= limit:
        return mutants
    picked = random.Random(f"{args.seed}:{file}:{task}").sample(range(len(mutants)), limit)
    return [mutants[i] for i in sorted(picked)]


def grade_mutant(rig, mutant, entry, stripped_archive, scratch_root):
    """Compiles, links and tests one mutant; returns (outcome, failed tests by task)."""
    scratch = Path(tempfile.mkdtemp(dir=scratch_root))
    try:
        # As a student compiles it: CI's -Werror on lab code is not theirs (-Werror=return-type is).
        words = [word for word in shlex.split(entry["command"]) if word != "-Werror"]
        source = scratch / Path(mutant.file).name
        source.write_text(mutant.text, encoding="utf-8")
        c_index, _ = option_value(words, "-c")
        o_index, _ = option_value(words, "-o")
        obj = scratch / "mutant.o"
        words[c_index + 1], words[o_index + 1] = str(source), str(obj)
        # Quoted includes of the mutated file look in its own folder first.
        words.insert(1, "-iquote" + str((ROOT / mutant.file).parent))
        try:
            if run(words, timeout=120, cwd=entry["directory"]).returncode != 0:
                return "did-not-compile", {}
            program = scratch / "tests"
            link = replace(rig.link.swap_library(rig.archive, [str(obj), str(stripped_archive)]), output=str(program))
            if run(link.words(), timeout=120, cwd=link.directory).returncode != 0:
                return "did-not-compile", {}
        except subprocess.TimeoutExpired:
            return "did-not-compile", {}
        results = rig.run_tests(program)
        failed = {}
        for name, verdict in results.items():
            if verdict != "pass":
                failed.setdefault(task_of_test(name), []).append(f"{name} ({verdict})" if verdict != "fail" else name)
        return ("killed" if mutant.task in failed else "survived"), failed
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def lab_mutants(folder, args, answers=()):
    """{(file, task): [mutants]} for every task block of the lab's sources, with the listed
    wrong answers of its tasks (always tried; a generated mutant that is one becomes "sheet")."""
    found, sheet = {}, {}
    for source in sorted((ROOT / "labs" / folder).rglob("*")):
        if source.suffix not in SOURCE_SUFFIXES:
            continue
        regions = task_regions(source)
        if not regions:
            continue
        relative = source.relative_to(ROOT).as_posix()
        if source.suffix != ".cpp":
            print(f"check-mutants: {relative}: task blocks in a header are not mutated (only .cpp files are)")
            continue
        lines = source.read_text(encoding="utf-8").splitlines()
        for region in regions:
            mutants = mutants_of_region(source, relative, region, lines)
            found.setdefault((relative, region.task), []).extend(mutants)
            sheet.setdefault((relative, region.task), []).extend(
                wrong_answer_mutant(relative, region, lines, *answer[2:])
                for answer in answers if (answer[0], answer[1]) == (relative, region.task))
    chosen = {}
    for key, mutants in found.items():
        answers_here = sheet.get(key, [])
        texts = {m.text for m in answers_here}
        picked = [m for m in choose([m for m in mutants if m.text not in texts], args, *key)]
        chosen[key] = picked + answers_here
    for (file, _), mutants in sheet.items():
        for mutant in mutants:
            if (file, mutant.task) not in found:
                raise Refusal(f"{WRONG_ANSWERS.name}: {file} has no task {mutant.task}")
    return chosen


def check_lab(build, folder, lab, args, commands, equivalents, scratch_root, rows, answers=()):
    by_task = lab_mutants(folder, args, answers)
    if args.list:
        for (file, task), mutants in by_task.items():
            for m in mutants:
                print(f"{file}:{m.line} task {task} {m.kind}: {m.original!r} -> {m.mutated!r}")
        return
    subprocess.run(["cmake", "--build", str(build), "--target", f"{lab}_tests", "--parallel", str(min(args.jobs, 2))],
                   check=True, stdout=subprocess.DEVNULL)
    rig = LabRig(build, folder, lab, args.timeout)
    baseline = rig.run_tests(rig.program)
    broken = [name for name, verdict in baseline.items() if verdict != "pass"]
    if broken:
        raise Refusal(f"{lab}: the solution fails {', '.join(broken)}; mutants mean nothing until it passes")
    stripped = {}
    for file in sorted({file for file, _ in by_task}):
        entry = compile_entry(commands, ROOT / file, lab)
        member = Path(option_value(shlex.split(entry["command"]), "-o")[1]).name
        copy = scratch_root / f"{lab}-{member}.a"
        shutil.copyfile(rig.archive, copy)
        subprocess.run(["ar", "d", str(copy), member], check=True)
        stripped[file] = (entry, copy)
    jobs = [(m, *stripped[m.file]) for mutants in by_task.values() for m in mutants]
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(grade_mutant, rig, m, entry, copy, scratch_root) for m, entry, copy in jobs]
        for (mutant, _, _), future in zip(jobs, futures):
            outcome, failed = future.result()
            reason = equivalents.get(mutant.key()) if mutant.kind != "sheet" else None
            if outcome == "survived" and reason:
                outcome = "equivalent"
            # A test of no task (a Level or helper suite) costs no task's mark: not collateral.
            other = sorted(name for task, names in failed.items()
                           if task not in (mutant.task, None) for name in names)
            rows.append({"lab": folder, "file": mutant.file, "task": mutant.task, "line": mutant.line,
                         "kind": mutant.kind, "original": mutant.original, "mutated": mutant.mutated,
                         "occurrence": mutant.occurrence, "outcome": outcome,
                         "own_failed": len(failed.get(mutant.task, [])), "collateral": " ".join(other),
                         "listed_equivalent": reason or ""})


def summarise(rows, threshold):
    """Per task: mutants, killed, survived, equivalent, did-not-compile, kill rate, collateral."""
    tasks = {}
    for row in rows:
        t = tasks.setdefault((row["lab"], row["task"]), {
            "lab": row["lab"], "task": row["task"], "mutants": 0, "killed": 0, "survived": 0,
            "equivalent": 0, "did_not_compile": 0, "collateral": 0})
        t["mutants"] += 1
        t[row["outcome"].replace("-", "_")] += 1
        t["collateral"] += bool(row["collateral"])
    for t in tasks.values():
        counted = t["killed"] + t["survived"]
        t["percent"] = round(100.0 * t["killed"] / counted, 1) if counted else 100.0
        t["ok"] = t["percent"] >= threshold and t["collateral"] == 0
    return [tasks[key] for key in sorted(tasks)]


def write_outputs(out, rows, tasks):
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "mutants.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]) if rows else ["lab"])
        writer.writeheader()
        writer.writerows(rows)
    fields = ["lab", "task", "mutants", "killed", "survived", "equivalent", "did_not_compile", "percent", "collateral", "ok"]
    with open(out / "tasks.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.DictWriter(handle, fieldnames=fields)
        writer.writeheader()
        writer.writerows(tasks)
    with open(out / "tasks.json", "w", encoding="utf-8") as handle:
        json.dump({"tasks": tasks}, handle, indent=2)
        handle.write("\n")


def print_table(tasks):
    print(f"{'LAB':<26} {'TASK':>4} {'MUTANTS':>7} {'KILLED':>6} {'SURVIVED':>8} {'EQUIV':>5} "
          f"{'NO-BUILD':>8} {'%':>6} {'COLLATERAL':>10}")
    for t in tasks:
        print(f"{t['lab']:<26} {t['task']:>4} {t['mutants']:>7} {t['killed']:>6} {t['survived']:>8} "
              f"{t['equivalent']:>5} {t['did_not_compile']:>8} {t['percent']:>6.1f} {t['collateral']:>10}"
              f"{'' if t['ok'] else '   <- FAILS'}")


def main(argv):
    try:
        args = parse_arguments(argv)
        build = Path(args.build).resolve()
        if not (build / "CMakeCache.txt").exists() or not (build / "compile_commands.json").exists():
            raise Refusal(f"{args.build} is not a configured build folder with compile_commands.json "
                          "(run: cmake --preset debug)")
        labs = chosen_labs(args.labs)
        equivalents = read_equivalents(args.equivalents)
        answers = read_wrong_answers(WRONG_ANSWERS)
        commands = json.loads((build / "compile_commands.json").read_text(encoding="utf-8"))
    except (Refusal, MarkerError) as problem:
        print(f"check-mutants: {problem}", file=sys.stderr)
        return 2
    out = Path(args.out) if args.out else build / "check-mutants"
    rows = []
    started = time.monotonic()
    scratch_root = Path(tempfile.mkdtemp(prefix="check-mutants-"))
    try:
        for folder, lab in labs:
            before = len(rows)
            check_lab(build, folder, lab, args, commands, equivalents, scratch_root, rows, answers)
            if not args.list:
                print(f"check-mutants: {folder}: {len(rows) - before} mutants graded "
                      f"({time.monotonic() - started:.0f} s so far)", flush=True)
    except (Refusal, MarkerError) as problem:
        print(f"check-mutants: {problem}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("check-mutants: interrupted; the sources were never changed", file=sys.stderr)
        return 130
    finally:
        shutil.rmtree(scratch_root, ignore_errors=True)
    if args.list:
        return 0
    tasks = summarise(rows, args.threshold)
    write_outputs(out, rows, tasks)
    print()
    print_table(tasks)
    print(f"\ncheck-mutants: {len(rows)} mutants in {time.monotonic() - started:.0f} s; "
          f"tables in {out}/tasks.csv, tasks.json, mutants.csv")
    problems = []
    survivors = [row for row in rows if row["outcome"] == "survived"]
    for row in rows:
        if row["collateral"]:
            problems.append(f"{row['file']}:{row['line']} task {row['task']} ({row['outcome']}) "
                            f"{row['original']!r} -> {row['mutated']!r} also fails {row['collateral']}")
    for row in rows:
        if row["kind"] == "sheet" and row["outcome"] != "killed" and row["outcome"] != "did-not-compile":
            problems.append(f"{row['file']} task {row['task']}: the wrong answer {row['mutated']!r} in place of "
                            f"{row['original']!r} is not caught by the task's tests")
        elif row["kind"] == "sheet" and row["outcome"] == "did-not-compile":
            problems.append(f"{row['file']} task {row['task']}: the listed wrong answer in place of "
                            f"{row['original']!r} does not compile (fix the list)")
    for t in tasks:
        if t["percent"] < args.threshold:
            problems.append(f"{t['lab']} task {t['task']}: {t['percent']} % killed, below {args.threshold:g} %")
    if survivors:
        print("\nSurvivors (kill each with a test, or list it with its reason in "
              f"{Path(args.equivalents).relative_to(ROOT) if Path(args.equivalents).is_absolute() else args.equivalents}):")
        writer = csv.writer(sys.stdout, lineterminator="\n")
        for row in survivors:
            writer.writerow([row["file"], row["task"], row["original"], row["mutated"], row["occurrence"], "REASON"])
    if problems:
        print("\ncheck-mutants: FAILED", file=sys.stderr)
        for problem in problems:
            print(f"  - {problem}", file=sys.stderr)
        return 1
    print("check-mutants: every task kills enough of its mutants, and each costs its own task only")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
