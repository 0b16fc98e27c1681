#!/usr/bin/env python3
"""Writes scenes/glint_tex.png, the image texture the demo and image-map scenes use.

Plain standard library (zlib + struct), so it runs anywhere and the file it writes carries no
gAMA/sRGB/iCCP chunk: POV-Ray and glint then both apply their default PNG decoding. The picture
is asymmetric on purpose (a "GLINT" banner, a disc off-centre, a corner marker) so that a flipped
or rotated mapping shows at once.

Usage: scenes/make_texture.py [OUT.png]   (default: glint_tex.png next to this script)
"""
import os
import struct
import sys
import zlib

WIDTH, HEIGHT = 128, 64

# 5x7 bitmap glyphs, one string per row, '#' = ink.
GLYPHS = {
    "G": [" ### ", "#   #", "#    ", "# ###", "#   #", "#   #", " ### "],
    "L": ["#    ", "#    ", "#    ", "#    ", "#    ", "#    ", "#####"],
    "I": ["#####", "  #  ", "  #  ", "  #  ", "  #  ", "  #  ", "#####"],
    "N": ["#   #", "##  #", "# # #", "#  ##", "#   #", "#   #", "#   #"],
    "T": ["#####", "  #  ", "  #  ", "  #  ", "  #  ", "  #  ", "  #  "],
}


def lerp(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


def background(x, y):
    # Warm top, cool bottom, hue sweeping left to right; 8 vertical bands of alternating shade.
    u, v = x / (WIDTH - 1), y / (HEIGHT - 1)
    top = lerp((0.95, 0.35, 0.10), (0.95, 0.80, 0.15), u)
    bottom = lerp((0.10, 0.25, 0.75), (0.10, 0.65, 0.45), u)
    c = lerp(top, bottom, v)
    shade = 1.0 if (x // 16) % 2 == 0 else 0.85
    return tuple(ch * shade for ch in c)


def pixels():
    img = [[background(x, y) for x in range(WIDTH)] for y in range(HEIGHT)]
    # Off-centre white disc with a dark rim.
    cx, cy, r = 100, 40, 14
    for y in range(HEIGHT):
        for x in range(WIDTH):
            d2 = (x - cx) ** 2 + (y - cy) ** 2
            if d2 <= r * r:
                img[y][x] = (0.08, 0.08, 0.1) if d2 >= (r - 2) ** 2 else (0.97, 0.97, 0.95)
    # Red corner marker (top left) shows orientation.
    for y in range(6):
        for x in range(6):
            img[y][x] = (0.9, 0.0, 0.0)
    # "GLINT" at 2x scale with a one-pixel drop shadow.
    scale, x0, y0 = 2, 8, 8
    for i, ch in enumerate("GLINT"):
        for gy, row in enumerate(GLYPHS[ch]):
            for gx, cell in enumerate(row):
                if cell != "#":
                    continue
                for sy in range(scale):
                    for sx in range(scale):
                        px = x0 + i * 6 * scale + gx * scale + sx
                        py = y0 + gy * scale + sy
                        img[py + 1][px + 1] = (0.0, 0.0, 0.0)
                        img[py][px] = (1.0, 1.0, 1.0)
    return img


def png_bytes(img):
    raw = bytearray()
    for row in img:
        raw.append(0)  # filter type None
        for c in row:
            raw.extend(max(0, min(255, round(ch * 255))) for ch in c)

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", WIDTH, HEIGHT, 8, 2, 0, 0, 0)  # 8-bit RGB
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header)
            + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b""))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "glint_tex.png")
    with open(out, "wb") as f:
        f.write(png_bytes(pixels()))


if __name__ == "__main__":
    main()
