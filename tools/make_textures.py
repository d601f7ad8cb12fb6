#!/usr/bin/env python3
"""Writes the corpus's texture images (corpus/textures/, corpus/seeds/003/) and the checkerboard floor's grid mesh
(corpus/meshes/checker_floor.obj), so they can be remade and reviewed.

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


def floor_obj(path, cells_x=16, cells_z=20, size=10.0, x0=-80.0, z0=6.0):
    """A grid of square cells on y = 0, from (x0, z0) towards -z, with u = (x - x0) / 4 and v = (z0 - z) / 4.

    A grid rather than one big quad: small triangles are not clipped by the near plane, so their barycentrics (and
    so their texture coordinates) keep the tight bounds of unclipped triangles."""
    lines = ["# The checkerboard floor of checker_floor.yaml: %d x %d cells of %g units, written by "
             "tools/make_textures.py." % (cells_x, cells_z, size)]
    for j in range(cells_z + 1):
        for i in range(cells_x + 1):
            x, z = x0 + i * size, z0 - j * size
            lines.append("v %g 0 %g" % (x, z))
            lines.append("vt %g %g" % ((x - x0) / 4.0, (z0 - z) / 4.0))
    lines.append("vn 0 1 0")
    row = cells_x + 1
    for j in range(cells_z):
        for i in range(cells_x):
            a = j * row + i + 1
            b, c, d = a + 1, a + row + 1, a + row
            lines.append("f %d/%d/1 %d/%d/1 %d/%d/1 %d/%d/1" % (a, a, b, b, c, c, d, d))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    out = os.path.join(ROOT, "corpus", "textures")
    os.makedirs(out, exist_ok=True)
    write_png(os.path.join(out, "checker.png"), 240, 240, checker(8, 240))  # not a power of two either
    write_png(os.path.join(out, "crate.png"), 120, 90, crate(120, 90))  # not a power of two
    write_ppm(os.path.join(ROOT, "corpus", "seeds", "003", "checker.ppm"), 64, 64, checker(4, 64))
    floor_obj(os.path.join(ROOT, "corpus", "meshes", "checker_floor.obj"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
