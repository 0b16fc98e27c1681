"""Image checks for tests/plugin, run inside Blender (its Python has numpy and reads EXR):

    blender -b --factory-startup --python-exit-code 1 --python compare_exr.py -- same A B
        exit 0 when the RGB float values of A and B are equal bit for bit, else prints how
        many values differ and the largest difference and exits 1
    blender ... -- differ A B MIN_RELMSE
        exit 0 when relMSE(A, B) = mean((A-B)^2 / (B^2 + 0.01)) >= MIN_RELMSE (two frames of
        an animation that must not be the same picture)

Images are loaded as float buffers with the colour space set to Non-Color, so Blender applies
no transform: the values compared are those stored in the file (half or float).
"""

import sys

import bpy
import numpy as np


def load(path):
    img = bpy.data.images.load(path, check_existing=False)
    img.colorspace_settings.name = "Non-Color"
    w, h, c = img.size[0], img.size[1], img.channels
    a = np.empty(w * h * c, dtype=np.float32)
    img.pixels.foreach_get(a)
    bpy.data.images.remove(img)
    return a.reshape(h, w, c)[:, :, :3]


def main(argv):
    mode, a_path, b_path = argv[0], argv[1], argv[2]
    a, b = load(a_path), load(b_path)
    if a.shape != b.shape:
        print("compare_exr: sizes differ: %s %s, %s %s" % (a_path, a.shape, b_path, b.shape))
        return 1
    if mode == "same":
        differ = a.view(np.uint32) != b.view(np.uint32)
        n = int(differ.sum())
        if n == 0:
            print("compare_exr: %s and %s are equal bit for bit (%d float values)"
                  % (a_path, b_path, a.size))
            return 0
        d = np.abs(a.astype(np.float64) - b)
        y, x, ch = np.unravel_index(int(np.argmax(d)), d.shape)
        print("compare_exr: %d of %d values differ; largest |difference| %.6g at x %d, y %d "
              "(from the top), channel %d: %.9g vs %.9g"
              % (n, a.size, d.max(), x, a.shape[0] - 1 - y, ch, a[y, x, ch], b[y, x, ch]))
        return 1
    if mode == "differ":
        a64, b64 = a.astype(np.float64), b.astype(np.float64)
        relmse = float(np.mean((a64 - b64) ** 2 / (b64 ** 2 + 0.01)))
        need = float(argv[3])
        print("compare_exr: relMSE(%s, %s) = %.4g (must be >= %.4g)"
              % (a_path, b_path, relmse, need))
        return 0 if relmse >= need else 1
    print("compare_exr: unknown mode " + mode)
    return 2


sys.exit(main(sys.argv[sys.argv.index("--") + 1:]))
