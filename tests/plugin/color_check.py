"""Checks that `glint convert --view ...` gives Blender 3.4's own 8-bit (and 16-bit) values.

    blender -b --factory-startup --python tests/plugin/color_check.py -- \
        --glint build/glint --out DIR

Blender writes a linear float EXR of test values (a fine gray ramp across the 8-bit rounding
steps, a logarithmic ramp from 2^-24 to 2^12, negative, tiny and denormal values, saturated
and random colors, and pixels with partial and zero alpha), reloads it, and saves it as an
RGBA PNG through the scene's color management (dither 0) for each case below, either with
Image.save_render or as a render result (the EXR through the compositor, F12 with
write_still), and as a 16-bit TIFF; glint converts the same EXR with the same view, look,
exposure and gamma. Every value (R, G, B, A) must be identical. One line per case reports the
count of differing values and the largest |difference|; the exit code is non-zero when any
case differs or a step fails.
"""

import argparse
import os
import shutil
import subprocess
import sys

import bpy
import numpy as np

W, H = 256, 192

# (name, view, look, exposure, gamma, how Blender saves: "save" or "render"; "save16": a 16-bit
# TIFF, compared through oiiotool when it is installed)
CASES = [
    ("standard", "Standard", "None", 0.0, 1.0, "save"),
    ("filmic", "Filmic", "None", 0.0, 1.0, "save"),
    ("filmic_look", "Filmic", "Medium High Contrast", 0.0, 1.0, "save"),
    ("filmic_exposure_gamma", "Filmic", "None", 1.3, 0.8, "save"),
    ("standard_exposure_gamma", "Standard", "None", -0.7, 1.6, "save"),
    ("render_standard", "Standard", "None", 0.0, 1.0, "render"),
    ("render_filmic", "Filmic", "None", 0.0, 1.0, "render"),
    ("tiff16_standard", "Standard", "None", 0.0, 1.0, "save16"),
    ("tiff16_filmic", "Filmic", "None", 0.0, 1.0, "save16"),
]


def test_pixels():
    """H x W x 4 float32 RGBA (top row first), premultiplied alpha as OpenEXR stores it."""
    rng = np.random.default_rng(5)
    px = np.zeros((H, W, 4), np.float32)
    px[..., 3] = 1.0
    n = W * 48
    # Rows 0-47: a gray ramp 0..1.25, fine enough to land on both sides of every 8-bit step.
    ramp = np.linspace(0.0, 1.25, n, dtype=np.float32).reshape(48, W)
    px[0:48, :, 0:3] = ramp[..., None]
    # Rows 48-79: a logarithmic ramp 2^-24 .. 2^12, gray and tinted.
    log_ramp = np.exp2(np.linspace(-24.0, 12.0, 16 * W)).astype(np.float32).reshape(16, W)
    px[48:64, :, 0:3] = log_ramp[..., None]
    px[64:80, :, 0] = log_ramp
    px[64:80, :, 1] = log_ramp * 0.25
    px[64:80, :, 2] = log_ramp * 0.02
    # Rows 80-111: random colors, some channels negative, some far above 1.
    px[80:96, :, 0:3] = rng.uniform(-0.5, 1.5, (16, W, 3))
    px[96:112, :, 0:3] = np.exp2(rng.uniform(-12.0, 8.0, (16, W, 3))) * np.where(
        rng.uniform(size=(16, W, 3)) < 0.1, -1.0, 1.0)
    # Rows 112-127: tiny and denormal values, signed zeros, exact 8-bit code centres.
    tiny = np.array([0.0, -0.0, 1e-45, 1e-40, 1e-38, 1e-30, 1e-20, 1e-10, 1e-7, -1e-7,
                     1e-5, -1e-3], np.float32)
    px[112:120, :, 0:3] = np.resize(tiny, (8, W, 1))
    codes = (np.arange(W, dtype=np.float32) % 256) / 255.0
    px[120:128, :, 0:3] = codes[None, :, None] ** 2.2
    # Rows 128-159: saturated primaries and secondaries at rising intensity.
    hues = np.array([[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1], [1, 0, 1],
                     [1, 0.5, 0.1], [0.1, 0.3, 1]], np.float32)
    level = np.exp2(np.linspace(-8.0, 8.0, W)).astype(np.float32)
    for i, hue in enumerate(hues):
        px[128 + 4 * i:132 + 4 * i, :, 0:3] = hue[None, None, :] * level[None, :, None]
    # Rows 160-191: partial and zero alpha over premultiplied colors.
    alpha = rng.uniform(0.0, 1.0, (32, W)).astype(np.float32)
    alpha[:, ::7] = 0.0
    alpha[:, 3::11] = 1.0
    straight = rng.uniform(0.0, 2.0, (32, W, 3)).astype(np.float32)
    px[160:192, :, 0:3] = straight * alpha[..., None]
    px[160:192, :, 3] = alpha
    return px


def write_exr(path):
    img = bpy.data.images.new("color_check_src", W, H, alpha=True, float_buffer=True)
    # Blender's pixel rows run bottom to top.
    img.pixels.foreach_set(np.flipud(test_pixels()).ravel())
    scene = bpy.context.scene
    s = scene.render.image_settings
    s.file_format = "OPEN_EXR"
    s.color_mode = "RGBA"
    s.color_depth = "32"
    s.exr_codec = "ZIP"
    img.save_render(path, scene=scene)
    bpy.data.images.remove(img)


def setup_compositor(exr):
    """The EXR as the render result: an empty scene whose compositor shows the image."""
    scene = bpy.context.scene
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj)
    scene.render.engine = "CYCLES"
    scene.cycles.samples = 1
    scene.render.resolution_x, scene.render.resolution_y = W, H
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = True
    scene.use_nodes = True
    nodes = scene.node_tree.nodes
    for n in list(nodes):
        nodes.remove(n)
    src = nodes.new("CompositorNodeImage")
    src.image = bpy.data.images.load(exr, check_existing=False)
    out = nodes.new("CompositorNodeComposite")
    out.use_alpha = True
    scene.node_tree.links.new(src.outputs["Image"], out.inputs["Image"])
    scene.node_tree.links.new(src.outputs["Alpha"], out.inputs["Alpha"])


def blender_png(exr, png, view, look, exposure, gamma, how):
    scene = bpy.context.scene
    scene.display_settings.display_device = "sRGB"
    vs = scene.view_settings
    vs.view_transform = view
    vs.look = look
    vs.exposure = exposure
    vs.gamma = gamma
    vs.use_curve_mapping = False
    scene.sequencer_colorspace_settings.name = "sRGB"
    scene.render.dither_intensity = 0.0
    s = scene.render.image_settings
    if how == "save16":
        s.file_format = "TIFF"
        s.color_depth = "16"
        s.tiff_codec = "DEFLATE"
    else:
        s.file_format = "PNG"
        s.color_depth = "8"
        s.compression = 15
    s.color_mode = "RGBA"
    if how == "render":
        scene.render.filepath = png
        bpy.ops.render.render(write_still=True)
        return
    img = bpy.data.images.load(exr, check_existing=False)
    img.save_render(png, scene=scene)
    bpy.data.images.remove(img)


def read_tiff16(path):
    """H x W x 4 raw 16-bit codes, top row first (Blender would linearize them on loading)."""
    r = subprocess.run(["oiiotool", "--dumpdata", path], capture_output=True, text=True,
                       check=True)
    rows = [line.split(":", 1)[1].split("(")[0].split()
            for line in r.stdout.splitlines() if line.strip().startswith("Pixel (")]
    return np.array(rows, np.int64).reshape(H, W, 4)


def read_png(path):
    """H x W x 4 uint8, top row first."""
    img = bpy.data.images.load(path, check_existing=False)
    w, h = img.size
    buf = np.empty(w * h * 4, np.float32)
    img.pixels.foreach_get(buf)
    bpy.data.images.remove(img)
    return np.flipud(np.rint(buf.reshape(h, w, 4) * 255.0).astype(np.int32))


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser()
    ap.add_argument("--glint", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--ocio-config", default="")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    exr = os.path.join(args.out, "color_check.exr")
    write_exr(exr)
    setup_compositor(exr)
    failed = False
    oiiotool = shutil.which("oiiotool")
    for name, view, look, exposure, gamma, how in CASES:
        ext = ".tif" if how == "save16" else ".png"
        if how == "save16" and not oiiotool:
            print(f"{name}: skipped (no oiiotool to read 16-bit values)")
            continue
        ref = os.path.join(args.out, name + "_blender" + ext)
        out = os.path.join(args.out, name + "_glint" + ext)
        blender_png(exr, ref, view, look, exposure, gamma, how)
        cmd = [args.glint, "convert", exr, "-o", out, "--view", view, "--exposure",
               repr(exposure), "--gamma", repr(gamma)]
        if look != "None":
            cmd += ["--look", look]
        if args.ocio_config:
            cmd += ["--ocio-config", args.ocio_config]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            print(f"{name}: glint failed ({r.returncode}): {r.stderr.strip()}")
            failed = True
            continue
        read = read_tiff16 if how == "save16" else read_png
        a, b = read(out), read(ref)
        if a.shape != b.shape:
            print(f"{name}: sizes differ: glint {a.shape}, blender {b.shape}")
            failed = True
            continue
        diff = np.abs(a.astype(np.int64) - b)
        count = int(np.count_nonzero(diff))
        rgb = int(np.count_nonzero(diff[..., 0:3]))
        bits = 16 if how == "save16" else 8
        print(f"{name}: {how}, view={view} look={look} exposure={exposure} gamma={gamma}: "
              f"{count} of {diff.size} {bits}-bit values differ ({rgb} RGB), "
              f"max |diff| {int(diff.max())}")
        if count:
            ys, xs = np.nonzero(diff.max(axis=2))
            for y, x in list(zip(ys, xs))[:5]:
                print(f"  at x={x} y={y}: glint {a[y, x].tolist()} blender {b[y, x].tolist()}")
            failed = True
    sys.stdout.flush()
    # Blender's --python keeps running after the script; leave with the result.
    os._exit(1 if failed else 0)


main()
