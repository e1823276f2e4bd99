#!/usr/bin/env python3
"""Checks that the debug view's three states stay apart for people with colour vision deficiency.

Usage: scripts/check-palette.py OUTPUT_FOLDER SCREENSHOT.png...

Reads the palette from its one home (framework/hitbox/debug/DebugRenderer.cpp), finds each
state's colour in the screenshots (free, touching, overlapping: each must be drawn somewhere),
and simulates protanopia, deuteranopia and tritanopia on them with the matrices of Machado,
Oliveira and Fernandes, "A Physiologically-based Model for Simulation of Color Vision
Deficiency" (IEEE TVCG 15(6), 2009; severity 1.0, applied to linear RGB). Every pair of states,
and each state against the window's background, must stay at least MIN_DELTA_E apart (CIE 1976
colour difference in CIELAB; about 2.3 is just noticeable). The shapes differ too (solid,
dashed, hatched: DebugRenderer.h), so colour is never the only cue; this checks the colours.
Writes each screenshot as seen with each deficiency into OUTPUT_FOLDER (NAME-deuteranopia.png).
Exits 1 naming the pair that came too close, 2 on bad input. Pictures are read and written
with Pillow (python3-pil), through scripts/compare-png.py.
"""
import importlib.util
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MIN_DELTA_E = 30.0
# The red/green pair the debug view used before (free (80, 255, 120), hit (255, 70, 70)) comes
# out only 23.6 apart under deuteranopia: the check must refuse it, or it checks nothing.
KNOWN_BAD = ((80, 255, 120), (255, 70, 70), "deuteranopia")
MIN_PIXELS = 50  # a state counts as drawn when this many pixels have its exact colour
STATES = ("freeColor", "touchingColor", "overlappingColor")
BACKGROUND = "backgroundColor"  # the windows' clear colour, also from DebugRenderer.cpp
SIMULATIONS = {  # Machado et al. 2009, table of severity 1.0
    "protanopia": ((0.152286, 1.052583, -0.204868), (0.114503, 0.786281, 0.099216),
                   (-0.003882, -0.048116, 1.051998)),
    "deuteranopia": ((0.367322, 0.860646, -0.227968), (0.280085, 0.672501, 0.047413),
                     (-0.011820, 0.042940, 0.968881)),
    "tritanopia": ((1.255528, -0.076749, -0.178779), (-0.078411, 0.930809, 0.147602),
                   (0.004733, 0.691367, 0.303900)),
}


def load_png_module():
    """scripts/compare-png.py: reads and writes pictures with Pillow (python3-pil)."""
    spec = importlib.util.spec_from_file_location("compare_png", ROOT / "scripts" / "compare-png.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    module.pillow_image()  # (under a python3 without Pillow, this script restarts under Debian's)
    return module


def palette():
    """The colours DebugRenderer.cpp defines, by name."""
    source = (ROOT / "framework/hitbox/debug/DebugRenderer.cpp").read_text(encoding="utf-8")
    found = re.findall(r"DebugRenderer::(\w+Color)\{(\d+), (\d+), (\d+)\}", source)
    return {name: (int(r), int(g), int(b)) for name, r, g, b in found}


def to_linear(channel):
    c = channel / 255.0
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def to_srgb(value):
    value = min(1.0, max(0.0, value))
    c = value * 12.92 if value <= 0.0031308 else 1.055 * value ** (1 / 2.4) - 0.055
    return round(c * 255)


def simulate(colour, matrix):
    linear = [to_linear(c) for c in colour]
    return tuple(to_srgb(sum(row[i] * linear[i] for i in range(3))) for row in matrix)


def lab(colour):
    """CIELAB (D65) of an sRGB colour."""
    r, g, b = (to_linear(c) for c in colour)
    xyz = (0.4124 * r + 0.3576 * g + 0.1805 * b, 0.2126 * r + 0.7152 * g + 0.0722 * b,
           0.0193 * r + 0.1192 * g + 0.9505 * b)
    white = (0.95047, 1.0, 1.08883)
    f = [t ** (1 / 3) if t > 0.008856 else 7.787 * t + 16 / 116
         for t in (v / w for v, w in zip(xyz, white))]
    return (116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2]))


def delta_e(a, b):
    return sum((x - y) ** 2 for x, y in zip(lab(a), lab(b))) ** 0.5


def main():
    if len(sys.argv) < 3:
        print("usage: check-palette.py OUTPUT_FOLDER SCREENSHOT.png...", file=sys.stderr)
        return 2
    output = Path(sys.argv[1])
    shots = [Path(p) for p in sys.argv[2:]]
    for shot in shots:
        if not shot.is_file():
            print(f"check-palette: no screenshot {shot}", file=sys.stderr)
            return 2
    bad_first, bad_second, bad_deficiency = KNOWN_BAD
    bad_matrix = SIMULATIONS[bad_deficiency]
    if delta_e(simulate(bad_first, bad_matrix), simulate(bad_second, bad_matrix)) >= MIN_DELTA_E:
        print("check-palette: the threshold lets the old red/green pair through", file=sys.stderr)
        return 1
    colours = palette()
    missing = [name for name in STATES + (BACKGROUND,) if name not in colours]
    if missing:
        print(f"check-palette: DebugRenderer.cpp defines no {', '.join(missing)}", file=sys.stderr)
        return 2
    png = load_png_module()
    output.mkdir(parents=True, exist_ok=True)
    drawn = {name: 0 for name in STATES}
    for shot in shots:
        width, height, rgba = png.pixels(shot)
        counts = {}
        for i in range(0, len(rgba), 4):
            key = rgba[i:i + 3]
            counts[key] = counts.get(key, 0) + 1
        for name in STATES:
            drawn[name] += counts.get(bytes(colours[name]), 0)
        for deficiency, matrix in SIMULATIONS.items():
            seen = {key: bytes(simulate(tuple(key), matrix)) for key in counts}
            pixels = bytearray(rgba)
            for i in range(0, len(pixels), 4):
                pixels[i:i + 3] = seen[bytes(pixels[i:i + 3])]
            png.write_png(output / f"{shot.stem}-{deficiency}.png", width, height, bytes(pixels))
    failures = [f"{name} is not drawn in any screenshot" for name in STATES
                if drawn[name] < MIN_PIXELS]
    for deficiency, matrix in SIMULATIONS.items():
        seen = {name: simulate(colours[name], matrix) for name in STATES}
        seen["background"] = simulate(colours[BACKGROUND], matrix)
        names = list(seen)
        for i, first in enumerate(names):
            for second in names[i + 1:]:
                difference = delta_e(seen[first], seen[second])
                line = f"{deficiency}: {first} {seen[first]} vs {second} {seen[second]}: " \
                       f"delta E {difference:.1f}"
                print(("  " if difference >= MIN_DELTA_E else "  TOO CLOSE ") + line)
                if difference < MIN_DELTA_E:
                    failures.append(line)
    if failures:
        for failure in failures:
            print(f"check-palette: {failure} (needs {MIN_DELTA_E})", file=sys.stderr)
        return 1
    print(f"check-palette: free, touching and overlapping stay apart under protanopia, "
          f"deuteranopia and tritanopia (delta E >= {MIN_DELTA_E}); simulations in {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
