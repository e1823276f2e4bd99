"""Runs one built course lab on the display it is given, photographs the screen, then closes it
(courselabs.py runs this under xvfb-run, from the checkout's top). Exit status 0 means the lab
was still running when closed; anything else is a crash or an early exit.

    courselab_window.py SCREEN BUILD SECONDS SHOT LOG MOUSE_AT [INSIDE...]

SCREEN: the display's size (WxH), photographed whole into SHOT; BUILD: the build folder holding
course_lab and course_lab_run/; LOG: what the lab prints; MOUSE_AT: "X Y" to hold the left
button down there from MOUSE_DOWN_AFTER seconds on, or ""; INSIDE: the command that runs it in
the Debian root (scripts/sid-root.sh run), or nothing to run it here.
Standard library only; started as a program of its own, so it imports nothing of labtool.
"""
import os
import shlex
import signal
import subprocess
import sys
import time

MOUSE_DOWN_AFTER = 2  # seconds: the lab has opened its window and drawn a frame or two


def main(arguments):
    screen, build, seconds, shot, log, mouse_at, *inside = arguments
    seconds, display = int(seconds), os.environ["DISPLAY"]
    # The lab gets a process group of its own (in the root, with the commands around it), so
    # closing it closes them all; `env` hands the display into the root, whose environment is
    # otherwise empty.
    with open(log, "wb") as output:
        lab = subprocess.Popen([*inside, "env", f"DISPLAY={display}", "sh", "-c",
                                f"cd {shlex.quote(build + '/course_lab_run')} && exec ../course_lab"],
                               stdin=subprocess.DEVNULL, stdout=output, stderr=subprocess.STDOUT,
                               start_new_session=True)
    if mouse_at:
        time.sleep(MOUSE_DOWN_AFTER)
        subprocess.run(["xdotool", "mousemove", *mouse_at.split(), "mousedown", "1"])
        time.sleep(seconds - MOUSE_DOWN_AFTER)
    else:
        time.sleep(seconds)
    status = lab.poll()
    if status is not None:
        status = status if status >= 0 else 128 - status  # killed by a signal: the shell's number
        print(f"exited early with code {status} (output: {log})", file=sys.stderr)
        return 1
    subprocess.run(["ffmpeg", "-loglevel", "error", "-f", "x11grab", "-draw_mouse", "0", "-video_size", screen,
                    "-i", display, "-frames:v", "1", shot])
    try:
        os.killpg(lab.pid, signal.SIGTERM)
    except ProcessLookupError:
        pass  # (it ended between the look and the photograph)
    lab.wait()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
