#!/usr/bin/env python3
"""Writes the corpus's texture images (corpus/textures/, corpus/seeds/003/), so they can be remade and reviewed.

Each is asymmetric in u and in v, so a texture drawn mirrored or upside down differs from the right one.
"""
import os
import struct
import sys
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def write_png(path, width, height, pixel):
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def write_ppm(path, width, height, pixel):
    with open(path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (width, height))
        f.write(bytes(c for y in range(height) for x in range(width) for c in pixel(x, y)))


def checker(squares, size):
    """A squares x squares board: light squares near-white, dark ones coloured by their column and row."""
    cell = size // squares

    def pixel(x, y):
        i, j = x // cell, y // cell
        if (i + j) % 2 == 0:
            return (230, 230, 230)
        return (40 + 200 * i // (squares - 1), 60, 40 + 200 * j // (squares - 1))

    return pixel


def crate(width, height):
    """A plank pattern with a frame, a diagonal brace and a marker in the top-left corner."""

    def pixel(x, y):
        if x < width // 6 and y < height // 5:
            return (200, 30, 30)  # top-left marker: shows a flip at once
        if x < 6 or y < 6 or x >= width - 6 or y >= height - 6:
            return (90, 55, 25)
        if abs(x * height - y * width) < 5 * width:
            return (110, 70, 30)
        plank = (y // 16) % 2
        return (170 + 25 * plank, 120 + 20 * plank, 60 + 10 * plank)

    return pixel


def main():
    out = os.path.join(ROOT, "corpus", "textures")
    os.makedirs(out, exist_ok=True)
    write_png(os.path.join(out, "checker.png"), 256, 256, checker(8, 256))
    write_png(os.path.join(out, "crate.png"), 120, 90, crate(120, 90))  # not a power of two
    write_ppm(os.path.join(ROOT, "corpus", "seeds", "003", "checker.ppm"), 64, 64, checker(4, 64))
    return 0


if __name__ == "__main__":
    sys.exit(main())
