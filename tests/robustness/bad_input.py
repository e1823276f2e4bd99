#!/usr/bin/env python3
"""The bad-input table (issue 19): every program given a hostile command line, level file or
screen answers with ONE line on stderr, exactly as written here, the stated exit code, and
nothing on stdout (no "saved"). Run by CTest in every build, the sanitizer one included.
Usage: bad_input.py BUILD_DIR

The screenshot rows need a display: the whole table runs inside ONE xvfb-run (the other rows
take the display away themselves), so a busy machine starts one X server, not many.
"""
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def header_number(path, pattern):
    """A number read from its one home, a framework header: the table follows it."""
    with open(os.path.join(REPO, path), encoding="utf-8") as header:
        found = re.search(pattern, header.read())
    if not found:
        sys.exit(f"bad_input: {path} has no line matching {pattern}")
    return int(float(found.group(1).replace("'", "")))


# The largest --seconds, and --frames: that many seconds of fixed steps.
MAX_SECONDS = header_number("framework/hitbox/app/Options.h", r"constexpr long long maxSeconds = ([0-9']+);")
MAX_STEPS = MAX_SECONDS * header_number("framework/hitbox/app/Loop.h",
                                        r"constexpr float stepsPerSecond = ([0-9.]+)f;")
NO_DISPLAY = ["env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY"]
# The programs the table runs, by the name of their executable.
PROGRAMS = ("pong", "sandbox", "lab02_bouncing_balls", "lab03_bouncing_squares",
            "lab05_ray_caster", "lab06_rotated_boxes", "lab07_swept_circles",
            "lab08_many_objects", "lab09_platformer")
NO_DISPLAY_FOUND = ("no display found ({}). Run with --headless --frames N to simulate without a "
                    "window, or start it under a display (e.g. xvfb-run -a).")
SHARED_OPTIONS = ("--headless --frames N --seconds S --screenshot FILE.png --debug --seed N "
                  "--record FILE --replay FILE --timeline F.csv --pause-at-step N")
LAB9 = "Lab 9 - Platformer: "
LAB9_TILES = r"(use # for solid, . for empty, - for a one-way platform, / and \ for slopes, C for a checkpoint, P for the player start)"


def find_program(build, name):
    """The first executable called NAME under BUILD (CMake's own folders left out), or ""."""
    for folder, subfolders, files in os.walk(build):
        subfolders[:] = [sub for sub in subfolders if sub != "CMakeFiles"]
        path = os.path.join(folder, name)
        if name in files and os.access(path, os.X_OK) and os.path.isfile(path):
            return path
    return ""


def command_line_rows(p):
    """(exit code, the one line, command): the shared command line and each program's options."""
    pong = NO_DISPLAY + [p["pong"]]
    lab06 = NO_DISPLAY + [p["lab06_rotated_boxes"]]
    lab08 = NO_DISPLAY + [p["lab08_many_objects"]]
    rows = [
        (2, "Pong: --frames needs a value", pong + ["--frames"]),
        (2, f"Pong: --frames needs a whole number from 0 to {MAX_STEPS}, not 'ten'", pong + ["--frames", "ten"]),
        (2, f"Pong: --frames needs a whole number from 0 to {MAX_STEPS}, not '-3'", pong + ["--frames", "-3"]),
        (2, f"Pong: --seconds needs a number from 0 to {MAX_SECONDS}, not '76861433640456466'",
         pong + ["--headless", "--seconds", "76861433640456466"]),
        (2, f"Pong: --seconds needs a number from 0 to {MAX_SECONDS}, not '153722867280912931'",
         pong + ["--headless", "--seconds", "153722867280912931"]),
        (2, "Pong: --seed needs a whole number from 0 to 4294967295, not '4294967297'",
         pong + ["--headless", "--seed", "4294967297"]),
        (2, "Pong: --screenshot draws a picture, so it cannot be --headless",
         pong + ["--headless", "--screenshot", "x.png"]),
        (2, "Pong: --screenshot needs a file name, e.g. shot.png", [p["pong"], "--screenshot", ""]),
        (2, "Pong: unknown option '--bogus' (the options are: " + SHARED_OPTIONS + " --mode VALUE "
         "--difficulty VALUE --points-to-win VALUE --screen VALUE; --help explains)", pong + ["--bogus"]),
        (2, r"Hitbox sandbox: unknown option '\xEF\xBB\xBF' (the options are: " + SHARED_OPTIONS
         + "; --help explains)", NO_DISPLAY + [p["sandbox"], b"\xef\xbb\xbf"]),
    ]
    # Issue 25, items 23 and 24: numbers are decimal only (as Options.h says), and an option that
    # would silently override another is refused.
    for bad in ("0x10", "0x1p3", "1e-400", "1e2", " 5", "+5", ".5", "5.", "inf"):
        rows.append((2, f"Lab 6 - Rotated boxes: --spin needs a number from -720 to 720, not '{bad}'",
                     lab06 + ["--headless", "--spin", bad]))
    rows += [
        (2, "Pong: --seconds needs a number from 0 to 100000000, not '1e3'", pong + ["--headless", "--seconds", "1e3"]),
        # Record and replay (docs/debugging.md): a bad file is one line and exit 2, before any run.
        (2, "Pong: --replay: cannot open '/no/such.replay'", pong + ["--headless", "--replay", "/no/such.replay"]),
        (2, "Pong: --record and --replay: give one of them", pong + ["--headless", "--record", "a", "--replay", "b"]),
        (2, "Pong: --record: cannot save '/no/such/folder/a.replay': the folder '/no/such/folder' does not exist",
         pong + ["--headless", "--record", "/no/such/folder/a.replay"]),
        (2, "Pong: --timeline: cannot save '/no/such/folder/t.csv': the folder '/no/such/folder' does not exist",
         pong + ["--headless", "--timeline", "/no/such/folder/t.csv"]),
        (2, "Pong: --pause-at-step pauses the window, so it needs one (not --headless or --screenshot)",
         pong + ["--headless", "--pause-at-step", "3"]),
        (2, "Pong: --frames is given twice; give it once", pong + ["--headless", "--frames", "5", "--frames", "7"]),
        (2, "Pong: --mode is given twice; give it once", pong + ["--headless", "--mode", "1p", "--mode", "2p"]),
        (2, "Pong: --frames and --seconds both set how long to run; give one of them",
         pong + ["--headless", "--frames", "5", "--seconds", "7"]),
        (2, "Pong: --frames and --seconds both set how long to run; give one of them",
         pong + ["--headless", "--seconds", "7", "--frames", "5"]),
        # Each program's own options: the typed getters' one message format.
        (2, "Pong: --mode needs one of 1p, 2p, cvc, not 'bogus'", pong + ["--headless", "--mode", "bogus"]),
        (2, "Pong: --difficulty needs one of easy, normal, hard, not 'impossible'",
         pong + ["--headless", "--difficulty", "impossible"]),
        (2, "Pong: --points-to-win needs a whole number from 1 to 99, not '0'", pong + ["--headless", "--points-to-win", "0"]),
        (2, "Pong: --screen needs one of title, play, win, not 'menu'", pong + ["--headless", "--screen", "menu"]),
    ]
    for bad in ("abc", "200000000", "-5", "1e9"):
        rows.append((2, f"Lab 2 - Bouncing balls: --balls needs a whole number from 2 to 60, not '{bad}'",
                     NO_DISPLAY + [p["lab02_bouncing_balls"], "--headless", "--balls", bad]))
    return rows + [
        (2, "Lab 3 - Bouncing squares: --squares needs a whole number from 2 to 40, not 'many'",
         NO_DISPLAY + [p["lab03_bouncing_squares"], "--headless", "--squares", "many"]),
        (2, "Lab 5 - Ray caster: --time-order needs on or off, not 'maybe'",
         NO_DISPLAY + [p["lab05_ray_caster"], "--headless", "--time-order", "maybe"]),
        (2, "Lab 7 - Swept circles: --mode needs one of swept, discrete, not 'bogus'",
         NO_DISPLAY + [p["lab07_swept_circles"], "--headless", "--mode", "bogus"]),
        (2, "Lab 8 - Many objects: --balls needs a whole number from 1 to 100000, not 'abc'",
         lab08 + ["--headless", "--balls", "abc"]),
        (2, "Lab 8 - Many objects: --balls needs a whole number from 1 to 100000, not '200000000'",
         lab08 + ["--headless", "--balls", "200000000"]),
        (2, "Lab 8 - Many objects: --method needs one of brute, sweep, grid, quadtree, not 'fast'",
         lab08 + ["--headless", "--method", "fast"]),
        (2, "Lab 8 - Many objects: --scene needs one of crowd, table, layers, not 'bogus'",
         lab08 + ["--headless", "--scene", "bogus"]),
        (2, "Lab 8 - Many objects: --print-timing needs a number from 0 to 3600, not 'nan'",
         lab08 + ["--headless", "--print-timing", "nan"]),
        (2, "Lab 9 - Platformer: --demo needs on or off, not 'no'",
         NO_DISPLAY + [p["lab09_platformer"], "--headless", "--demo", "no"]),
    ]


def level_files(work):
    """Lab 9's hostile level files, written into WORK: each problem its own line, never a raw byte."""
    contents = {
        "good.txt": b"#P.#\n####\n", "big.txt": b"#" * 2000000, "bom.txt": b"\xef\xbb\xbf#P.#\n####\n",
        "cr.txt": b"#P.#\r####\r", "nul.txt": b"#P\0#\n####\n", "byte.txt": b"#P.#\n#\xef##\n",
        "empty": b"", "gap.txt": b"####\n#P.#\n####\n",
        # Issue 25, items 6 and 7: beyond the exact range, or no room for the player at 'P'.
        "wide.txt": b"." * 20001 + b"\n",
    }
    for name, content in contents.items():
        with open(os.path.join(work, name), "wb") as level:
            level.write(content)
    os.mkfifo(os.path.join(work, "fifo.txt"))


def level_rows(p, work):
    lab09 = NO_DISPLAY + [p["lab09_platformer"], "--headless", "--level"]
    file = LAB9 + "level file '" + work
    return [
        (2, LAB9 + "--level needs a file name, e.g. levels/platformer.txt", lab09 + [""]),
        (2, file + "/missing.txt' does not exist", lab09 + [work + "/missing.txt"]),
        (2, file + "' is a folder; pick a file in it, e.g. levels/platformer.txt", lab09 + [work]),
        (2, LAB9 + "level file '/dev/zero' is not a regular file (a device or a pipe); a level is a text file",
         lab09 + ["/dev/zero"]),
        (2, file + "/fifo.txt' is not a regular file (a device or a pipe); a level is a text file",
         lab09 + [work + "/fifo.txt"]),
        (2, file + "/big.txt' is 2000000 bytes; a level file may be at most 1048576 bytes (1 MiB)",
         lab09 + [work + "/big.txt"]),
        (2, file + r"/cr.txt' line 1: unknown tile '\r' in column 5 (a line ends in a lone carriage return: "
         "save the file with Unix or Windows line ends)", lab09 + [work + "/cr.txt"]),
        (2, file + r"/nul.txt' line 1: unknown tile '\0' in column 3 " + LAB9_TILES, lab09 + [work + "/nul.txt"]),
        (2, file + r"/byte.txt' line 2: unknown tile '\xEF' in column 2 " + LAB9_TILES, lab09 + [work + "/byte.txt"]),
        (2, file + "/empty' has no rows (draw the level with # . and one P)",
         ["env", "-u", "DISPLAY", p["lab09_platformer"], "--headless", "--level", work + "/empty"]),
        (2, file + "/wide.txt' line 1: the level is over 20000 tiles wide; the collision maths is exact to "
         "1000000 px (hitbox/geometry/Range.h), so a level may be at most 20000 tiles wide and tall",
         lab09 + [work + "/wide.txt"]),
        (2, LAB9 + "the player start 'P' (column 2, row 2) has solid tiles above and below it; the player is "
         "taller than one tile, so leave the tile above or below 'P' empty", lab09 + [work + "/gap.txt"]),
    ]


def no_display_rows(p):
    return [
        (2, "Pong: " + NO_DISPLAY_FOUND.format("DISPLAY is not set"), NO_DISPLAY + [p["pong"]]),
        (2, "Pong: " + NO_DISPLAY_FOUND.format("only WAYLAND_DISPLAY is set, and SFML needs X11 (Xwayland)"),
         ["env", "-u", "DISPLAY", "WAYLAND_DISPLAY=wayland-0", p["pong"]]),
        (2, LAB9 + NO_DISPLAY_FOUND.format("no X server answers at DISPLAY=:4711"),
         ["env", "DISPLAY=:4711", p["lab09_platformer"]]),
    ]


def full_disk():
    """In the child: files may grow to 8 KiB only, and SIGXFSZ ignored, so write() fails instead."""
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (8 * 1024, 8 * 1024))


def screenshot_rows(sandbox, work):
    """Screenshots that cannot be written: one line, exit 1 (the files are made in screenshots())."""
    could_not = "Hitbox sandbox: could not save '" + work
    fonts = work + "/fifo-assets/fonts/DejaVuSans.ttf"
    missing = "/no/such/folder/a.png': the folder '" + work + "/no/such/folder' does not exist"
    return [
        (1, could_not + "/shots/taken.png': it is a folder", [sandbox, "--screenshot", work + "/shots/taken.png"]),
        (1, could_not + "/shots/pipe.png': it is not a regular file (a device or a pipe)",
         [sandbox, "--screenshot", work + "/shots/pipe.png"]),
        (1, could_not + missing, [sandbox, "--screenshot", work + "/no/such/folder/a.png"]),
        (1, could_not + "/shots/full.png': the write did not complete (is the disk full?)",
         [sandbox, "--screenshot", work + "/shots/full.png"], full_disk),
    ], [
        # Issue 25: a read-only file and a symbolic link are never replaced (item 8); the name is
        # checked before a long simulation (item 16); a newline in it stays on one line (item 20);
        # a font that is a pipe is refused, not waited on for ever (item 14).
        (1, could_not + "/keep/ro.png': it is read-only (make it writable, or save to a new name)",
         [sandbox, "--screenshot", work + "/keep/ro.png"]),
        (1, could_not + "/keep/link.png': it is a symbolic link (save to the file it points to, or to a new name)",
         [sandbox, "--screenshot", work + "/keep/link.png"]),
    ], [
        (1, could_not + missing, [sandbox, "--frames", str(MAX_STEPS), "--screenshot", work + "/no/such/folder/a.png"]),
        (1, could_not + r"/new\nline/a.png': the folder '" + work + r"/new\nline' does not exist",
         [sandbox, "--screenshot", work + "/new\nline/a.png"]),
        (1, "Hitbox sandbox: the font '" + fonts + "' is not a regular file (a folder, a device or a pipe). "
         "Fix: restore it with 'git checkout -- assets/fonts/DejaVuSans.ttf'.",
         ["env", "HITBOX_ASSETS=" + work + "/fifo-assets", sandbox, "--screenshot", work + "/keep/font.png"]),
    ]


class Table:
    """The rows run so far and how many failed."""

    def __init__(self):
        self.rows, self.failures = 0, 0

    def fail(self, message):
        self.failures += 1
        print("FAIL: " + message, file=sys.stderr, flush=True)

    def check(self, passed, message):
        """One row that is not a one-line message: a failure says MESSAGE."""
        self.rows += 1
        if not passed:
            self.fail(message)

    def row(self, code, expected, command, preexec=None):
        """Runs COMMAND (no display unless the row says so): exit CODE, stderr the line EXPECTED."""
        self.rows += 1
        try:
            run = subprocess.run(command, stdin=subprocess.DEVNULL, capture_output=True, timeout=60,
                                 preexec_fn=preexec)
            actual, out, err = run.returncode, run.stdout, run.stderr
        except subprocess.TimeoutExpired as expired:
            actual, out, err = 124, expired.stdout or b"", expired.stderr or b""
        lines = err.count(b"\n")
        if actual != code or lines != 1 or err.rstrip(b"\n") != os.fsencode(expected) or out:
            shown = " ".join(os.fsdecode(word) for word in command)
            self.fail(f"{shown}\n  expected exit {code} and the line: {expected}\n"
                      f"  got exit {actual}, stderr ({lines} lines):")
            indented = [b"    " + line for line in err[:2000].split(b"\n") if line]
            indented += [b"    stdout: " + line for line in out[:500].split(b"\n") if line]
            sys.stderr.buffer.write(b"".join(line + b"\n" for line in indented))
            sys.stderr.flush()


def output(command, **options):
    """COMMAND's stdout and stderr together, as text."""
    return subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          errors="replace", **options).stdout


def special_rows(table, p):
    """Item 22: --help and -h print the usage page on stdout, exit 0, whatever else is given.
    Item 9: angles wrap. Item 24: half a second is 60 steps."""
    for help_option in ("--help", "-h"):
        done = subprocess.run(NO_DISPLAY + [p["lab06_rotated_boxes"], "--spin", "bogus", help_option],
                              capture_output=True, text=True, errors="replace")
        usage = done.stdout.splitlines()
        table.check(done.returncode == 0 and not done.stderr and "  --spin VALUE" in usage
                    and any(line.startswith("  --seconds S ") for line in usage),
                    f"{help_option}: exit {done.returncode}, stderr: {done.stderr.rstrip()}")
    # 10 s at 720 degrees a second from 25 ends at 25, not 7225 (and a float that only grows
    # stops turning after about 42 simulated hours).
    spun = output(NO_DISPLAY + [p["lab06_rotated_boxes"], "--headless", "--spin", "720", "--seconds", "10"])
    table.check(spun.rstrip("\n").endswith("held shape 0 at 25 degrees"),
                "the spinning shape's angle did not wrap: " + spun.rstrip("\n"))
    half = output(NO_DISPLAY + [p["pong"], "--headless", "--seconds", "0.5"])
    table.check(half.startswith("Pong: 60 frames, 0.5 s simulated |"), "--seconds 0.5 did not run 60 steps")


def level_checks(table, p, work):
    """A byte-order mark (Windows Notepad) is not an error; an unreadable (not missing) level is."""
    lab09 = p["lab09_platformer"]
    bom = subprocess.run(NO_DISPLAY + [lab09, "--headless", "--frames", "1", "--level", work + "/bom.txt"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, errors="replace")
    table.check(bom.returncode == 0, "a level with a byte-order mark did not load:\n" + bom.stderr.rstrip("\n"))
    # As root, run the program as nobody; otherwise chmod is enough.
    os.chmod(work + "/good.txt", 0)
    os.chmod(work, 0o755)
    unreadable = LAB9 + "level file '" + work + "/good.txt' cannot be read: Permission denied"
    command = NO_DISPLAY + [lab09, "--headless", "--level", work + "/good.txt"]
    if os.getuid() == 0:
        nobody = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"]
        if subprocess.run(nobody + ["test", "-x", lab09], stderr=subprocess.DEVNULL).returncode == 0:
            table.row(2, unreadable, NO_DISPLAY + nobody + command[len(NO_DISPLAY):])
        else:
            print("note: the build folder cannot be reached as nobody; the unreadable-level row is skipped", flush=True)
    else:
        table.row(2, unreadable, command)


def screenshots(table, sandbox, work):
    """The screenshot rows: the files they need, the rows, and nothing half-written left behind."""
    os.makedirs(work + "/shots/taken.png")
    os.mkfifo(work + "/shots/pipe.png")
    # A GL context under Xvfb makes LeakSanitizer report Mesa's memory (docs: platform notes).
    asan = os.environ.get("ASAN_OPTIONS")
    os.environ["ASAN_OPTIONS"] = (asan + ":" if asan else "") + "detect_leaks=0"
    unwritable, kept, later = screenshot_rows(sandbox, work)
    for row in unwritable:
        table.row(*row)
    leftovers = sorted(os.listdir(work + "/shots"))
    table.check(leftovers == ["pipe.png", "taken.png"], "failed screenshots left files behind: " + "\n".join(leftovers))
    os.makedirs(work + "/keep")
    with open(work + "/keep/ro.png", "w", encoding="ascii") as mine:
        mine.write("mine")
    os.chmod(work + "/keep/ro.png", 0o444)
    os.symlink("ro.png", work + "/keep/link.png")
    for row in kept:
        table.row(*row)
    with open(work + "/keep/ro.png", encoding="ascii", errors="replace") as mine:
        untouched = mine.read() == "mine"
    table.check(untouched and oct(os.stat(work + "/keep/ro.png").st_mode & 0o777) == "0o444"
                and os.path.islink(work + "/keep/link.png"), "a read-only file or a link was replaced")
    os.makedirs(work + "/fifo-assets/fonts")
    os.mkfifo(work + "/fifo-assets/fonts/DejaVuSans.ttf")
    for row in later:
        table.row(*row)
    # Item 17: a legal 254-byte name is saved (its hidden temporary name must fit too).
    long_name = work + "/keep/" + "x" * 250 + ".png"
    saved = subprocess.run([sandbox, "--screenshot", long_name], stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, text=True, errors="replace")
    table.check(saved.returncode == 0 and os.path.isfile(long_name) and os.path.getsize(long_name) > 0,
                "a 254-byte screenshot name was not saved: " + saved.stderr.rstrip("\n"))


def main():
    if len(sys.argv) != 2:
        print("usage: bad_input.py BUILD_DIR", file=sys.stderr)
        return 2
    if not os.environ.get("DISPLAY") and not os.environ.get("HITBOX_BAD_INPUT_XVFB") and shutil.which("xvfb-run"):
        # -n: start looking for a free display at a number of its own, not at 99: ctest runs
        # other xvfb-run tests at the same moment, and two servers racing for one number
        # leave one program with a display that vanishes under it.
        os.execvp("xvfb-run", ["xvfb-run", "-a", "-n", str(100 + os.getpid() % 800), "env", "HITBOX_BAD_INPUT_XVFB=1", sys.executable] + sys.argv)
    os.environ["ALSOFT_DRIVERS"] = "null"
    programs = {name: find_program(sys.argv[1], name) for name in PROGRAMS}
    work = tempfile.mkdtemp()
    table = Table()
    try:
        for row in command_line_rows(programs):
            table.row(*row)
        special_rows(table, programs)
        level_files(work)
        for row in level_rows(programs, work):
            table.row(*row)
        level_checks(table, programs, work)
        for row in no_display_rows(programs):
            table.row(*row)
        if os.environ.get("DISPLAY"):
            screenshots(table, programs["sandbox"], work)
        else:
            print("note: no display and no xvfb-run; the screenshot rows are skipped", flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"bad-input table: {table.rows} rows, {table.failures} failed")
    return 0 if table.failures == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
