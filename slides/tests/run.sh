#!/usr/bin/env bash
# slides/tests/run.sh - shows that the slides' checks catch each mistake they exist for.
#
# Each case plants one defect in a small deck (or a figure list with stand-in programs),
# runs the same tools check.sh runs, and expects them to fail with the right message; the
# clean cases must pass. Needs node and clang-format only (no display, no build): seconds.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
slides="$(cd "$here/.." && pwd)"
repo="$(cd "$slides/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

passed=0
failed=0
pass() { passed=$((passed + 1)); echo "ok   $1"; }
fail() { failed=$((failed + 1)); echo "FAIL $1" >&2; }

# A small project: one source file with slide regions, and the repository's .clang-format.
root="$work/project"
mkdir -p "$root/src"
cp "$repo/.clang-format" "$root/"
cat >"$root/src/Example.cpp" <<'CPP'
// [slide:short]
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

// [slide:tall]
void tall()
{
    int a1 = 1;
    int a2 = 2;
    int a3 = 3;
    int a4 = 4;
    int a5 = 5;
    int a6 = 6;
    int a7 = 7;
    int a8 = 8;
    int a9 = 9;
    int a10 = 10;
    int a11 = 11;
    int a12 = 12;
    int a13 = 13;
    int a14 = 14;
    int a15 = 15;
}
// [/slide]
CPP
: >"$work/concepts.txt"

# deck_case NAME EXPECTED-MESSAGE|"" SLIDE-BODY: one deck with a title slide and SLIDE-BODY;
# the tools must fail with EXPECTED-MESSAGE in their output, or pass when it is "".
deck_case() {
    local name="$1" expected="$2" body="$3"
    local dir="$work/$name"
    mkdir -p "$dir/src" "$dir/decks" "$dir/dist" "$dir/figures"
    [[ -n "${unused_figure:-}" ]] && echo '<svg xmlns="http://www.w3.org/2000/svg"/>' >"$dir/figures/$unused_figure"
    printf -- '---\nmarp: true\ntitle: "Test"\n---\n\n# Test\n\n<!-- notes -->\n\n---\n\n%s\n\n<!--\nNotes.\n-->\n' \
        "$body" >"$dir/src/01-test.md"
    echo '<html></html>' >"$dir/dist/01-test.html"
    local output status=0
    output="$( (node "$slides/tools/include-regions.mjs" --root "$root" --src "$dir/src" --out "$dir/decks" &&
        node "$slides/tools/check-decks.mjs" --decks "$dir/decks" --dist "$dir/dist" \
            --concepts "$work/concepts.txt" --src "$dir/src" --figures "$dir/figures") 2>&1)" || status=$?
    if [[ -z "$expected" ]]; then
        if [[ $status -eq 0 ]]; then pass "$name"; else fail "$name: expected to pass, got: $output"; fi
    elif [[ $status -ne 0 && "$output" == *"$expected"* ]]; then
        pass "$name"
    else
        fail "$name: expected a failure with \"$expected\", got (exit $status): $output"
    fi
}

deck_case clean-deck-passes "" '# A test

<!-- include: src/Example.cpp#short -->'
deck_case code-line-too-long-for-clang-format "characters (at most 78 fit at 24px)" '# Too wide

<!-- include: src/Example.cpp#long-string -->'
deck_case hand-written-code-too-long "characters (at most 78 fit at 24px)" '# Too wide

```cpp
int aVeryLongFunctionName(int firstArgument, int secondArgument, int thirdArgumentHere);
```'
deck_case too-many-code-lines "lines of code (at most 16 fit)" '# Too tall

<!-- include: src/Example.cpp#tall -->'
deck_case excerpt-cut-mid-block "unbalanced brackets" '# Cut short

<!-- include: src/Example.cpp#function lines 1-6 key "sum +=" -->'
deck_case excerpt-cut-before-key-line "does not contain its key line" '# Cut before the point

<!-- include: src/Example.cpp#function lines 1-3 key "return sum" -->'
deck_case part-without-key-line 'needs key "TEXT"' '# No key

<!-- include: src/Example.cpp#function lines 3-4 -->'
deck_case part-with-gap-passes "" '# Parts

<!-- include: src/Example.cpp#function lines 1-3,8-9 key "return sum" -->'
# An excerpt is a whole thing: it starts and ends on a statement boundary.
deck_case excerpt-starts-mid-statement "starts mid-statement at line 4" '# Cut at the start

<!-- include: src/Example.cpp#split lines 4-6 key "return sum" -->'
deck_case excerpt-ends-mid-statement "ends mid-statement at line 5" '# Cut at the end

<!-- include: src/Example.cpp#split lines 3-5 key "if (sum" -->'
deck_case excerpt-ends-on-a-comment "ends on a comment at line 7" '# Cut after a comment

<!-- include: src/Example.cpp#split lines 3-7 key "sum > 0" -->'
deck_case excerpt-starts-inside-a-comment "starts inside a comment at line 8" '# Cut in a comment

<!-- include: src/Example.cpp#split lines 8-9 key "return 0" -->'
deck_case whole-statements-pass "" '# Whole

<!-- include: src/Example.cpp#split lines 3-6 key "return sum" -->'
deck_case excerpt-repeats-lines "repeats lines 5-6" '# Twice

<!-- include: src/Example.cpp#split lines 3-6 key "return sum" -->

<!-- include: src/Example.cpp#split lines 5-6,9-9 key "return 0" -->'
deck_case caption-names-code-not-shown "name \"hit.time\", which the slide's code does not contain" '# Promise

<!-- include: src/Example.cpp#short -->

The time of impact is `hit.time`.'
unused_figure=orphan.svg deck_case figure-used-by-no-deck "figures/orphan.svg: used by no deck" '# No figure

- text'

deck_case seed-in-code "words for insiders" '# Rules

<!-- include: src/Example.cpp#internal -->'
deck_case seed-in-text "words for insiders" '# Layers

- As seed 004 says, time order matters'
deck_case old-course-code "words for insiders" '# Radius

- Old course code: radius = width / 2'
deck_case last-years "words for insiders" "# Fixing last year's mistake

- The edge rule"
deck_case insider-words-in-notes-allowed "" '# Fine

- The edge rule

<!-- From seed 002; last year'"'"'s slides had it wrong. -->'

# Figures: stand-in programs write a "PNG" made of their arguments.
programs="$work/programs"
mkdir -p "$programs"
cat >"$programs/steady" <<'SH'
#!/usr/bin/env bash
# Draws its arguments: the same picture for the same arguments.
out=""; args=()
while [[ $# -gt 0 ]]; do
    if [[ "$1" == --screenshot ]]; then out="$2"; shift 2; else args+=("$1"); shift; fi
done
printf '%s\n' "${args[@]}" >"$out"
SH
cat >"$programs/clock" <<'SH'
#!/usr/bin/env bash
# Draws a timing, as a debug build's readout does: different on every run.
while [[ $# -gt 0 ]]; do [[ "$1" == --screenshot ]] && out="$2"; shift; done
echo "collision: $(date +%N) ms" >"$out"
SH
cat >"$programs/deaf" <<'SH'
#!/usr/bin/env bash
# Ignores every option: a "debug view" that looks the same as the plain one.
while [[ $# -gt 0 ]]; do [[ "$1" == --screenshot ]] && out="$2"; shift; done
echo "the same picture" >"$out"
SH
cat >"$programs/painter" <<'SH'
#!/usr/bin/env bash
# Paints a real PNG whose colour follows --frames: an animation's frames differ.
frames=0
while [[ $# -gt 0 ]]; do
    case "$1" in --screenshot) out="$2"; shift ;; --frames) frames="$2"; shift ;; esac
    shift
done
ffmpeg -nostdin -loglevel error -y -f lavfi -i "color=c=0x$(printf '%02x' $((frames % 256)))4080:s=16x16" \
    -frames:v 1 "$out"
SH
chmod +x "$programs"/*

figure_case() {
    local name="$1" expected="$2" line="$3"
    echo "$line" >"$work/$name.txt"
    local output status=0
    output="$(DISPLAY="${DISPLAY:-:none}" "$slides/make-figures.sh" "$work" --list "$work/$name.txt" \
        --out "$work/$name-figures" 2>&1)" || status=$?
    if [[ -z "$expected" ]]; then
        if [[ $status -eq 0 ]]; then pass "$name"; else fail "$name: expected to pass, got: $output"; fi
    elif [[ $status -ne 0 && "$output" == *"$expected"* ]]; then
        pass "$name"
    else
        fail "$name: expected a failure with \"$expected\", got (exit $status): $output"
    fi
}

figure_case figure-clean-passes "" "shot.png programs/steady --frames 2 | --debug"
figure_case figure-with-timing "two runs drew different pictures" "shot.png programs/clock --frames 2"
figure_case figure-claim-not-drawn "claims '--debug' but looks the same without it" \
    "shot.png programs/deaf --frames 2 | --debug"
figure_case figure-program-missing "program programs/nothing not found" "shot.png programs/nothing --frames 2"

figure_case animation-without-frames "an animation needs frames=FIRST:LAST:STEP" \
    "moving.apng programs/painter --debug"
if command -v ffmpeg >/dev/null; then
    figure_case animation-clean-passes "" "moving.apng programs/painter frames=10:50:20"
    # The still must be clean frames: one laid over the others (an onion skin) must fail.
    moving="$work/animation-clean-passes-figures/moving"
    status=0
    "$slides/tools/check-stills.sh" "$moving.apng" >/dev/null 2>&1 || status=$?
    if [[ $status -eq 0 ]]; then pass animation-still-of-clean-frames; else fail "animation-still-of-clean-frames: exit $status"; fi
    ffmpeg -nostdin -loglevel error -y -i "$moving.apng" -vf "tblend=all_mode=average" -frames:v 1 -update 1 \
        "$work/onion.png"
    ffmpeg -nostdin -loglevel error -y -i "$work/onion.png" -vf "pad=iw:ih+24:0:24:white" "$moving.png"
    status=0
    output="$("$slides/tools/check-stills.sh" "$moving.apng" 2>&1)" || status=$?
    if [[ $status -eq 1 && "$output" == *"is not one frame of"* ]]; then
        pass animation-still-overprinted
    else
        fail "animation-still-overprinted: expected a failure naming the panel, got (exit $status): $output"
    fi
fi

# Layout: a slide whose content runs below its bottom edge, measured in Chromium.
if [[ -x "$slides/node_modules/.bin/marp" && -x "${CHROME_PATH:-/usr/bin/chromium}" ]]; then
    layout="$work/layout"
    mkdir -p "$layout/src" "$layout/dist"
    {
        printf -- '---\nmarp: true\ntheme: hitbox\n---\n\n# Fits\n\n- one line\n\n---\n\n# Too long\n\n'
        for i in $(seq 1 20); do echo "- bullet number $i"; done
    } >"$layout/src/01-layout.md"
    (cd "$slides" && node_modules/.bin/marp --config-file marp.config.mjs --input-dir "$layout/src" \
        --output "$layout/dist" --html >/dev/null 2>&1)
    status=0
    output="$(node "$slides/tools/check-layout.mjs" --dist "$layout/dist" 2>&1)" || status=$?
    if [[ $status -ne 0 && "$output" == *"01-layout.html slide 2:"* && "$output" != *"slide 1:"* ]]; then
        pass layout-content-below-the-slide
    else
        fail "layout-content-below-the-slide: expected slide 2 (only) to fail, got (exit $status): $output"
    fi

    # A diagram label under 24 px as shown: a 600-wide SVG drawn in 40% of the slide (512 px)
    # with a 20 px label is 17 px on the slide; the same SVG with a 30 px label is 25.6 px.
    labels="$work/labels"
    mkdir -p "$labels/src" "$labels/dist/figures"
    for size in 20 30; do
        python3 - "$labels/dist/figures/label-$size.svg" "$size" <<'PY'
import sys
import xml.etree.ElementTree as ET
svg = ET.Element("svg", xmlns="http://www.w3.org/2000/svg", viewBox="0 0 600 450")
ET.SubElement(svg, "rect", width="600", height="450", fill="white")
ET.SubElement(svg, "text", {"x": "20", "y": "200", "font-size": sys.argv[2]}).text = "a label"
ET.ElementTree(svg).write(sys.argv[1])
PY
    done
    printf -- '---\nmarp: true\ntheme: hitbox\n---\n\n# Large\n\n![bg right:40%% fit](figures/label-30.svg)\n\n---\n\n# Small\n\n![bg right:40%% fit](figures/label-20.svg)\n' >"$labels/src/01-labels.md"
    (cd "$slides" && node_modules/.bin/marp --config-file marp.config.mjs --input-dir "$labels/src" \
        --output "$labels/dist" --html >/dev/null 2>&1)
    status=0
    output="$(node "$slides/tools/check-layout.mjs" --dist "$labels/dist" 2>&1)" || status=$?
    if [[ $status -ne 0 && "$output" == *"01-labels.html slide 2: label \"a label\""*"17.1 px"* && "$output" != *"slide 1:"* ]]; then
        pass diagram-label-under-24-px
    else
        fail "diagram-label-under-24-px: expected slide 2 (only) to fail at 17.1 px, got (exit $status): $output"
    fi
fi

echo "slides tests: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
