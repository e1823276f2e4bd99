"""lab.py grade-class and lab.py gradescope: grading submissions against the instructor's tree.

From a submission only the files a student edits are taken (the lab sources with a task
marker in the solution); everything else is the instructor's, and the feedback lists what was
ignored. A submission holding a symbolic link is refused. Each submission gets a fresh
scratch folder, deleted when it is done: nothing it did reaches the next one or a re-grade.
Its files and the tests are compiled in the cage (sandbox.py), seeing the framework, the
tests and its own lab folder only, under the compile limits; its objects are then read
(inspect.py) and refused, with one line, if they could decide their own verdict; the program
is linked with the instructor's objects, and each instructor test runs caged in a process of
its own and is judged by engine.py. The list of tests comes from the instructor's build.
"""
import concurrent.futures
import hashlib
import json
import os
import queue
import shlex
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import traceback
import zipfile  # (BadZipFile: a broken upload)
from pathlib import Path

from . import cmakeapi, engine, inspect, limits, procs, reports, sandbox
from .submission import Refused, find, printable_name, submission_name, unpack
from .labs import REPO, BadInput, all_labs, find_lab, is_handout

FAST_LINKER = next(([f"-fuse-ld={name}"] for name in ("lld", "gold") if shutil.which(f"ld.{name}")), [])


def run_checked(command, **kwargs):
    return subprocess.run(command, check=True, **kwargs)


# --- The instructor's build -------------------------------------------------------------

def prepare(build_dir, labs, jobs):
    """Builds the framework and every lab's tests (solution) once; reads what to compile."""
    build_dir = Path(build_dir).resolve()
    launcher = ["ccache"] if shutil.which("ccache") else []
    env = dict(os.environ)
    if launcher:
        env.setdefault("CCACHE_BASEDIR", str(REPO.parent))
    if not (build_dir / "CMakeCache.txt").exists():
        configure = ["cmake", "-S", str(REPO), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Debug",
                     "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON", "-DHITBOX_BUILD_BENCHMARKS=OFF",
                     "-DHITBOX_WARNINGS_AS_ERRORS=OFF"]  # a student's unused variable warns only
        if launcher:
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        run_checked(configure, env=env, stdout=subprocess.DEVNULL)
    elif not (build_dir / "compile_commands.json").exists():
        run_checked(["cmake", "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON", str(build_dir)], env=env, stdout=subprocess.DEVNULL)
    commands = None
    for lab in labs:
        # One lab at a time: in a handout (GitHub Classroom) the lab code is the student's, and a
        # lab that does not compile must cost that lab only.
        targets = [f"{lab.name}_tests"] + ([] if is_handout() else [f"{lab.name}_exercise_level"])
        built = subprocess.run(["cmake", "--build", str(build_dir), "--parallel", str(jobs), "--target", *targets],
                               env=env, capture_output=True, text=True, errors="replace")
        lab.broken = ""
        if built.returncode != 0:
            if not is_handout():
                sys.stderr.write(built.stdout[-6000:] + built.stderr[-6000:])
                raise RuntimeError(f"the instructor's {lab.name}_tests does not build (the messages are above)")
            lab.broken = "did not build"
        commands = commands or json.loads((build_dir / "compile_commands.json").read_text())
        program = build_dir / "tests" / lab.folder / f"{lab.name}_tests"
        if lab.broken:
            lab.tests = lab.visible_tests()
        else:
            listing = subprocess.run([str(program), "--gtest_list_tests"], check=True, text=True,
                                     capture_output=True, env=engine.test_environment(), timeout=limits.LIST_SECONDS).stdout
            lab.tests = engine.list_tests(listing)
        lab.tasks_for_grading = lab.tasks()
        lab.hidden = lab.hidden_tests()
        lab.compile = [c for c in commands if f"CMakeFiles/{lab.name}_level.dir/" in c["command"]
                       or f"CMakeFiles/{lab.name}_tests.dir/" in c["command"]]
        lab.link = cmakeapi.link_command(build_dir, f"{lab.name}_tests")
        lab.level_archive = f"lib{lab.name}_level.a"
        archives = [lab.link.path(a) for a in lab.link.libraries  # and shared ones: SFML's
                    if (a.endswith(".a") or ".so" in Path(a).name) and not a.endswith(lab.level_archive)]
        lab.harness = inspect.harness_symbols(tuple(str(a) for a in archives if a.is_file()))
    return build_dir, launcher


# --- One submission ------------------------------------------------------------------------

HEADER_SUFFIXES = (".h", ".hpp", ".inl")


def headers_only(folder, lab_copy):
    """A copy of folder's headers (nothing else) beside the submission's lab copy."""
    copy = lab_copy.parent.parent / "headers-only" / folder.name
    if not copy.is_dir():
        for header in folder.rglob("*"):
            if header.suffix in HEADER_SUFFIXES and header.is_file() and not header.is_symlink():
                target = copy / header.relative_to(folder)
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(header, target)
        copy.mkdir(parents=True, exist_ok=True)
    return copy


def compile_caged(arguments, lab, lab_copy, output, cwd, log, caged, what, tests_visible):
    """One compiler run (caged unless caged is False); returns "" or why it failed."""
    if caged:
        read_only = {lab_copy}
        for index, argument in enumerate(arguments):
            folder = argument[2:] if argument.startswith("-I") else None
            if argument == "-isystem" and index + 1 < len(arguments):
                folder = arguments[index + 1]
            if folder and Path(folder).is_dir() and not Path(folder).resolve() == (REPO / lab.folder).resolve():
                read_only.add(Path(folder).resolve())
        read_only = {f for f in read_only if tests_visible or not str(f).startswith(str(REPO / "tests"))}
        # Another lab's folder (labs 02 and 03 include lab 0's header) holds the instructor's
        # solutions: the cage gets a copy of its headers only, at the same path.
        read_only = {(headers_only(f, lab_copy), f) if f.is_relative_to(REPO / "labs") else f for f in read_only}
        writable = {output.parent}
        ccache_dir = os.environ.get("CCACHE_DIR") or str(Path.home() / ".cache" / "ccache")
        if arguments[0] == "ccache" and Path(ccache_dir).is_dir():
            writable.add(Path(ccache_dir))
        source = Path(arguments[arguments.index("-c") + 1])
        read_only.add(source.parent)
        command = sandbox.compile_command(arguments, sorted(read_only, key=str), sorted(writable), cwd)
    else:
        command = procs.prlimit_prefix(limits.COMPILE_MEMORY, limits.COMPILE_FILE_BYTES, limits.COMPILE_SECONDS) + arguments
    out = output.parent / (output.name + ".log")
    # Every path in the scratch folder becomes relative to the lab copy, which lies equally
    # deep in every submission's scratch: ccache then finds what another submission (or an
    # earlier run) compiled from the same text (an untouched starter file, the same headers).
    scratch_root = Path(lab_copy).parents[len(Path(lab.folder).parts) + 2]
    outcome = procs.run_limited(command, out, limits.COMPILE_WALL_SECONDS, cwd=cwd,
                                env=dict(os.environ, CCACHE_NOHASHDIR="1", CCACHE_BASEDIR=str(scratch_root)))
    log.append(outcome.output)
    out.unlink(missing_ok=True)
    if caged and outcome.status > 128:
        outcome.status = 128 - outcome.status  # the cage reports a signal as 128 + n
    stopped = procs.why_stopped(outcome, limits.COMPILE_SECONDS, limits.COMPILE_FILE_BYTES, what=f"compiling {what}",
                                wall_seconds=limits.COMPILE_WALL_SECONDS)
    if stopped:
        return stopped.replace("(an endless loop?)", "").strip()
    if outcome.status != 0:
        if any(s in outcome.output for s in ("memory exhausted", "out of memory", "std::bad_alloc", "Cannot allocate")):
            return f"compiling {what} used more than {limits.megabytes(limits.COMPILE_MEMORY)} of memory"
        return "did not build"
    return ""


def grade_lab(lab, files, root, work, used, launcher, shared_dir, slot, deadline, caged):
    """Builds the lab's tests against the student's files and runs every instructor test."""
    def all_failed(reason, notes=(), message=""):
        return {"results": [engine.TestResult(t, False, reason, message) for t in lab.tests],
                "reason": reason, "notes": list(notes)}

    if not any(find(lab, relative, files) for relative in lab.student_files):
        return all_failed("not submitted", [f"none of the lab's files ({', '.join(lab.student_files)}) is in the submission"])
    lab_copy = work / "src" / lab.folder  # the instructor's lab folder with the student's files in it
    shutil.copytree(REPO / lab.folder, lab_copy, symlinks=True)
    notes = []
    starter_dir = lab.starter_dir
    for relative in lab.student_files:
        found = find(lab, relative, files)
        if found is None:
            shutil.copy(starter_dir / relative, lab_copy / relative)
            notes.append(f"`{relative}` was not in the submission: graded the starter code")
            continue
        used.add(found)
        shutil.copyfile(root / found, lab_copy / relative, follow_symlinks=False)

    # Only the student's own .cpp files are compiled for every submission; the tests and the
    # lab's other sources depend on them only through the headers among them, so they are
    # compiled once per distinct set of those headers (shared within this run) or, when the
    # headers are the instructor's, taken from the instructor's build.
    header_names = [r for r in lab.student_files if not r.endswith(".cpp")]
    headers = "".join((lab_copy / r).read_text(errors="replace") for r in header_names)
    headers_key = hashlib.sha256(headers.encode()).hexdigest()[:16]
    unchanged = headers == "".join((REPO / lab.folder / r).read_text(errors="replace") for r in header_names)
    own = {str(REPO / lab.folder / r): r for r in lab.student_files if r.endswith(".cpp")}
    level_objects, test_objects, student_objects, log = [], [], {}, []
    started = time.monotonic()
    for entry in lab.compile:
        arguments = [a for a in shlex.split(entry["command"]) if a != "-Werror"]
        for flag in ("-MT", "-MF", "-MQ"):
            while flag in arguments:
                del arguments[arguments.index(flag):arguments.index(flag) + 2]
        arguments = [a for a in arguments if a not in ("-MD", "-MMD")]
        source = arguments[arguments.index("-c") + 1]
        arguments = [a.replace(str(REPO / lab.folder), str(lab_copy)) for a in arguments]
        output_index = arguments.index("-o") + 1
        original = arguments[output_index]
        is_test = f"{lab.name}_tests.dir" in original
        if time.monotonic() > deadline:
            return all_failed(f"not run: the submission used up its {limits.SUBMISSION_SECONDS} s", notes)
        if source in own:
            output = work / "objects" / original
            output.parent.mkdir(parents=True, exist_ok=True)
            arguments[output_index] = str(output)
            why = compile_caged(launcher + arguments, lab, lab_copy, output, lab_copy, log, caged,
                                f"`{own[source]}`", tests_visible=False)
            student_objects[own[source]] = output
        elif unchanged:
            output, why = Path(entry["directory"]) / original, ""
        else:
            output = shared_dir / lab.name / headers_key / original
            why = compile_shared(launcher + arguments, output_index, output, lab, lab_copy, entry["directory"], log, caged)
        if why:
            return failed_build(lab, why, log, lab_copy, notes)
        (test_objects if is_test else level_objects).append(str(output))
    seconds = {"compile": time.monotonic() - started}
    harness = lab.harness | inspect.harness_symbols(tuple(test_objects + [o for o in level_objects
                                                                          if o not in map(str, student_objects.values())]))
    refused = inspect.refusal(student_objects, harness)
    if refused:
        return all_failed(f"refused: {refused}", notes)
    program = work / "run" / f"{lab.name}_tests"
    program.parent.mkdir(parents=True, exist_ok=True)
    # The instructor's link command with the objects built here: the test objects first (as
    # before the flags), the lab's own objects where its archive was, the program in the
    # scratch. The student's objects come last, then the libraries again for what they use:
    # where the student's code and the instructor's both define a weak (inline, template)
    # symbol, the linker keeps the first copy it meets, the instructor's.
    students = [str(o) for o in student_objects.values()]
    linked = [lab.link.compiler, *FAST_LINKER, *test_objects, *lab.link.flags, "-o", str(program)]
    for library in lab.link.libraries:
        linked += [o for o in level_objects if o not in students] if library.endswith(lab.level_archive) else [library]
    linked += students + [library for library in lab.link.libraries if not library.endswith(lab.level_archive)]
    outcome = procs.run_limited(linked, work / "link.log", limits.LINK_SECONDS, cwd=lab.link.directory)
    log.append(outcome.output)
    if outcome.status != 0 or outcome.timed_out:
        return failed_build(lab, "did not build", log, lab_copy, notes)
    program.chmod(0o755)
    sandbox.open_path_for_slot(program)
    results = []
    started = time.monotonic()
    for test in lab.tests:
        if time.monotonic() > deadline:
            results.append(engine.TestResult(test, False, f"not run: the submission used up its {limits.SUBMISSION_SECONDS} s"))
            continue
        results.append(engine.run_test(program, test, work / "run", slot if caged else None, threaded=True))
    seconds["tests"] = time.monotonic() - started
    return {"results": results, "notes": notes, "seconds": seconds}


def failed_build(lab, why, log, lab_copy, notes):
    errors = [line for line in "\n".join(log).splitlines()
              if any(k in line for k in ("error", "undefined reference", "multiple definition", "cannot find"))][:20]
    message = "\n".join(errors).replace(str(lab_copy) + "/", "")
    return {"results": [engine.TestResult(t, False, why, message) for t in lab.tests], "reason": why,
            "notes": notes + [f"{why}: no test of this lab ran" + ("" if not message else "\n\n```\n" + message + "\n```")]}


shared_locks, shared_guard = {}, threading.Lock()


def compile_shared(arguments, output_index, output, lab, lab_copy, directory, log, caged):
    """An object every submission with the same headers shares, compiled once per run."""
    with shared_guard:
        lock = shared_locks.setdefault(str(output), threading.Lock())
    with lock:
        if output.is_file():
            return ""
        output.parent.mkdir(parents=True, exist_ok=True)
        arguments = list(arguments)
        arguments[output_index + (1 if arguments[0] == "ccache" else 0)] = str(output) + ".part"
        why = compile_caged(arguments, lab, lab_copy, Path(str(output) + ".part"), lab_copy, log, caged,
                            "the tests with your headers", tests_visible=True)
        if not why:
            os.replace(str(output) + ".part", output)
        return why


def grade_submission(source, labs, scratch_root, launcher, shared_dir, slots, caged):
    name = submission_name(source)
    report = {"student": name, "labs": {}, "ignored": [], "error": None}
    started = time.monotonic()
    slot = slots.get()
    work = Path(tempfile.mkdtemp(prefix=f"{slot}-", dir=scratch_root))  # fresh for this submission only
    work.chmod(0o711)
    try:
        files, listed = unpack(source, work)
        used = set()
        deadline = started + limits.SUBMISSION_SECONDS
        for lab in labs:
            report["labs"][lab.name] = grade_lab(lab, listed, files, work / lab.name, used, launcher,
                                                 shared_dir, slot, deadline, caged)
        report["ignored"] = [f for f in listed if f not in used]
    except (Refused, OSError, subprocess.CalledProcessError, zipfile.BadZipFile, ValueError) as error:
        reason = str(error) if isinstance(error, Refused) else f"not graded: {printable_name(str(error))}"
        report["error"] = reason
        for lab in labs:
            report["labs"][lab.name] = {"results": [engine.TestResult(t, False, reason) for t in lab.tests],
                                        "reason": reason, "notes": []}
    finally:
        shutil.rmtree(work, ignore_errors=True)
        slots.put(slot)
    report["seconds"] = time.monotonic() - started
    return report


def write_student(report, labs, out):
    student = report["student"]
    text = reports.feedback(student, labs, report)
    reports.write_atomically(out / f"{student}.md", text)
    reports.write_atomically(out / f"{student}.junit.xml",
                             reports.junit(student, [(lab.name, report["labs"][lab.name]["results"]) for lab in labs]))
    scope = reports.gradescope(labs, report, text)
    reports.write_atomically(out / f"{student}.results.json", scope)
    rows = []
    for lab in labs:
        rows += reports.gradebook_rows(student, lab, report["labs"][lab.name])
    return rows, scope


def grade(sources, labs, build, out, jobs, caged, gradescope_file=None):
    if caged:
        sandbox.ensure_bubblewrap()
    started = time.monotonic()
    print(f"grade-class: building the framework and the instructor's tests once ({build})", flush=True)
    build, launcher = prepare(build, labs, jobs)
    for lab in labs:
        lab.starter_dir = build / lab.folder / "exercise"
        if not lab.starter_dir.is_dir():
            lab.starter_dir = REPO / lab.folder  # a handout: the lab folder is the starter
    print(f"grade-class: instructor build ready in {time.monotonic() - started:.0f} s; grading "
          f"{len(sources)} submission(s), {jobs} at a time{'' if caged else ' (no cage)'}", flush=True)
    out.mkdir(parents=True, exist_ok=True)
    scratch_root = Path(tempfile.mkdtemp(prefix="hitbox-grading-"))
    scratch_root.chmod(0o711)
    shared_dir = scratch_root / "shared"
    slots = queue.Queue()  # a slot is the user id its caged tests run as
    held = sandbox.claim_users(jobs) if caged else [(number, None) for number in range(jobs)]
    for user, _ in held:
        slots.put(user)
    all_rows, done = [], 0
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            futures = [pool.submit(grade_submission, s, labs, scratch_root, launcher, shared_dir, slots, caged)
                       for s in sources]
            for future in concurrent.futures.as_completed(futures):
                report = future.result()
                rows, scope = write_student(report, labs, out / "students")
                all_rows += rows
                done += 1
                marks = sum(r[5] for r in rows if r[5] != "")
                possible = sum(1 for r in rows if r[5] != "")
                phases = {}
                for graded in report["labs"].values():
                    for phase, seconds in graded.get("seconds", {}).items():
                        phases[phase] = phases.get(phase, 0.0) + seconds
                print(f"[{done}/{len(sources)}] {report['student']}: {marks}/{possible} tasks "
                      f"({report['seconds']:.1f} s{': ' if phases else ''}"
                      f"{', '.join(f'{p} {s:.1f} s' for p, s in phases.items())})"
                      f"{' - ' + report['error'] if report['error'] else ''}", flush=True)
                if gradescope_file:
                    reports.write_atomically(gradescope_file, scope)
    finally:
        shutil.rmtree(scratch_root, ignore_errors=True)
    reports.write_gradebook(out / "grades.csv", all_rows)
    print(f"grade-class: {len(sources)} submission(s) in {time.monotonic() - started:.0f} s; gradebook "
          f"{out / 'grades.csv'}, feedback, JUnit XML and results.json in {out / 'students'}/", flush=True)


def chosen_labs(names):
    labs = all_labs()
    return [find_lab(n, labs) for n in names] if names else labs


def run(options):
    labs = chosen_labs(options.lab)
    jobs = options.jobs or os.cpu_count() or 1
    build = Path(options.build).resolve() if options.build else REPO / "build" / "grading"
    if options.prepare_only:
        prepare(build, labs, jobs)
        print(f"grade-class: instructor build ready in {build}")
        return 0
    sources = []
    for given in map(Path, options.submissions):
        if options.one:
            sources.append(given.resolve())
        elif not given.is_dir():
            raise BadInput(f"{given} is not a folder of submissions")
        else:
            sources += sorted(p.resolve() for p in given.iterdir() if not p.name.startswith("."))
    if not sources:
        raise BadInput("no submissions found")
    named = {}
    for source in sources:
        named.setdefault(submission_name(source), []).append(source.name)
    clashes = [names for names in named.values() if len(names) > 1]
    if clashes:
        raise BadInput(f"two submissions would be graded under one name ({' and '.join(clashes[0])}): "
                       "rename one; nothing was graded")
    try:
        grade(sources, labs, build, Path(options.out).resolve(), jobs, caged=not options.no_cage)
    except sandbox.SandboxUnavailable as error:
        print(f"grade-class: {error} (or grade without it: --no-cage)", file=sys.stderr)
        return 2
    return 0


def run_gradescope(options):
    """Gradescope's run_autograder: always writes results/results.json, with the reason when
    grading itself failed."""
    root = Path(options.root)
    results = root / "results" / "results.json"
    try:
        labs = chosen_labs([(root / "source" / "lab.txt").read_text().strip()])
        if options.prepare_only:
            prepare(root / "build", labs, 2)
            return 0
        try:
            sandbox.ensure_bubblewrap()
            caged = True
        except sandbox.SandboxUnavailable as error:  # Gradescope's container is the cage then
            print(f"gradescope: grading without the sandbox: {error}", flush=True)
            caged = False
        grade([root / "submission"], labs, root / "build", root / "results" / "grading", 2,
              caged=caged, gradescope_file=results)
        return 0
    except BaseException as error:  # noqa: B902 - whatever happened, Gradescope gets a file
        if options.prepare_only:
            raise
        traceback.print_exc()
        reports.write_atomically(results, reports.failed_gradescope(f"{type(error).__name__}: {error}"))
        return 0 if not isinstance(error, KeyboardInterrupt) else 130
