"""Builds lab folders written for the course's own framework and runs each one, to prove that
course lab code of both generations builds and runs on Hitbox unchanged.

    ./scripts/check-course-labs.sh                    every folder in tests/course/
    ./scripts/check-course-labs.sh ~/labs/Week8 ...   your own lab folders
    ./scripts/check-course-labs.sh --screenshots DIR  keep what each window showed
    (the same: python3 scripts/lab.py check-course-labs ...; a relative folder is taken from
    the checkout's top)

Each folder is built as `cmake -DHITBOX_COURSE_LAB_DIR=<folder>` (see docs/course-labs.md), then
run for a few seconds under Xvfb and photographed. A lab passes when it builds, is still
running when it is closed, every picture, font and sound it asked for loaded, the picture is
not blank (more than the screen's black and one clear colour), and its output is not flooded
(no sound device must cost one line, not thousands). A folder may hold check-course-lab.txt,
saying what else it must do (Expectations in scripts/labtool/courselabs.py). 2019-24 labs need SFML 2 and 2025-26
labs SFML 3: a lab whose SFML is not installed here is built and run in the Debian unstable
root (scripts/sid-root.sh, SFML 3), shown on this machine's Xvfb; such a folder must be
inside this checkout.

Exit status: 0 every lab passed (or was skipped), 1 one failed, 2 a tool is missing or bad
input.
"""
import os
import re
import shutil
import subprocess
import sys
from collections import Counter
from dataclasses import dataclass
from glob import glob
from pathlib import Path

from .labs import REPO

SECONDS_TO_RUN = 4
SCREEN = "1920x1920"  # Xvfb's screen, photographed whole (a lab may open a window half its size)
# A flood, not a chatty lab: a lab printing a line every frame writes about 240 lines in four
# seconds; OpenAL Soft with no sound device wrote 2.6 million (week10_sound_effects, unsilenced).
MOST_OUTPUT_LINES = 1000
BLANK_COLOURS = 2  # the screen's black and the window's clear colour: nothing drawn
INSIDE_ROOT = ["scripts/sid-root.sh", "run"]  # runs a command in the Debian unstable root (SFML 3)
EXPECTATIONS_FILE = "check-course-lab.txt"
WINDOW_RUNNER = Path(__file__).resolve().with_name("courselab_window.py")
# ffmpeg grabs the Xvfb screen and xdotool holds the mouse down for the folders that ask for
# it; only this check needs them, so students' install-deps leaves them out.
INSTALLED_HERE_IF_MISSING = ("ffmpeg", "xdotool")
NEEDED_TOOLS = ("xvfb-run", "ffmpeg", "xdotool")

GO, DONE, FAIL = "go", "done", "fail"  # a lab's verdict after a step: run it next, finished, failed


@dataclass
class Expectations:
    """What a folder's check-course-lab.txt asks, one a line (# starts a comment):
        cmake: -DNAME=VALUE          an option for its configure step
        configure says: TEXT         a line the configure step must print
        build fails                  it must not build (the configure lines still count)
        hold the mouse at: X Y       hold the left button down there from the second second
        run says: TEXT               a line the program must print"""
    cmake: list
    configure_says: list
    run_says: list
    mouse_at: str  # "X Y", or "" for no mouse
    build_fails: bool


@dataclass
class Place:
    """Where one lab is built and run: here, or in the Debian unstable root."""
    name: str
    generation: str  # "2019" or "2025", as HitboxCourseLab.cmake decides it
    sfml_major: int
    inside: list  # the command prefix: [] here, INSIDE_ROOT in the root
    build: str  # the build folder, relative to the checkout (one per SFML major)
    launcher: str  # ccache here, none in the root
    lab_path: str  # the folder as the build sees it


def say(text):
    print(text, flush=True)


def complain(text):
    print(text, file=sys.stderr, flush=True)


def echo_bytes(stream, data):
    """Writes a log's own bytes to stdout or stderr, after what was printed before them."""
    stream.flush()
    stream.buffer.write(data)
    stream.buffer.flush()


def log_lines(data):
    """A log's lines as grep, sort and tail see them (split at newlines only), each with its end."""
    return re.findall(rb"[^\n]*\n|[^\n]+\Z", data)


def stripped(line):
    return line[:-1] if line.endswith(b"\n") else line


def output_of(command):
    """A command's output without its final newlines; a failure ends the whole check with its
    status, as any step the check cannot go on without."""
    done = subprocess.run(command, stdout=subprocess.PIPE)
    if done.returncode != 0:
        sys.exit(done.returncode)
    return done.stdout.decode("utf-8", "surrogateescape").rstrip("\n")


def read_expectations(folder):
    path = Path(folder) / EXPECTATIONS_FILE
    lines = []
    if path.is_file():
        lines = path.read_bytes().decode("utf-8", "surrogateescape").split("\n")
        if lines[-1] == "":
            lines.pop()

    def values(key):  # every value given for KEY, in order ("KEY:" then spaces)
        return [line[len(key) + 1:].lstrip(" ") for line in lines if line.startswith(key + ":")]
    return Expectations(cmake=values("cmake"), configure_says=values("configure says"),
                        run_says=values("run says"), mouse_at="\n".join(values("hold the mouse at")),
                        build_fails="build fails" in lines)


def sfml_major_installed():
    """The SFML major version pkg-config finds here, "0" for none."""
    try:
        done = subprocess.run(["pkg-config", "--modversion", "sfml-graphics"], stdout=subprocess.PIPE,
                              stderr=subprocess.DEVNULL, text=True)
    except OSError:
        return "0"
    version = done.stdout.rstrip("\n") if done.returncode == 0 else "0"
    return version.split(".")[0]


def hitbox_builds_on_sfml3():
    """Hitbox's SFML 3 port is in: HitboxSFML.cmake accepts SFML 3 and the maths layer is marked
    free of SFML types."""
    def text(path):
        try:
            return (REPO / path).read_text(encoding="utf-8", errors="replace")
        except OSError:
            return ""
    return ("SFML 3" in text("framework/cmake/HitboxSFML.cmake")
            and re.search(r"^hitbox_layer\(geometry +NO_SFML", text("framework/CMakeLists.txt"), re.M) is not None)


def place_lab(lab, sfml_major_here):
    """(verdict, Place): where LAB is built and run; FAIL and DONE (skipped) said why on one line."""
    name = Path(lab).name or lab
    if not os.path.isfile(f"{lab}/Main.cpp"):
        complain(f"FAIL {name}: not a lab folder (no Main.cpp in it)")
        return FAIL, None
    # The generation decides the SFML major; the build says the same (HitboxCourseLab.cmake).
    generation = output_of(["cmake", f"-DHITBOX_PRINT_GENERATION_OF={lab}", "-P",
                            "framework/cmake/HitboxCourseLab.cmake"])
    sfml_major = 3 if generation == "2025" else 2
    place = Place(name=name, generation=generation, sfml_major=sfml_major, inside=[],
                  build=f"build/course-sfml{sfml_major}", launcher=shutil.which("ccache") or "",
                  lab_path=os.path.abspath(lab))
    if str(sfml_major) == sfml_major_here:
        return GO, place
    # In the root this checkout is /hitbox, so the folder is named from the checkout's top.
    place.inside, place.build, place.launcher = INSIDE_ROOT, "build/sid-course", ""
    place.lab_path = os.path.relpath(os.path.realpath(lab), os.path.realpath("."))
    if sfml_major != 3 or place.lab_path.startswith("../"):
        complain(f"FAIL {name}: needs SFML {sfml_major}, not installed here "
                 "(only folders inside this checkout can use scripts/sid-root.sh)")
        return FAIL, None
    # A 2025-26 lab needs Hitbox's SFML 3 port; until it is in, say so on one line rather than
    # fail or pass in silence.
    if not hitbox_builds_on_sfml3():
        complain(f"SKIP {name}: a 2025-26 lab; Hitbox does not build on SFML 3 yet")
        return DONE, None
    return GO, place


def remove(path):
    if os.path.islink(path) or os.path.isfile(path):
        os.unlink(path)
    elif os.path.isdir(path):
        shutil.rmtree(path)


def run_logged(command, log):
    """Exit status of COMMAND, its output (both streams) in LOG."""
    with open(log, "wb") as out:
        return subprocess.run(command, stdout=out, stderr=subprocess.STDOUT).returncode


def build_lab(place, expected):
    """Configures and builds one lab: GO (built: run it), DONE (it must not build and did not)
    or FAIL (one FAIL line said why)."""
    name, build = place.name, place.build
    say(f"== {name} ({place.generation}-generation course framework, SFML {place.sfml_major}): build")
    # One build folder per SFML major: the framework is compiled once. The converted copies of
    # the previous lab's files and its run folder are removed so nothing is picked up by mistake.
    remove(f"{build}/course_lab_sources")
    remove(f"{build}/course_lab_run")
    os.makedirs(build, exist_ok=True)
    # The lab's own Framework/ files to build are named afresh for every folder.
    configured = run_logged([*place.inside, "cmake", "-S", ".", "-B", build,
                             f"-DHITBOX_COURSE_LAB_DIR={place.lab_path}", "-DHITBOX_BUILD_TESTS=OFF",
                             "-DHITBOX_BUILD_BENCHMARKS=OFF", "-DHITBOX_COURSE_LAB_OWN_FRAMEWORK=",
                             f"-DCMAKE_CXX_COMPILER_LAUNCHER={place.launcher}", *expected.cmake],
                            f"{build}/configure.log")
    configure_lines = log_lines(Path(f"{build}/configure.log").read_bytes())
    missing = False
    for wanted in expected.configure_says:
        found = [line for line in configure_lines if os.fsencode(wanted) in line]
        echo_bytes(sys.stdout, b"".join(found))
        if not found:
            complain(f'FAIL {name}: configure did not say "{wanted}" ({build}/configure.log)')
            missing = True
    if missing:
        return FAIL
    built = 0
    if configured == 0:
        built = run_logged([*place.inside, "cmake", "--build", build, "--target", "course_lab", "-j", "2"],
                           f"{build}/build.log")
    if expected.build_fails:
        if configured == 0 and built == 0:
            complain(f"FAIL {name}: built, but it should not (the project leaves out a file it needs)")
            return FAIL
        say(f"ok   {name} (does not build, as in Visual Studio, and configure said so)")
        return DONE
    if configured != 0 or built != 0:
        if os.path.isfile(f"{build}/build.log"):
            echo_bytes(sys.stderr, b"".join(log_lines(Path(f"{build}/build.log").read_bytes())[-30:]))
        complain(f"FAIL {name}: does not build (logs: {build}/configure.log, {build}/build.log)")
        return FAIL
    described = [line for line in configure_lines if re.search(rb"Course lab: .*course framework", line)]
    echo_bytes(sys.stdout, b"".join(described[:1]))
    return GO


def count_colours(shot):
    """Distinct colours in the screenshot, shrunk to 480 pixels wide (nearest neighbour: no new
    colours); ffmpeg failing to read it ends the check with its status."""
    done = subprocess.run(["ffmpeg", "-loglevel", "error", "-i", shot, "-vf", "scale=480:-1:flags=neighbor",
                           "-f", "rawvideo", "-pix_fmt", "rgb24", "-"], stdout=subprocess.PIPE)
    if done.returncode != 0:
        sys.exit(done.returncode)
    pixels = done.stdout
    return len({pixels[i:i + 3] for i in range(0, len(pixels), 3)})


def most_printed(lines, count):
    """`sort | uniq -c | sort -rn | head -n COUNT` of the lines: the most repeated first."""
    tally = Counter(stripped(line) for line in lines)
    ranked = sorted(tally.items(), key=lambda item: (item[1], item[0]), reverse=True)[:count]
    return b"".join(b"%7d %s\n" % (times, line) for line, times in ranked)


def run_lab(place, expected, screenshots):
    """Runs the built lab under Xvfb for SECONDS_TO_RUN seconds, photographs it and checks what
    it printed and drew: DONE (ok) or FAIL (one FAIL line said why)."""
    name, build = place.name, place.build
    say(f"== {name}: run for {SECONDS_TO_RUN} seconds")
    shot = f"{screenshots or os.path.join(os.getcwd(), build)}/{name}.png"
    log = f"{build}/run.log"
    if os.path.lexists(shot):
        os.unlink(shot)
    # Start the lab, let it run, photograph the screen, then close it (courselab_window.py). The
    # X server accepts any local client (-ac), so a program in the Debian root can use it too,
    # and does not reset when its last client leaves (-noreset: a lab that asks the desktop's
    # size before opening its window connects twice, and a resetting server refuses the second
    # connection, which a real desktop never does).
    window = subprocess.run(["xvfb-run", "-a", "-s", f"-screen 0 {SCREEN}x24 -ac -noreset", sys.executable,
                             str(WINDOW_RUNNER), SCREEN, build, str(SECONDS_TO_RUN), shot, log, expected.mouse_at,
                             *place.inside])
    if window.returncode != 0:
        complain(f"FAIL {name}: did not keep running")
        return FAIL
    output = Path(log).read_bytes()
    lines, printed = log_lines(output), output.count(b"\n")
    # First the flood (its lines would bury everything else).
    if printed > MOST_OUTPUT_LINES:
        echo_bytes(sys.stderr, most_printed(lines, 3))
        complain(f"FAIL {name}: printed {printed} lines in {SECONDS_TO_RUN} seconds (output: {log})")
        return FAIL
    # SFML says when a picture, font or sound does not load (a white box, no text, silence).
    not_loaded = [line for line in lines if re.search(rb"Failed to (load|open)", line)]
    if not_loaded:
        echo_bytes(sys.stderr, b"".join(not_loaded))
        complain(f"FAIL {name}: a file did not load (output: {log})")
        return FAIL
    missing = False
    for wanted in expected.run_says:
        if not any(os.fsencode(wanted) in line for line in lines):
            complain(f'FAIL {name}: did not print "{wanted}" (output: {log})')
            missing = True
    if missing:
        return FAIL
    # Blank: nothing but the screen's black and the window's clear colour.
    colours = count_colours(shot)
    if colours <= BLANK_COLOURS:
        complain(f"FAIL {name}: the window stayed blank ({colours} colours; screenshot: {shot})")
        return FAIL
    say(f"ok   {name} (screenshot: {shot}, {colours} colours)")
    return DONE


def install_missing_tools():
    """As root on Debian, installs this check's own tools; then 2 if one is still missing."""
    for tool in INSTALLED_HERE_IF_MISSING:
        if not shutil.which(tool) and shutil.which("apt-get") and os.geteuid() == 0:
            done = subprocess.run(["apt-get", "-o", "DPkg::Lock::Timeout=600", "install", "-y", "-qq",
                                   "--no-install-recommends", tool], stdout=subprocess.DEVNULL,
                                  env={**os.environ, "DEBIAN_FRONTEND": "noninteractive"})
            if done.returncode != 0:
                sys.exit(done.returncode)
    for tool in NEEDED_TOOLS:
        if not shutil.which(tool):
            complain(f"check-course-labs: needs {tool} (./scripts/install-deps.sh; apt-get install ffmpeg)")
            return 2
    return 0


def parse(arguments):
    """(screenshots folder or "", lab folders, exit status or None); every word not an option is
    a folder."""
    screenshots, labs = "", []
    words = list(arguments)
    while words:
        word = words.pop(0)
        if word == "--screenshots":
            if not words:
                complain("check-course-labs: --screenshots needs a folder")
                return "", [], 2
            try:
                os.makedirs(words[0], exist_ok=True)
            except OSError as error:
                complain(f"check-course-labs: --screenshots {words[0]}: {error.strerror}")
                return "", [], 2
            screenshots = os.path.abspath(words.pop(0))
        elif word in ("-h", "--help"):
            say(__doc__.split("\n\nExit status")[0])
            return "", [], 0
        else:
            labs.append(word)
    return screenshots, labs, None


def run(arguments):
    os.chdir(REPO)  # folders and --screenshots are taken from the checkout's top
    screenshots, labs, status = parse(arguments)
    if status is not None:
        return status
    if not labs:
        labs = [folder.rstrip("/") for folder in sorted(glob("tests/course/*/"))]
    status = install_missing_tools()
    if status:
        return status
    sfml_major_here = sfml_major_installed()
    failed = 0
    for lab in labs:
        verdict, place = place_lab(lab, sfml_major_here)
        if verdict == GO:
            expected = read_expectations(lab)
            verdict = build_lab(place, expected)
            if verdict == GO:
                verdict = run_lab(place, expected, screenshots)
        if verdict == FAIL:
            failed = 1
    return failed
