"""Image checks for tests/plugin, run inside Blender (its Python has numpy and reads EXR):

    blender -b --factory-startup --python-exit-code 1 --python compare_exr.py -- same A B
        exit 0 when the RGB (and, when both have it, alpha) float values of A and B are equal
        bit for bit, else prints how many values differ and the largest difference and exits 1
    blender ... -- alpha A REF_MEAN REF_STDERR SEEDS SPP
        the alpha channel of A (SPP samples a pixel) against a Cycles alpha reference (its
        mean and standard error over SEEDS images, in the reference files' R): per pixel
        z = (a - mean) / sqrt(stderr^2 + var_a + 0.001^2), var_a the larger of one Cycles
        image's variance (stderr^2 SEEDS) and mean (1 - mean) / SPP (the variance of a mean
        of SPP values in [0, 1]; glint's see-through surfaces are noisier in alpha than
        Cycles'); exit 0 when >= 99.75% of the pixels have |z| < 5.141 (the RGB Z-test's
        threshold) and the reference has transparent pixels at all
    blender ... -- differ A B MIN_RELMSE
        exit 0 when relMSE(A, B) = mean((A-B)^2 / (B^2 + 0.01)) >= MIN_RELMSE (two frames of
        an animation that must not be the same picture)

Images are loaded as float buffers with the colour space set to Non-Color, so Blender applies
no transform: the values compared are those stored in the file (half or float).
"""

import sys

import bpy
import numpy as np


def load(path, channels=3):
    """The first `channels` channels (all with None) of the image, rows bottom-up."""
    img = bpy.data.images.load(path, check_existing=False)
    img.colorspace_settings.name = "Non-Color"
    w, h, c = img.size[0], img.size[1], img.channels
    a = np.empty(w * h * c, dtype=np.float32)
    img.pixels.foreach_get(a)
    bpy.data.images.remove(img)
    return a.reshape(h, w, c)[:, :, :channels]


def alpha_test(a_path, mean_path, stderr_path, seeds, spp):
    a = load(a_path, None)
    if a.shape[2] < 4:
        print("compare_exr: %s has no alpha channel" % a_path)
        return 1
    alpha = a[:, :, 3].astype(np.float64)
    mean = load(mean_path)[:, :, 0].astype(np.float64)
    se = load(stderr_path)[:, :, 0].astype(np.float64)
    if alpha.shape != mean.shape:
        print("compare_exr: sizes differ: %s %s" % (alpha.shape, mean.shape))
        return 1
    var_a = np.maximum(se ** 2 * seeds, np.clip(mean * (1 - mean), 0, None) / spp)
    z = np.abs(alpha - mean) / np.sqrt(se ** 2 + var_a + 1e-3 ** 2)
    accepted = float(np.mean(z < 5.141))
    transparent = int(np.sum(mean < 0.5))
    y, x = np.unravel_index(int(np.argmax(z)), z.shape)
    print("compare_exr: alpha of %s against Cycles: %.2f%% of pixels accepted (need 99.75%%), "
          "worst |z| %.2f at x %d, y %d (from the top): %.4f vs %.4f; mean alpha %.5f vs "
          "Cycles %.5f; mean |difference| %.5f; %d reference pixels below 0.5"
          % (a_path, 100 * accepted, z.max(), x, alpha.shape[0] - 1 - y, alpha[y, x],
             mean[y, x], alpha.mean(), mean.mean(), np.abs(alpha - mean).mean(), transparent))
    if transparent == 0:
        print("compare_exr: the reference has no transparent pixels: nothing is tested")
        return 1
    return 0 if accepted >= 0.9975 else 1


def main(argv):
    mode, a_path, b_path = argv[0], argv[1], argv[2]
    if mode == "alpha":
        return alpha_test(a_path, b_path, argv[3], int(argv[4]), int(argv[5]))
    a, b = load(a_path, None), load(b_path, None)
    if a.shape[2] != b.shape[2]:  # one with alpha, one without: compare RGB
        a, b = a[:, :, :3], b[:, :, :3]
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
