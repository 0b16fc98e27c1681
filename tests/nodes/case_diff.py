"""Per-case differences between glint's render of a node family and Cycles' (README.md).

    blender -b --factory-startup --python tests/nodes/case_diff.py -- \
        CASE_DIR GLINT.exr [--all] [--tolerance 1]

CASE_DIR is tests/nodes/cases/<family> (its cases.json says where each case's tile is).
Prints, per case: the largest difference of the 8-bit sRGB values (as `glint compare` encodes
them), the fraction of the tile's pixels within --tolerance, the largest linear difference and
Cycles' range over the tile; --all prints every case, else only those off by more than the
tolerance. Blender is used only to read OpenEXR (numpy comes with it).
"""

import json
import os
import sys

import bpy
import numpy as np


def read_exr(path):
    img = bpy.data.images.load(os.path.abspath(path))
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float64).reshape(h, w, 4)[::-1, :, :3]
    bpy.data.images.remove(img)
    return px


def srgb8(x):
    x = np.nan_to_num(np.clip(x, 0.0, 1.0))
    s = np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
    return np.round(s * 255.0).astype(np.int32)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    show_all = "--all" in argv
    tol = 1
    if "--tolerance" in argv:
        tol = int(argv[argv.index("--tolerance") + 1])
    args = [a for a in argv if not a.startswith("--") and not a.isdigit()]
    case_dir, glint_exr = args[0], args[1]
    with open(os.path.join(case_dir, "cases.json"), encoding="utf-8") as f:
        layout = json.load(f)
    ref = read_exr(os.path.join(case_dir, "cycles.exr"))
    out = read_exr(glint_exr)
    d8 = np.abs(srgb8(out) - srgb8(ref)).max(axis=2)
    dl = np.abs(out - ref).max(axis=2)
    print("%-44s %5s %8s %11s  %s" % ("case", "max8", "within", "max_linear", "cycles range"))
    worst = 0
    for c in layout["cases"]:
        x0, y0, x1, y1 = c["rect"]
        t8, tl, r = d8[y0:y1, x0:x1], dl[y0:y1, x0:x1], ref[y0:y1, x0:x1]
        m8 = int(t8.max())
        worst = max(worst, m8)
        if show_all or m8 > tol:
            print("%-44s %5d %8.4f %11.3g  [%.3g, %.3g]" % (
                c["name"], m8, float((t8 <= tol).mean()), float(np.nan_to_num(tl).max()),
                float(r.min()), float(r.max())))
    print("whole image: max8 %d, within %.5f" % (int(d8.max()), float((d8 <= tol).mean())))


main()
