#!/usr/bin/env python3
"""slides/tests/run.py - shows that the slides' checks catch each mistake they exist for.

Each case plants one defect in a small deck (or a figure list with stand-in programs), runs the
same tools check.sh runs, and expects them to fail with the right message; the clean cases must
pass. Needs node and clang-format only (no display, no build): seconds.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

SLIDES = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REPO = os.path.dirname(SLIDES)

# A small project: one source file with slide regions (and the repository's .clang-format).
EXAMPLE_CPP = """// [slide:short]
bool inside(float x, float left, float right)
{
    // Strict: a point on an edge is outside.
    return left < x && x < right;
}
// [/slide]

// [slide:long-string]
int aVeryLongIdentifierThatIsLongerThanAnySlideCanShowInOneLineAtTwentyFourPixels = 0;
// [/slide]

// [slide:internal]
// Game rules first (seed 002: no alien-alien collisions).
bool allowed(int a, int b) { return a != b; }
// [/slide]

// [slide:function]
int sumOf(const int* values, int count)
{
    int sum = 0;
    for (int i = 0; i < count; ++i)
    {
        sum += values[i];
    }
    return sum;
}
// [/slide]

// [slide:split]
int total(int a, int b)
{
    const int sum =
        a + b;
    if (sum > 0)
        return sum;
    // A comment about the last line,
    // in two lines.
    return 0;
}
// [/slide]

// [slide:copied]
// The lines of lab 01's task 1 answer, under another function's name.
int limit(int value, int low, int high)
{
    const int notBelow = value < low ? low : value;
    const int notAbove = notBelow > high ? high : notBelow;
    const bool changed = notAbove != value;
    return changed ? notAbove : value;
}
// [/slide]

// [slide:repeat-a]
float speedOf(float vx, float vy)
{
    const float squared = vx * vx + vy * vy;
    const float speed = std::sqrt(squared);
    const float halfSpeed = speed / 2.f;
    return halfSpeed;
}
// [/slide]

// [slide:repeat-b]
float halfSpeedOf(float vx, float vy)
{
    const float squared = vx * vx + vy * vy;
    const float speed = std::sqrt(squared);
    const float halfSpeed = speed / 2.f;
    return halfSpeed + 0.f;
}
// [/slide]

// [slide:product]
float smallerSide()
{
    const Box box = makeBox();
    const Vec2 scale = makeScale();
    const float radius = std::fmin(box.width * scale.x, box.height * scale.y) / 2.f + 0.f;
    return radius;
}
// [/slide]

// [slide:tall]
void tall()
{
""" + "".join(f"    int a{i} = {i};\n" for i in range(1, 16)) + """}
// [/slide]
"""


# A lab with a graded task: the answer between BEGIN TASK and STARTER TASK.
LAB_CPP = """// [slide:lab-answer]
int clampToRange(int value, int low, int high)
{
    // BEGIN TASK 1: clamp the value into the range
    const int notBelow = value < low ? low : value;
    const int notAbove = notBelow > high ? high : notBelow;
    const bool changed = notAbove != value;
    return changed ? notAbove : value;
    // STARTER TASK 1
    // return value;
    // END TASK 1
}
// [/slide]
"""

# Speaker notes that say enough (12 words or more) for the cases about something else.
NOTES = "Say what the slide shows, ask the class one question, and point at the code."


def include(region, extra=""):
    return f"<!-- include: src/Example.cpp#{region}{extra} -->"


def include_from(path, region, extra=""):
    return f"<!-- include: {path}#{region}{extra} -->"


# (name, the message the tools must fail with or "" to pass, the slide's body, a figure no deck uses)
DECK_CASES = [
    ("clean-deck-passes", "", "# A test\n\n" + include("short")),
    ("code-line-too-long-for-clang-format", "characters (at most 78 fit at 24px)",
     "# Too wide\n\n" + include("long-string")),
    ("hand-written-code-too-long", "characters (at most 78 fit at 24px)",
     "# Too wide\n\n```cpp\nint aVeryLongFunctionName(int firstArgument, int secondArgument, int thirdArgumentHere);\n```"),
    ("too-many-code-lines", "lines of code (at most 16 fit)", "# Too tall\n\n" + include("tall")),
    ("excerpt-cut-mid-block", "unbalanced brackets", "# Cut short\n\n" + include("function", ' lines 1-6 key "sum +="')),
    ("excerpt-cut-before-key-line", "does not contain its key line",
     "# Cut before the point\n\n" + include("function", ' lines 1-3 key "return sum"')),
    ("part-without-key-line", 'needs key "TEXT"', "# No key\n\n" + include("function", " lines 3-4")),
    ("part-with-gap-passes", "", "# Parts\n\n" + include("function", ' lines 1-3,8-9 key "return sum"')),
    # An excerpt is a whole thing: it starts and ends on a statement boundary.
    ("excerpt-starts-mid-statement", "starts mid-statement at line 4",
     "# Cut at the start\n\n" + include("split", ' lines 4-6 key "return sum"')),
    ("excerpt-ends-mid-statement", "ends mid-statement at line 5",
     "# Cut at the end\n\n" + include("split", ' lines 3-5 key "if (sum"')),
    ("excerpt-ends-on-a-comment", "ends on a comment at line 7",
     "# Cut after a comment\n\n" + include("split", ' lines 3-7 key "sum > 0"')),
    ("excerpt-starts-inside-a-comment", "starts inside a comment at line 8",
     "# Cut in a comment\n\n" + include("split", ' lines 8-9 key "return 0"')),
    ("whole-statements-pass", "", "# Whole\n\n" + include("split", ' lines 3-6 key "return sum"')),
    ("excerpt-repeats-lines", "repeats lines 5-6", "# Twice\n\n" + include("split", ' lines 3-6 key "return sum"')
     + "\n\n" + include("split", ' lines 5-6,9-9 key "return 0"')),
    ("caption-names-code-not-shown", "name \"hit.time\", which the slide's code does not contain",
     "# Promise\n\n" + include("short") + "\n\nThe time of impact is `hit.time`."),
    ("figure-used-by-no-deck", "figures/orphan.svg: used by no deck", "# No figure\n\n- text", "orphan.svg"),
    ("seed-in-code", "words for insiders", "# Rules\n\n" + include("internal")),
    ("seed-in-text", "words for insiders", "# Layers\n\n- As seed 004 says, time order matters"),
    ("old-course-code", "words for insiders", "# Radius\n\n- Old course code: radius = width / 2"),
    ("last-years", "words for insiders", "# Fixing last year's mistake\n\n- The edge rule"),
    ("insider-words-in-notes-allowed", "",
     "# Fine\n\n- The edge rule\n\n<!-- Last year's slides had it wrong; say so, it helps. -->"),
    # A reader can follow an excerpt: a local it uses is declared on the slide or explained.
    ("excerpt-uses-a-name-it-does-not-declare", "uses sum, declared at line 3 of the region",
     "# Which sum?\n\n" + include("split", ' lines 5-6 key "return sum"')),
    ("name-explained-in-the-caption-passes", "",
     "# Explained\n\n" + include("split", ' lines 5-6 key "return sum"') + "\n\n`sum` is a + b."),
    # A slide never hands students a graded answer.
    ("excerpt-inside-a-task-block", "shows the answer to labs/01_lab/Lab.cpp's task 1",
     "# The answer\n\n" + include_from("labs/01_lab/Lab.cpp", "lab-answer")),
    ("excerpt-copies-a-task-answer", "lines of the answer to lab 01 task 1 (labs/01_lab/Lab.cpp:4)",
     "# A copy\n\n" + include("copied")),
    # One deck says a thing once, even from two regions.
    ("two-excerpts-repeat-lines", "repeats 3 lines already shown at",
     "# Speed\n\n" + include("repeat-a") + "\n\n---\n\n# Again\n\n" + include("repeat-b") + "\n\n<!-- " + NOTES + " -->"),
    # Speaker notes help the one presenting.
    ("notes-only-point-to-the-next-deck", "speaker notes say too little",
     "# Summary\n\n- The edge rule", None, "Next: the next deck."),
    ("notes-name-an-authoring-source", 'by its authoring name: "the top-down report"',
     "# Capsules\n\n- Round ends", None, "From the top-down report: a capsule is a rectangle with round ends."),
]

# Stand-in programs for the figure cases: each writes a "PNG" made of its arguments.
STAND_INS = {
    "steady": """#!/usr/bin/env bash
# Draws its arguments: the same picture for the same arguments.
out=""; args=()
while [[ $# -gt 0 ]]; do
    if [[ "$1" == --screenshot ]]; then out="$2"; shift 2; else args+=("$1"); shift; fi
done
printf '%s\\n' "${args[@]}" >"$out"
""",
    "clock": """#!/usr/bin/env bash
# Draws a timing, as a debug build's readout does: different on every run.
while [[ $# -gt 0 ]]; do [[ "$1" == --screenshot ]] && out="$2"; shift; done
echo "collision: $(date +%N) ms" >"$out"
""",
    "ticker": """#!/usr/bin/env bash
# Paints a real PNG with a run-dependent corner, as a timing readout would be: only the 4 x 2
# pixels at (8, 12) change from run to run.
while [[ $# -gt 0 ]]; do [[ "$1" == --screenshot ]] && out="$2"; shift; done
ffmpeg -nostdin -loglevel error -y -f lavfi -i "color=c=0x204080:s=16x16" \
    -vf "drawbox=x=8:y=12:w=4:h=2:t=fill:c=0x$(date +%N | cut -c1-6)" -frames:v 1 "$out"
""",
    "deaf": """#!/usr/bin/env bash
# Ignores every option: a "debug view" that looks the same as the plain one.
while [[ $# -gt 0 ]]; do [[ "$1" == --screenshot ]] && out="$2"; shift; done
echo "the same picture" >"$out"
""",
    "painter": """#!/usr/bin/env bash
# Paints a real PNG whose colour follows --frames: an animation's frames differ.
frames=0
while [[ $# -gt 0 ]]; do
    case "$1" in --screenshot) out="$2"; shift ;; --frames) frames="$2"; shift ;; esac
    shift
done
ffmpeg -nostdin -loglevel error -y -f lavfi -i "color=c=0x$(printf '%02x' $((frames % 256)))4080:s=16x16" \\
    -frames:v 1 "$out"
""",
}

# (name, the message make-figures must fail with or "" to pass, the line of figures.txt)
FIGURE_CASES = [
    ("figure-clean-passes", "", "shot.png programs/steady --frames 2 text=0 | --debug"),
    ("figure-with-timing", "two runs drew different pictures", "shot.png programs/clock --frames 2 text=0"),
    ("figure-claim-not-drawn", "claims '--debug' but looks the same without it",
     "shot.png programs/deaf --frames 2 text=0 | --debug"),
    ("figure-program-missing", "program programs/nothing not found", "shot.png programs/nothing --frames 2 text=0"),
    ("animation-without-frames", "an animation needs frames=FIRST:LAST:STEP",
     "moving.apng programs/painter --debug text=0"),
    # The smallest text on a figure must be stated, so the slide can be checked for it.
    ("figure-without-text-size", "needs text=PX", "shot.png programs/steady --frames 2"),
]
# Needs ffmpeg: real pictures.
PICTURE_CASES = [
    ("animation-clean-passes", "", "moving.apng programs/painter frames=10:50:20 text=0"),
    # The message names where two runs differ (the timing's place), so it can be left out.
    ("figure-with-timing-named-where", "two runs drew different pictures, in crop=4:2:8:12",
     "shot.png programs/ticker --frames 2 text=0"),
]
FFMPEG = ["ffmpeg", "-nostdin", "-loglevel", "error", "-y"]


class Results:
    def __init__(self):
        self.passed, self.failed = 0, 0

    def report(self, name, ok, why=""):
        if ok:
            self.passed += 1
            print("ok   " + name, flush=True)
        else:
            self.failed += 1
            print(f"FAIL {name}: {why}", file=sys.stderr, flush=True)

    def expect(self, name, expected, status, output):
        """A case passes when it expected no failure and saw none, or saw the EXPECTED message."""
        if not expected:
            self.report(name, status == 0, "expected to pass, got: " + output)
        else:
            self.report(name, status != 0 and expected in output,
                        f'expected a failure with "{expected}", got (exit {status}): {output}')


def run(command, **options):
    """COMMAND's exit status and its stdout and stderr together, trailing newlines dropped."""
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          errors="replace", **options)
    return done.returncode, done.stdout.rstrip("\n")


def write(path, text, mode=None):
    with open(path, "w", encoding="utf-8") as out:
        out.write(text)
    if mode is not None:
        os.chmod(path, mode)


def deck_case(results, work, root, name, expected, body, unused_figure=None, notes=NOTES):
    """One deck with a title slide and BODY, through include-regions and check-decks."""
    folder = os.path.join(work, name)
    for sub in ("src", "decks", "dist", "figures"):
        os.makedirs(os.path.join(folder, sub))
    if unused_figure:
        write(os.path.join(folder, "figures", unused_figure), '<svg xmlns="http://www.w3.org/2000/svg"/>\n')
    write(os.path.join(folder, "src", "01-test.md"), '---\nmarp: true\ntitle: "Test"\n---\n\n# Test\n\n'
          f"<!-- {NOTES} -->\n\n---\n\n{body}\n\n<!--\n{notes}\n-->\n")
    write(os.path.join(folder, "dist", "01-test.html"), "<html></html>\n")
    status, output = run(["node", os.path.join(SLIDES, "tools", "include-regions.mjs"), "--root", root,
                          "--src", folder + "/src", "--out", folder + "/decks"])
    if status == 0:
        status, checked = run(["node", os.path.join(SLIDES, "tools", "check-decks.mjs"), "--decks", folder + "/decks",
                               "--dist", folder + "/dist", "--concepts", work + "/concepts.txt",
                               "--src", folder + "/src", "--figures", folder + "/figures"])
        output = "\n".join(part for part in (output, checked) if part)
    results.expect(name, expected, status, output)


def notes_deck_case(results, work):
    """The notes PDF prints every speaker note: one that starts with a scoped name
    ("hitbox::f (F.h) is ...") is a note, not a Marp directive, as in Marp's presenter view."""
    folder = os.path.join(work, "notes-deck")
    for sub in ("decks", "notes", "dist"):
        os.makedirs(os.path.join(folder, sub))
    write(os.path.join(folder, "decks", "01-test.md"), '---\nmarp: true\ntitle: "Test"\n---\n\n'
          "<!-- _class: lead -->\n\n# Code\n\n<!--\nhitbox::elasticCollision (Response.h) is the formula.\n-->\n")
    status, output = run(["node", os.path.join(SLIDES, "tools", "deck-extras.mjs"), "--decks", folder + "/decks",
                          "--notes", folder + "/notes", "--dist", folder + "/dist"])
    notes_file = os.path.join(folder, "notes", "01-test-notes.md")
    printed = open(notes_file, encoding="utf-8").read() if os.path.exists(notes_file) else ""
    results.report("notes-deck-keeps-a-note-starting-with-a-scoped-name",
                   status == 0 and "is the formula" in printed and "_class: lead" not in printed.split("# Code")[-1],
                   f"expected the note in {notes_file}, got (exit {status}): {output}")


def format_case(results, work, root):
    """Statements from a function body, formatted to fit the slide, keep their spaces: alone at
    file scope clang-format read `box.height * scale.y` as a pointer type (`box.height* scale.y`)."""
    folder = os.path.join(work, "format")
    for sub in ("src", "decks"):
        os.makedirs(os.path.join(folder, sub))
    write(os.path.join(folder, "src", "01-test.md"), '---\nmarp: true\ntitle: "Test"\n---\n\n# Test\n\n'
          + include("product", ' lines 3-6 key "std::fmin"') + f"\n\n<!--\n{NOTES}\n-->\n")
    status, output = run(["node", os.path.join(SLIDES, "tools", "include-regions.mjs"), "--root", root,
                          "--src", folder + "/src", "--out", folder + "/decks"])
    deck = os.path.join(folder, "decks", "01-test.md")
    shown = open(deck, encoding="utf-8").read() if os.path.exists(deck) else ""
    results.report("excerpt-from-a-body-formatted-as-statements",
                   status == 0 and "box.height * scale.y" in shown and "box.height*" not in shown,
                   f"expected `box.height * scale.y` in {deck}, got (exit {status}): {output}\n{shown}")


def pdf_links_case(results, work):
    """A handout PDF links no page of the build machine: the links to the other lectures become
    their titles and PDF names as text (Chromium would print a file:// link to the build's disk)."""
    folder = os.path.join(work, "pdf-links")
    os.makedirs(os.path.join(folder, "in"))
    write(os.path.join(folder, "in", "01-test.md"), "# Next lecture\n\n**Next:** [Two](02-two.html)\n\n"
          "Previous: [Zero](00-zero.html#3)\n\n[All lectures](index.html)\n")
    status, output = run(["node", os.path.join(SLIDES, "tools", "inline-images.mjs"), "--in", folder + "/in",
                          "--out", folder + "/out"])
    made = os.path.join(folder, "out", "01-test.md")
    printed = open(made, encoding="utf-8").read() if os.path.exists(made) else ""
    results.report("pdf-deck-links-no-local-page",
                   status == 0 and "Two (02-two.pdf)" in printed and "Zero (00-zero.pdf)" in printed
                   and ".html)" not in printed and "index.html" in printed,
                   f"expected the links as text in {made}, got (exit {status}): {output}\n{printed}")


def figure_case(results, work, name, expected, line):
    write(os.path.join(work, name + ".txt"), line + "\n")
    environment = dict(os.environ, DISPLAY=os.environ.get("DISPLAY") or ":none")
    status, output = run([sys.executable, os.path.join(SLIDES, "make-figures.py"), work, "--list",
                          os.path.join(work, name + ".txt"), "--out", os.path.join(work, name + "-figures")],
                         env=environment)
    results.expect(name, expected, status, output)


def still_cases(results, work):
    """The still must be clean frames: one laid over the others (an onion skin) must fail."""
    check_stills = os.path.join(SLIDES, "tools", "check-stills.sh")
    moving = os.path.join(work, "animation-clean-passes-figures", "moving")
    status = subprocess.run([check_stills, moving + ".apng"], capture_output=True).returncode
    results.report("animation-still-of-clean-frames", status == 0, f"exit {status}")
    subprocess.run(FFMPEG + ["-i", moving + ".apng", "-vf", "tblend=all_mode=average", "-frames:v", "1",
                             "-update", "1", work + "/onion.png"], check=True)
    subprocess.run(FFMPEG + ["-i", work + "/onion.png", "-vf", "pad=iw:ih+24:0:24:white", moving + ".png"], check=True)
    status, output = run([check_stills, moving + ".apng"])
    results.report("animation-still-overprinted", status == 1 and "is not one frame of" in output,
                   f"expected a failure naming the panel, got (exit {status}): {output}")


def marp_html(source, dist):
    subprocess.run(["node_modules/.bin/marp", "--config-file", "marp.config.mjs", "--input-dir", source,
                    "--output", dist, "--html"], cwd=SLIDES, capture_output=True, check=True)


def label_svg(path, size):
    svg = ET.Element("svg", xmlns="http://www.w3.org/2000/svg", viewBox="0 0 600 450")
    ET.SubElement(svg, "rect", width="600", height="450", fill="white")
    ET.SubElement(svg, "text", {"x": "20", "y": "200", "font-size": str(size)}).text = "a label"
    ET.ElementTree(svg).write(path)


def still_svg(path, border_inside):
    """An interactive figure's still: white, a frame, and an answer panel on the right. The
    frame inside the picture and drawn last is whole; the old one (1 px of light grey on the
    picture's edge, half outside it, drawn first: the panel's white covers its right side) is
    lost in print."""
    svg = ET.Element("svg", xmlns="http://www.w3.org/2000/svg", viewBox="0 0 1160 540", width="1160", height="540")
    frame = {"fill": "none", "stroke": "#999", "stroke-width": "4"}
    outline = dict(frame, x="2", y="2", width="1156", height="536") if border_inside else \
        dict(frame, x="0", y="0", width="1160", height="540", stroke="#ddd", **{"stroke-width": "1"})
    if not border_inside:
        ET.SubElement(svg, "rect", outline)
    ET.SubElement(svg, "rect", {"x": "680", "y": "1", "width": "479", "height": "538", "fill": "#fff"})
    ET.SubElement(svg, "text", {"x": "700", "y": "60", "font-size": "30"}).text = "an answer"
    if border_inside:
        ET.SubElement(svg, "rect", outline)
    ET.ElementTree(svg).write(path)


def picture_cases(results, work, check_layout):
    """Screenshots on slides: text under 24 px as shown (figure-text.json's size times the
    drawn scale), a screenshot whose text size is unknown, one flush against the slide's edge;
    and an interactive still whose border is cut off in print."""
    folder = os.path.join(work, "pictures")
    os.makedirs(folder + "/src")
    os.makedirs(folder + "/dist/figures/generated")
    os.makedirs(folder + "/dist/figures/labs")
    for name in ("clean.png", "small-text.png", "../labs/01.png"):
        subprocess.run(FFMPEG + ["-f", "lavfi", "-i", "color=c=0x202030:s=1200x675", "-frames:v", "1",
                                 f"{folder}/dist/figures/generated/{name}"], check=True)
    sizes = {"clean.png": {"text": 0, "width": 1200, "height": 675},
             "small-text.png": {"text": 14, "width": 1200, "height": 675}}
    write(folder + "/dist/figures/generated/figure-text.json", json.dumps(sizes))
    still_svg(folder + "/dist/figures/whole.svg", True)
    still_svg(folder + "/dist/figures/cut.svg", False)
    slides = ["![bg left:50% fit](figures/generated/clean.png)\n\n- beside it",
              "![bg left:50% fit](figures/generated/small-text.png)\n\n- beside it",
              "![bg left:50% fit](figures/labs/01.png)\n\n- beside it",
              '<img src="figures/generated/clean.png" style="position:absolute;left:0;top:0;width:640px">',
              '<div class="interactive" data-figure="x"><img class="still" src="figures/whole.svg"></div>',
              '<div class="interactive" data-figure="x"><img class="still" src="figures/cut.svg"></div>']
    write(folder + "/src/01-pictures.md", "---\nmarp: true\ntheme: hitbox\n---\n\n" +
          "\n\n---\n\n".join(f"# Slide {i + 1}\n\n{body}" for i, body in enumerate(slides)) + "\n")
    marp_html(folder + "/src", folder + "/dist")
    status, output = run(check_layout + [folder + "/dist"])
    expected = {2: "text in figures/generated/small-text.png (14 px in the picture, drawn at 0.49x)",
                3: "figures/labs/01.png has no known text size", 4: "px from the slide's edge (at least 16)",
                6: "right side(s) in print"}
    for slide, message in expected.items():
        found = any(line.startswith(f"01-pictures.html slide {slide}:") and message in line for line in output.split("\n"))
        results.report(f"picture-slide-{slide}-fails", status != 0 and found,
                       f'expected slide {slide} to fail with "{message}", got (exit {status}): {output}')
    clean = [line for line in output.split("\n") if re.match(r"01-pictures\.html slide [15]:", line)]
    results.report("picture-clean-slides-pass", not clean, f"expected slides 1 and 5 to pass, got: {clean}")


def layout_cases(results, work):
    """A slide whose content runs below its bottom edge, measured in Chromium; and a diagram
    label under 24 px as shown: a 600-wide SVG drawn in 40% of the slide (512 px) with a 20 px
    label is 17 px on the slide; the same SVG with a 30 px label is 25.6 px."""
    check_layout = ["node", os.path.join(SLIDES, "tools", "check-layout.mjs"), "--dist"]
    layout = os.path.join(work, "layout")
    os.makedirs(layout + "/src")
    os.makedirs(layout + "/dist")
    bullets = "".join(f"- bullet number {i}\n" for i in range(1, 21))
    write(layout + "/src/01-layout.md", "---\nmarp: true\ntheme: hitbox\n---\n\n# Fits\n\n- one line\n\n---\n\n"
          "# Too long\n\n" + bullets)
    marp_html(layout + "/src", layout + "/dist")
    status, output = run(check_layout + [layout + "/dist"])
    results.report("layout-content-below-the-slide",
                   status != 0 and "01-layout.html slide 2:" in output and "slide 1:" not in output,
                   f"expected slide 2 (only) to fail, got (exit {status}): {output}")
    labels = os.path.join(work, "labels")
    os.makedirs(labels + "/src")
    os.makedirs(labels + "/dist/figures")
    for size in (20, 30):
        label_svg(f"{labels}/dist/figures/label-{size}.svg", size)
    write(labels + "/src/01-labels.md", "---\nmarp: true\ntheme: hitbox\n---\n\n# Large\n\n"
          "![bg right:40% fit](figures/label-30.svg)\n\n---\n\n# Small\n\n![bg right:40% fit](figures/label-20.svg)\n")
    marp_html(labels + "/src", labels + "/dist")
    status, output = run(check_layout + [labels + "/dist"])
    small = output.find('01-labels.html slide 2: label "a label"')
    results.report("diagram-label-under-24-px",
                   status != 0 and small >= 0 and "17.1 px" in output[small:] and "slide 1:" not in output,
                   f"expected slide 2 (only) to fail at 17.1 px, got (exit {status}): {output}")
    picture_cases(results, work, check_layout)


def main():
    results = Results()
    work = tempfile.mkdtemp()
    try:
        root = os.path.join(work, "project")
        os.makedirs(root + "/src")
        shutil.copy(os.path.join(REPO, ".clang-format"), root)
        write(root + "/src/Example.cpp", EXAMPLE_CPP)
        os.makedirs(root + "/labs/01_lab")
        write(root + "/labs/01_lab/Lab.cpp", LAB_CPP)
        write(work + "/concepts.txt", "")
        for case in DECK_CASES:
            deck_case(results, work, root, *case)
        notes_deck_case(results, work)
        format_case(results, work, root)
        pdf_links_case(results, work)
        os.makedirs(work + "/programs")
        for name, source in STAND_INS.items():
            write(os.path.join(work, "programs", name), source, 0o755)
        for case in FIGURE_CASES:
            figure_case(results, work, *case)
        if shutil.which("ffmpeg"):
            for case in PICTURE_CASES:
                figure_case(results, work, *case)
            still_cases(results, work)
        chrome = os.environ.get("CHROME_PATH") or "/usr/bin/chromium"
        if os.access(os.path.join(SLIDES, "node_modules", ".bin", "marp"), os.X_OK) and os.access(chrome, os.X_OK):
            layout_cases(results, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"slides tests: {results.passed} passed, {results.failed} failed")
    return 0 if results.failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
