#!/usr/bin/env python3
"""Writes scenes/heightfield.png, the 8-bit grey height map of scenes/height_field.pov.

Plain standard library (zlib + struct), like make_texture.py. The terrain is asymmetric on
purpose (a high ridge off-centre, a crater, a terrace) so that a flipped or transposed mapping
shows at once; the border rows stay low so the water level cuts them away.

Usage: scenes/make_heightfield.py [OUT.png]   (default: heightfield.png next to this script)
"""
import math
import os
import struct
import sys
import zlib

SIZE = 48


def height(x, y):
    u, v = x / (SIZE - 1), y / (SIZE - 1)
    h = 0.55 * math.exp(-((u - 0.3) ** 2 * 18 + (v - 0.35) ** 2 * 6))  # ridge, upper left
    r = math.hypot(u - 0.7, v - 0.65)
    h += 0.45 * math.exp(-((r - 0.16) ** 2) * 300)  # crater rim, lower right
    h += 0.15 * (math.sin(u * 9) * math.cos(v * 7) + 1) / 2  # rolling ground
    if u > 0.75 and v < 0.3:
        h = max(h, 0.35)  # a flat terrace
    return min(max(h, 0.0), 1.0)


def png(path, rows):
    raw = b"".join(b"\x00" + bytes(r) for r in rows)

    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 0, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "heightfield.png")
    rows = [[round(255 * height(x, y)) for x in range(SIZE)] for y in range(SIZE)]
    png(out, rows)


if __name__ == "__main__":
    main()
