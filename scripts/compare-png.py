#!/usr/bin/env python3
"""Compares the PNG files of two folders pixel by pixel (python3's standard library only).

Usage: scripts/compare-png.py FOLDER_A FOLDER_B
Prints one line per picture that differs (or is missing) and exits 1 if any does.
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


def main():
    first, second = Path(sys.argv[1]), Path(sys.argv[2])
    different = 0
    for picture in sorted(first.glob("*.png")):
        other = second / picture.name
        if not other.exists():
            print(f"compare-png: {picture.name} is missing in {second}")
            different += 1
        elif pixels(picture) != pixels(other):
            print(f"compare-png: {picture.name} differs between {first} and {second}")
            different += 1
    print(f"compare-png: {len(list(first.glob('*.png'))) - different} pictures the same, "
          f"{different} different")
    return 1 if different else 0


if __name__ == "__main__":
    sys.exit(main())
