#!/usr/bin/env python3
"""Compares the PNG files of two folders pixel by pixel (Pillow decodes them).

Usage: scripts/compare-png.py FOLDER_A FOLDER_B
Prints the share of pixels that differ for each picture and exits 1 if a picture is missing,
has another size, or differs in more than TOLERANCE_PERCENT of its pixels. SFML 2 and 3 draw
text and the edges of circles slightly differently (SFML 3's letters are a little narrower;
measured on the 24 lab screenshots: 0.6-3.3 % of the pixels differ), so an exact match is
not expected; a moved object or a missing shape changes far more.
Pillow is Debian's python3-pil (scripts/install-deps.sh installs it), which Debian's own
python3 imports: run under another python3 (a pyenv, a venv) without Pillow, the script
starts itself again under /usr/bin/python3. Exit 2 when neither has Pillow.
"""
import os
import sys
from pathlib import Path

DEBIAN_PYTHON = "/usr/bin/python3"


def pillow_image():
    """PIL.Image; restarts the running command under Debian's python3 when this one lacks Pillow.
    The command as python3 was given it (sys.orig_argv, Python 3.10+), so a script and
    `python3 -m unittest ...` both restart whole: call this before the command does anything."""
    try:
        from PIL import Image
        return Image
    except ImportError:
        if os.path.exists(DEBIAN_PYTHON) and os.path.realpath(sys.executable) != os.path.realpath(DEBIAN_PYTHON):
            os.execv(DEBIAN_PYTHON, [DEBIAN_PYTHON, *sys.orig_argv[1:]])
        print(f"{Path(sys.argv[0]).name}: needs Pillow (Debian: python3-pil; scripts/install-deps.sh installs it)",
              file=sys.stderr)
        sys.exit(2)


def pixels(path):
    """Width, height and the RGBA bytes, row by row, of a picture."""
    with pillow_image().open(path) as picture:
        rgba = picture.convert("RGBA")
        return rgba.width, rgba.height, rgba.tobytes()


def write_png(path, width, height, rgba):
    """Writes RGBA bytes, row by row, as a PNG."""
    pillow_image().frombytes("RGBA", (width, height), bytes(rgba)).save(path, format="PNG")


TOLERANCE_PERCENT = 4.0


def differing_pixels(first, second):
    """(how many pixels differ in colour, how many there are) in two pictures; None if the sizes differ."""
    width, height, a = pixels(first)
    other_width, other_height, b = pixels(second)
    if (width, height) != (other_width, other_height):
        return None
    return sum(1 for i in range(0, len(a), 4) if a[i:i + 4] != b[i:i + 4]), width * height


def differing_percent(first, second):
    """The share of pixels, in percent, whose colour differs; None if the sizes differ."""
    counted = differing_pixels(first, second)
    return None if counted is None else 100.0 * counted[0] / counted[1]


def main():
    first, second = Path(sys.argv[1]), Path(sys.argv[2])
    different = 0
    for picture in sorted(first.glob("*.png")):
        other = second / picture.name
        if not other.exists():
            print(f"compare-png: {picture.name} is missing in {second}")
            different += 1
        else:
            percent = differing_percent(picture, other)
            if percent is None or percent > TOLERANCE_PERCENT:
                shown = "another size" if percent is None else f"{percent:.2f} % of the pixels"
                print(f"compare-png: {picture.name} differs: {shown} (at most "
                      f"{TOLERANCE_PERCENT} % may)")
                different += 1
            else:
                print(f"compare-png: {picture.name}: {percent:.2f} % of the pixels differ")
    print(f"compare-png: {len(list(first.glob('*.png'))) - different} pictures alike, "
          f"{different} different")
    return 1 if different else 0


if __name__ == "__main__":
    sys.exit(main())
