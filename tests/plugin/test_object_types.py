"""Every object type, missing images, and the temporary folders (issue 28), headless:

    blender -b --factory-startup --python-exit-code 1 --python tests/plugin/test_object_types.py \
        -- --glint build/glint

1. Blender's default scene plus an object of every type Blender 3.4 has, and collection
   instances of them all (object_types.py), renders through the add-on: no crash (an evaluated
   Empty's material slots took Blender down), no error, an image of the scene's size; the types
   glint leaves out (hair curves, point clouds, volume objects, Grease Pencil) are named in one
   warning each, with the instanced objects too; no warning names the temporary export.
2. The same scene with those left-out objects hidden from render agrees with Cycles 3.4 at equal
   samples: the relMSE of glint against Cycles is within 3x that of two Cycles seeds (the noise
   floor) plus 3e-5, on 4 x 4 pixel blocks.
3. An image file that is gone renders magenta where Cycles does (the cube's material and the
   world's Environment Texture share it): one warning, naming its path, both materials and the
   world; the cube's pixels are magenta in glint's image and in Cycles'. An Image Texture node
   without an image (on the metaball) is magenta in both too, and warned about.
4. A `blender -b` killed with SIGKILL mid-render: its glint stops by itself within 3 s
   (--exit-with-parent). Temporary folders: the one that Blender left, and a
   hand-made one whose owner is gone, are removed by the next render; a folder kept by the
   keep_temp preference and one whose owner is alive stay; the renders above leave none.
Exits non-zero on the first failure.
"""

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "cycles"))
import make_scenes as cycles_setup  # noqa: E402  (tests/cycles: Cycles' render settings)
sys.path.insert(0, HERE)
import addon_env  # noqa: E402
import bpy  # noqa: E402
import numpy as np  # noqa: E402
import object_types  # noqa: E402
from plugin_test_util import (alive, blender_render_cmd, child_pids, fail,  # noqa: E402
                              process_name, script_args)

W, H = 96, 72
SPP = 64
GLINT_ORPHAN_S = 3.0  # how long glint may outlive a killed Blender
LEFT_OUT = {"hair curves": ("Scene Hair", "Kit Hair"),
            "point clouds": ("Scene Point Cloud", "Kit Point Cloud"),
            "volume objects": ("Scene Volume", "Kit Volume"),
            "Grease Pencil": ("Scene Grease Pencil", "Kit Grease Pencil")}
TEMP_NAMES = ("scene.json", "scene.bin", "glint_render_")

REPORTS = {"warnings": [], "errors": []}


def log(msg):
    print("object_types: " + msg, flush=True)


def instrument():
    """Records the engine's warnings and errors (the add-on's own Python methods)."""
    cls = sys.modules["glint_blender.engine"].GlintRenderEngine
    orig_warn, orig_error = cls._warn_once, cls._error

    def warn_once(self, msg):
        REPORTS["warnings"].append(msg)
        return orig_warn(self, msg)

    def error(self, msg):
        REPORTS["errors"].append(msg)
        return orig_error(self, msg)
    cls._warn_once, cls._error = warn_once, error


def render(scene, path, engine, seed=0):
    """Renders the scene to a float EXR at `path` with glint or Cycles; returns the RGB array."""
    REPORTS["warnings"].clear()
    REPORTS["errors"].clear()
    if engine == "CYCLES":
        cycles_setup.setup_render(scene, SPP, seed)
    scene.render.engine = engine
    r = scene.render
    r.resolution_x, r.resolution_y, r.resolution_percentage = W, H, 100
    r.image_settings.file_format = "OPEN_EXR"
    r.image_settings.color_mode = "RGB"
    r.image_settings.color_depth = "32"
    scene.glint.samples = SPP
    scene.glint.seed = seed
    r.filepath = path
    bpy.ops.render.render(write_still=True)
    if REPORTS["errors"]:
        fail("%s render: errors %s" % (engine, REPORTS["errors"]))
    if not os.path.isfile(path):
        fail("%s render wrote no image at %s" % (engine, path))
    img = bpy.data.images.load(path, check_existing=False)
    try:
        w, h = img.size
        if (w, h) != (W, H):
            fail("%s render: the image is %dx%d, not %dx%d" % (engine, w, h, W, H))
        px = np.empty(w * h * 4, dtype=np.float32)
        img.pixels.foreach_get(px)
    finally:
        bpy.data.images.remove(img)
    return px.reshape(h, w, 4)[:, :, :3].astype(np.float64)


def blocks(a, k=4):
    h, w, c = a.shape
    return a[:h // k * k, :w // k * k].reshape(h // k, k, w // k, k, c).mean(axis=(1, 3))


def rel_mse(a, b):
    a, b = blocks(a), blocks(b)
    return float(np.mean((a - b) ** 2 / (b ** 2 + 0.01)))


def check_no_temp_names(what):
    for w in REPORTS["warnings"]:
        for t in TEMP_NAMES:
            if t in w:
                fail("%s: a warning names the temporary export (%s): %s" % (what, t, w))


def owned_dir(tmp, name, pid, start="None", keep=False):
    path = os.path.join(tmp, name)
    os.makedirs(path)
    with open(os.path.join(path, ".glint_owner"), "w") as f:
        f.write("%d %s\n" % (pid, start))
    if keep:
        with open(os.path.join(path, ".glint_keep"), "w") as f:
            f.write("kept\n")
    return path


def killed_blender_dir(glint, work, tmp):
    """A `blender -b` rendering through the add-on, killed with SIGKILL while glint runs: its
    glint must end by itself within GLINT_ORPHAN_S; returns the folder left in tmp."""
    scene = bpy.context.scene  # Blender's default scene, made slow to render
    scene.render.engine = "GLINT"
    scene.render.resolution_x, scene.render.resolution_y = 640, 480
    scene.glint.samples = 100000
    blend = os.path.join(work, "heavy.blend")
    bpy.ops.wm.save_as_mainfile(filepath=blend, copy=True)
    env = dict(os.environ, GLINT_BINARY=glint, TMPDIR=tmp)
    proc = subprocess.Popen(blender_render_cmd(blend, os.path.join(work, "killed_####")),
                            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    glint_pid, deadline = None, time.monotonic() + 60
    while glint_pid is None and time.monotonic() < deadline and proc.poll() is None:
        glint_pid = next((p for p in child_pids(proc.pid) if process_name(p) == "glint"), None)
        time.sleep(0.05)
    if glint_pid is None:
        proc.kill()
        fail("killed Blender: glint never started under it")
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait()
    killed_at = time.monotonic()
    while alive(glint_pid) and time.monotonic() - killed_at < GLINT_ORPHAN_S:
        time.sleep(0.02)
    if alive(glint_pid):
        os.kill(glint_pid, signal.SIGKILL)
        fail("killed Blender: its glint still ran %.1f s later (--exit-with-parent)"
             % GLINT_ORPHAN_S)
    log("killed Blender: its glint ended %.2f s after it" % (time.monotonic() - killed_at))
    left = [d for d in os.listdir(tmp) if d.startswith("glint_render_")]
    if len(left) != 1:
        fail("killed Blender: expected its one render folder in %s, found %s" % (tmp, left))
    return os.path.join(tmp, left[0])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--glint", required=True)
    args = ap.parse_args(script_args())
    glint = os.path.abspath(args.glint)
    work = tempfile.mkdtemp(prefix="glint_test_types_")
    tmp = os.path.join(work, "tmp")
    os.makedirs(tmp)
    addon_env.enable(glint)
    instrument()

    # ---- 4 (set-up): folders the first render must sweep or keep.
    killed = killed_blender_dir(glint, work, tmp)
    no_pid = 2 ** 22 + 17  # above Linux's largest pid_max: never a live process
    dead = owned_dir(tmp, "glint_render_dead", no_pid)
    kept = owned_dir(tmp, "glint_render_kept", no_pid, keep=True)
    live = owned_dir(tmp, "glint_render_live", os.getppid())
    tempfile.tempdir = tmp

    # ---- 1. Every object type, added to Blender's default scene.
    scene = bpy.context.scene
    object_types.build(scene)
    types = object_types.types_in(scene)
    missing_types = set(object_types.EXTRA_TYPES) - types
    if missing_types:
        fail("the scene lacks object types %s" % sorted(missing_types))
    log("object types in the scene: %s" % ", ".join(sorted(types)))
    every = render(scene, os.path.join(work, "every.exr"), "GLINT")
    log("every type: %d warnings:\n  %s" % (len(REPORTS["warnings"]),
                                            "\n  ".join(REPORTS["warnings"])))
    if every.mean() < 0.01:
        fail("every type: the image is black")
    check_no_temp_names("every type")
    for label, names in LEFT_OUT.items():
        said = [w for w in REPORTS["warnings"] if label in w]
        if len(said) != 1 or not all("'%s'" % n in said[0] for n in names):
            fail("every type: expected one warning about %s naming %s, got %s"
                 % (label, names, said))

    # ---- 4. The sweep the first render did.
    for path, should_exist in ((killed, False), (dead, False), (kept, True), (live, True)):
        if os.path.isdir(path) != should_exist:
            fail("temporary folders: %s should %s after the next render"
                 % (os.path.basename(path), "stay" if should_exist else "be removed"))
    shutil.rmtree(kept)
    shutil.rmtree(live)
    log("temporary folders: the killed Blender's and a dead owner's removed, kept and live "
        "ones left")

    # ---- 2. Against Cycles, with what glint leaves out hidden.
    for ob in bpy.data.objects:
        if ob.type in {"CURVES", "POINTCLOUD", "VOLUME", "GPENCIL"}:
            ob.hide_render = True
    g = render(scene, os.path.join(work, "glint.exr"), "GLINT")
    check_no_temp_names("every type, hidden")
    c1 = render(scene, os.path.join(work, "cycles1.exr"), "CYCLES", seed=1)
    c2 = render(scene, os.path.join(work, "cycles2.exr"), "CYCLES", seed=2)
    floor, err = rel_mse(c2, c1), rel_mse(g, c1)
    log("against Cycles (4x4 blocks): relMSE glint %.5f, Cycles seed to seed %.5f" % (err, floor))
    if err > 3 * floor + 3e-5:
        fail("every type: glint differs from Cycles (relMSE %.5f, noise floor %.5f)"
             % (err, floor))

    # ---- 3. A missing image, used by two materials and the world.
    png = os.path.join(work, "gone.png")
    made = bpy.data.images.new("gone.png", 4, 4)
    made.filepath_raw, made.file_format = png, "PNG"
    made.save()
    bpy.data.images.remove(made)
    image = bpy.data.images.load(png, check_existing=False)
    os.remove(png)
    image.reload()
    for mat in (bpy.data.materials["Material"], bpy.data.materials["Kit Block material"]):
        nt = mat.node_tree
        tex = nt.nodes.new("ShaderNodeTexImage")
        tex.image = image
        nt.links.new(tex.outputs["Color"], nt.nodes["Principled BSDF"].inputs["Base Color"])
    # An Image Texture node without an image: Cycles renders it magenta too.
    nt = bpy.data.materials["Scene Metaball material"].node_tree
    empty_tex = nt.nodes.new("ShaderNodeTexImage")
    nt.links.new(empty_tex.outputs["Color"], nt.nodes["Principled BSDF"].inputs["Base Color"])
    world = scene.world
    world.use_nodes = True
    env = world.node_tree.nodes.new("ShaderNodeTexEnvironment")
    env.image = image
    world.node_tree.links.new(env.outputs["Color"],
                              world.node_tree.nodes["Background"].inputs["Color"])
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.05
    g = render(scene, os.path.join(work, "missing_glint.exr"), "GLINT")
    said = [w for w in REPORTS["warnings"] if "gone.png" in w]
    log("missing image: %s" % said)
    if len(said) != 1 or png not in said[0] or not all(
            u in said[0] for u in ("material 'Material'", "material 'Kit Block material'",
                                   "the world")):
        fail("missing image: expected one warning naming %s, both materials and the world"
             % png)
    if not any("Scene Metaball material" in w and "has no image" in w
               for w in REPORTS["warnings"]):
        fail("missing image: the Image Texture without an image was not warned about")
    c = render(scene, os.path.join(work, "missing_cycles.exr"), "CYCLES", seed=1)
    for name, img in (("glint", g), ("Cycles", c)):
        r, gr, b = blocks(img)[H // 8, W // 8]  # the cube's centre
        log("missing image: %s's cube centre (%.3f, %.3f, %.3f)" % (name, r, gr, b))
        if not (r > 4 * gr + 0.02 and b > 4 * gr + 0.02):
            fail("missing image: %s's cube is not magenta" % name)
    err = rel_mse(g, c)
    log("missing image against Cycles: relMSE %.5f (floor %.5f)" % (err, floor))
    if err > 3 * floor + 1e-3:
        fail("missing image: glint differs from Cycles (relMSE %.5f)" % err)

    left = [d for d in os.listdir(tmp) if d.startswith("glint_render_")]
    if left:
        fail("temporary folders left by the renders: %s" % left)
    shutil.rmtree(work, ignore_errors=True)
    print("PASS test_object_types", flush=True)


main()
