#!/usr/bin/env python3
"""Compares the PNG files of two folders pixel by pixel (python3's standard library only).

Usage: scripts/compare-png.py FOLDER_A FOLDER_B
Prints the share of pixels that differ for each picture and exits 1 if a picture is missing,
has another size, or differs in more than TOLERANCE_PERCENT of its pixels. SFML 2 and 3 draw
text and the edges of circles slightly differently (SFML 3's letters are a little narrower;
measured on the 24 lab screenshots: 0.6-3.3 % of the pixels differ), so an exact match is
not expected; a moved object or a missing shape changes far more.
"""
import struct
import sys
import zlib
from pathlib import Path


def pixels(path):
    """Width, height and the unfiltered RGBA rows of an 8-bit RGB or RGBA PNG."""
    data = path.read_bytes()
    width = height = channels = 0
    packed = b""
    position = 8  # after the signature
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position:position + 8])
        body = data[position + 8:position + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            channels = {2: 3, 6: 4}[colour]
            assert depth == 8, "only 8-bit pictures"
        elif kind == b"IDAT":
            packed += body
        position += 12 + length
    raw = zlib.decompress(packed)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, row = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for x in range(stride):  # the five PNG filters (PNG specification, section 9)
            left = row[x - channels] if x >= channels else 0
            up, corner = previous[x], previous[x - channels] if x >= channels else 0
            if kind == 1:
                row[x] = (row[x] + left) & 255
            elif kind == 2:
                row[x] = (row[x] + up) & 255
            elif kind == 3:
                row[x] = (row[x] + (left + up) // 2) & 255
            elif kind == 4:
                guess = left + up - corner
                near = min((abs(guess - left), 0, left), (abs(guess - up), 1, up),
                           (abs(guess - corner), 2, corner))[2]
                row[x] = (row[x] + near) & 255
        rows.append(bytes(row) if channels == 4 else bytes(
            b for i in range(0, stride, 3) for b in row[i:i + 3] + b"\xff"))
        previous = row
    return width, height, b"".join(rows)


TOLERANCE_PERCENT = 4.0


def differing_percent(first, second):
    """The share of pixels, in percent, whose colour differs; None if the sizes differ."""
    width, height, a = pixels(first)
    other_width, other_height, b = pixels(second)
    if (width, height) != (other_width, other_height):
        return None
    differing = sum(1 for i in range(0, len(a), 4) if a[i:i + 4] != b[i:i + 4])
    return 100.0 * differing / (width * height)


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
