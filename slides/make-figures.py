#!/usr/bin/env python3
"""make-figures.py BUILD_DIR [--allow-missing] [--list FILE] [--out DIR]

Draws the slides' screenshots with the project's own programs, so a figure always shows what
the code really does. Each line of figures.txt (or FILE) names an output PNG, a program (a path
inside BUILD_DIR), its arguments (a set-up state: --frames/--seed and the program's own
options) and, after a `|`, the arguments that make what the figure claims to show (--debug for
"the debug view", --method quadtree for "the quadtree"). An argument crop=W:H:X:Y is not passed
on: the picture is cut to that rectangle (ffmpeg), to show the part the slide is about at a
size the back row can read. Neither is text=PX, which every line needs: the smallest text left
in the picture, in its own pixels (the program's font size; text=0 when none is left). It goes
into DIR/figure-text.json (with each picture's size, and an animation still's label size), where
tools/check-layout.mjs reads it to fail a figure whose text is under 24 px as the slide shows it.
Every program runs under xvfb-run with --screenshot into figures/generated/ (or DIR), and each
figure is checked:
- drawn twice, the same pixels: nothing run-dependent (a timing, a clock) is on it (a
  --screenshot run leaves timings out: hitbox::Options::repeatablePicture); when it differs, the
  message names the rectangle that changed, as crop=W:H:X:Y;
- drawn once more without the claimed arguments, different pixels: the claimed part is really
  drawn (a quadtree figure that looks the same as the default grid fails).
An output NAME.apng is an animation: an argument frames=FIRST:LAST:STEP draws the picture after
FIRST, FIRST+STEP, ... LAST fixed steps (--frames), and ffmpeg joins them into NAME.apng (for
the HTML, looping) and a still NAME.png for the PDF: three of its frames in a labelled strip
(tools/check-stills.sh: each panel is one clean frame). Both are checked the same way as a
picture. A missing program, a failed run, an empty PNG or a failed check fails, naming the
figure; with --allow-missing (drafts only) they are reported and skipped.
"""
import filecmp
import json
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
FONT_FILE = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
# A figure slide's picture area (theme/hitbox.css: the 1280 px slide less 2 x 56 px padding,
# section.figure img's max-height): a strip's layout shows the frames as large as fits in it.
SLIDE_W, SLIDE_H = 1168, 520
LABEL_PX = 28  # the smallest label size on the slide
ZOOMS = (1, 2)  # an animation still's frames: drawn as they are, or each pixel doubled (check-stills.sh)
GUTTER = 24  # white pixels between frames side by side: dark frames would otherwise read as one picture
LOOP_H = os.path.join(HERE, "..", "framework", "hitbox", "app", "Loop.h")
FFMPEG = ["ffmpeg", "-nostdin", "-loglevel", "error", "-y"]


def steps_per_second():
    """The fixed step rate (the frame labels show the time), read from its one home, Loop.h."""
    with open(LOOP_H, encoding="utf-8") as header:
        found = re.search(r"constexpr float stepsPerSecond = ([0-9.]+)f;", header.read())
    if not found:
        sys.exit(f"make-figures: {LOOP_H} has no line 'constexpr float stepsPerSecond = N.f;'")
    return float(found.group(1))


def run_logged(command, log):
    """Runs COMMAND with its output appended to LOG; true when it succeeds."""
    with open(log, "ab") as out:
        return subprocess.run(command, stdin=subprocess.DEVNULL, stdout=out, stderr=out).returncode == 0


def size_of(picture):
    """(width, height) of a picture, or None."""
    probe = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
                            "stream=width,height", "-of", "csv=p=0", picture], capture_output=True, text=True)
    try:
        w, h = (int(size) for size in probe.stdout.strip().split(",")[:2])
        return w, h
    except ValueError:
        return None


def changed_rectangle(first, second):
    """Where two pictures of one size differ, as "crop=W:H:X:Y"; None when they cannot be
    compared pixel by pixel (another size, not a picture)."""
    size = size_of(first)
    if size is None or size != size_of(second):
        return None
    rows = []
    for picture in (first, second):
        raw = subprocess.run(FFMPEG + ["-i", picture, "-frames:v", "1", "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                             capture_output=True).stdout
        stride = size[0] * 3
        if len(raw) != stride * size[1]:
            return None
        rows.append([raw[y * stride:(y + 1) * stride] for y in range(size[1])])
    changed = [y for y in range(size[1]) if rows[0][y] != rows[1][y]]
    if not changed:
        return None
    left, right = size[0], 0
    for y in changed:
        a, b = rows[0][y], rows[1][y]
        first_x = next(i for i in range(len(a)) if a[i] != b[i]) // 3
        last_x = next(i for i in range(len(a) - 1, -1, -1) if a[i] != b[i]) // 3
        left, right = min(left, first_x), max(right, last_x)
    return f"crop={right - left + 1}:{changed[-1] - changed[0] + 1}:{left}:{changed[0]}"


def draw(executable, target, log, arguments):
    """One screenshot (cropped when an argument is crop=W:H:X:Y); false when the run fails."""
    crop = [a[len("crop="):] for a in arguments if a.startswith("crop=")]
    passed = [a for a in arguments if not a.startswith("crop=")]
    if os.path.lexists(target):
        os.remove(target)
    with open(log, "wb") as out:
        if subprocess.run([executable, "--screenshot", target] + passed, stdin=subprocess.DEVNULL,
                          stdout=out, stderr=out).returncode != 0:
            return False
    if crop and os.path.isfile(target) and os.path.getsize(target) > 0:
        if not run_logged(FFMPEG + ["-i", target, "-vf", "crop=" + crop[-1], target + ".crop.png"], log):
            return False
        os.replace(target + ".crop.png", target)
    return True


def strip_layout(w, h, n):
    """The layout ("h": side by side, "v": one above the other) and zoom (each frame's pixels
    drawn 1 or 2 times as large: the slide shows a picture no larger than it is, so a small crop
    whose text needs more than 1x is doubled) that show N frames of W x H largest on the slide,
    and the label's font size and band height that stay LABEL_PX there."""
    best = None
    for layout in ("h", "v"):
        for zoom in ZOOMS:
            font = 40
            for _ in range(4):
                band = round(font * 1.5)
                width, height = ((n * w * zoom + (n - 1) * GUTTER, h * zoom + band) if layout == "h"
                                 else (w * zoom, n * (h * zoom + band)))
                scale = min(SLIDE_W / width, SLIDE_H / height, 1.0)
                font = max(LABEL_PX, math.ceil(LABEL_PX / scale))
            if best is None or zoom * scale > best[0] + 0.01:
                best = (zoom * scale, layout, zoom, font, band)
    return best[1:]


def strip(folder, still, log, steps):
    """The still of an animation whose frames are FOLDER/000.png... (STEPS: each frame's fixed
    steps): the first, middle and last frames (one when there is one frame, two for two), each
    under a label with its number and time. Never frames laid over each other: a handout must
    show each moment cleanly (tools/check-stills.sh checks every panel is one of the frames).
    Returns the labels' font size and the frames' zoom (None when it failed)."""
    count = len(steps)
    picks = [0, (count - 1) // 2, count - 1] if count >= 3 else list(range(count)) or [0]
    size = size_of(os.path.join(folder, "000.png"))
    if size is None:
        return None
    w, h = size
    layout, zoom, font, band = strip_layout(w, h, len(picks))
    w, h = w * zoom, h * zoom
    inputs, graph, labels = [], "", ""
    for i, pick in enumerate(picks):
        label = os.path.join(folder, f"label-{i}.txt")
        with open(label, "w", encoding="utf-8") as text:
            text.write(f"{i + 1}   t = {steps[pick] / steps_per_second():.2f} s")
        inputs += ["-i", os.path.join(folder, f"{pick:03d}.png")]
        gutter = GUTTER if layout == "h" and i < len(picks) - 1 else 0
        graph += (f"[{i}:v]format=rgb24,scale={w}:{h}:flags=neighbor,pad={w}:{h + band}:0:{band}:white,drawtext=fontfile={FONT_FILE}:"
                  f"textfile={label}:fontsize={font}:fontcolor=black:x=(w-text_w)/2:y=({band}-text_h)/2,"
                  f"pad={w + gutter}:{h + band}:0:0:white[p{i}];")
        labels += f"[p{i}]"
    if len(picks) > 1:
        graph += labels + ("hstack" if layout == "h" else "vstack") + f"=inputs={len(picks)}[out]"
    else:
        graph += labels + "null[out]"
    return (font, zoom) if run_logged(FFMPEG + inputs + ["-filter_complex", graph, "-map", "[out]", still], log) else None


def animate(executable, target, log, frames, arguments):
    """The frames FIRST:LAST:STEP of an animation, joined into TARGET (.apng), and its still for
    the PDF (the same name, .png). Returns the still's label size and zoom (None when it failed)."""
    try:
        first, last, step = (int(part) for part in frames.split(":"))
    except ValueError:
        return None
    folder = target + ".frames"
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    times = list(range(first, last + 1, step))
    for count, frame in enumerate(times):
        if not draw(executable, os.path.join(folder, f"{count:03d}.png"), log, arguments + ["--frames", str(frame)]):
            return None
    if not run_logged(FFMPEG + ["-framerate", "2", "-i", os.path.join(folder, "%03d.png"), "-plays", "0",
                                "-f", "apng", target], log):
        return None
    labels = strip(folder, target[: -len(".apng")] + ".png", log, times)
    if labels:
        shutil.rmtree(folder)
    return labels


def remove(*paths):
    for path in paths:
        if os.path.lexists(path) and not os.path.isdir(path):
            os.remove(path)


def make(line, build_dir, out_dir, text_sizes):
    """Draws and checks the figure of one line of the list; None when made, else the problem.
    Adds what tools/check-layout.mjs needs to TEXT_SIZES: {picture: {text, width, height}}."""
    line, bar, claimed = line.partition("|")
    parts = line.split(None, 2)
    name, program = parts[0], parts[1] if len(parts) > 1 else ""
    arguments = parts[2].strip() if len(parts) > 2 else ""
    set_up, claims = arguments.split(), claimed.split()
    executable, target = os.path.join(build_dir, program), os.path.join(out_dir, name)
    log = target + ".log"
    if not (os.path.isfile(executable) and os.access(executable, os.X_OK)):
        return f"{name}: program {program} not found in {build_dir}"
    texts = [a[len("text="):] for a in set_up if a.startswith("text=")]
    if len(texts) != 1 or not texts[0].isdigit():
        return (f"{name}: needs text=PX, the smallest text left in the picture in its own pixels "
                "(the program's font size; text=0 when the picture has no text)")
    smallest_text = int(texts[0])
    set_up = [a for a in set_up if not a.startswith("text=")]
    animation = name.endswith(".apng")
    if animation:
        # An animation: the frames=FIRST:LAST:STEP argument names its frames.
        frames = [a[len("frames="):] for a in set_up if a.startswith("frames=")]
        if not frames or not frames[-1]:
            return f"{name}: an animation needs frames=FIRST:LAST:STEP"
        set_up = [a for a in set_up if not a.startswith("frames=")]

    def paint(into, with_claims=True):
        shown = set_up + (claims if with_claims else [])
        return animate(executable, into, log, frames[-1], shown) if animation else draw(executable, into, log, shown)

    label = paint(target)
    if not label:
        return f"{name}: {program} {arguments} {claimed} failed (see {log})"
    if not (os.path.isfile(target) and os.path.getsize(target) > 0):
        return f"{name}: {program} wrote no image (empty or missing {target})"
    again = os.path.join(out_dir, ".again-" + name)
    again_still = re.sub(r"\.apng$", "", again) + ".png"
    if not paint(again) or not filecmp.cmp(target, again, shallow=False):
        where = changed_rectangle(*((target, again) if not animation else
                                    (re.sub(r"\.apng$", ".png", target), again_still)))
        remove(again, again_still)
        return (f"{name}: two runs drew different pictures{f', in {where}' if where else ''}: run-dependent "
                "text (a timing, a clock) or state on the figure; a --screenshot run must leave it out "
                "(hitbox::Options::repeatablePicture), or crop it off")
    if claims and (not paint(again, with_claims=False) or filecmp.cmp(target, again, shallow=False)):
        remove(again)
        return f"{name}: claims '{' '.join(claims)}' but looks the same without it"
    if animation:
        with open(log, "ab") as errors:
            clean = subprocess.run([os.path.join(HERE, "tools", "check-stills.sh"), target], stderr=errors).returncode == 0
        if not clean:
            remove(again, again_still)
            return f"{name}: its still {name[: -len('.apng')]}.png is not made of clean frames (see {log})"
    remove(again, log, again_still)
    # An animation's still has its labels too (the strip's font size), and its frames' text is
    # drawn `zoom` times as large.
    pictures = [(name, smallest_text)]
    if animation:
        font, zoom = label
        pictures.append((re.sub(r"\.apng$", ".png", name), min(smallest_text * zoom or font, font)))
    for picture, text in pictures:
        size = size_of(os.path.join(out_dir, picture))
        if size:
            text_sizes[picture] = {"text": text, "width": size[0], "height": size[1]}
    return None


def main(argv):
    usage = "usage: " + argv[0] + " BUILD_DIR [--allow-missing] [--list FILE] [--out DIR]"
    if len(argv) < 2:
        print(usage, file=sys.stderr)
        return 2
    build_dir, allow_missing = os.path.abspath(argv[1]), False
    figure_list, out_dir = os.path.join(HERE, "figures.txt"), os.path.join(HERE, "figures", "generated")
    options = argv[2:]
    while options:
        option = options.pop(0)
        if option == "--allow-missing":
            allow_missing = True
        elif option in ("--list", "--out") and options:
            value = os.path.abspath(options.pop(0))
            figure_list, out_dir = (value, out_dir) if option == "--list" else (figure_list, value)
        else:
            print(usage, file=sys.stderr)
            return 2
    if not os.path.isdir(build_dir):
        print(f"make-figures: no build folder {build_dir}", file=sys.stderr)
        return 1
    os.makedirs(out_dir, exist_ok=True)
    os.environ["ALSOFT_DRIVERS"] = "null"  # programs with sound stay silent without a sound device
    # A display: use the one we have, otherwise run this whole script once under xvfb-run
    # (one X server for all figures instead of one per figure).
    if not os.environ.get("DISPLAY"):
        if not shutil.which("xvfb-run"):
            print("make-figures: xvfb-run is needed (apt-get install xvfb xauth)", file=sys.stderr)
            return 1
        again = [sys.executable, os.path.abspath(argv[0]), build_dir] + (["--allow-missing"] if allow_missing else [])
        os.execvp("xvfb-run", ["xvfb-run", "-a", "-s", "-screen 0 1280x800x24"] + again
                  + ["--list", figure_list, "--out", out_dir])
    failures, made, text_sizes = [], 0, {}
    with open(figure_list, encoding="utf-8") as lines:
        for line in lines:
            line = line.rstrip("\n")
            if not line.replace(" ", "") or line.startswith("#"):
                continue
            problem = make(line, build_dir, out_dir, text_sizes)
            if problem:
                failures.append(problem)
            else:
                made += 1
    with open(os.path.join(out_dir, "figure-text.json"), "w", encoding="utf-8") as out:
        json.dump(text_sizes, out, indent=1, sort_keys=True)
    print(f"make-figures: {made} figure(s) made and checked in {out_dir}", flush=True)
    for problem in failures:
        print("make-figures: " + problem, file=sys.stderr)
    if failures and not allow_missing:
        print(f"make-figures: {len(failures)} figure(s) missing or wrong", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
