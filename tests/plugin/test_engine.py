"""The GLINT engine end to end in this Blender, and the exporter's API.

    blender -b --factory-startup --python-exit-code 1 --python tests/plugin/test_engine.py -- \
        --glint build/glint

1. A small scene rendered with bpy.ops.render.render through the add-on: the saved image has
   the render size (resolution x percentage), is not empty, and equals bit for bit what glint
   writes when the kept folder's command.txt is run again from the shell.
2. The native export (scene.json): an orthographic camera is written as one; a panoramic
   camera (equirectangular) renders without a message; depth of field and motion blur are
   written and render without a warning, the transparent film and Transparent Glass too; a
   scene without meshes renders the world alone.
3. Animation: `blender -b f.blend -E GLINT -a` over a 3-frame camera move writes three frames
   that differ from each other and each equal the CLI re-render of its own export.
4. make_zip.sh's zip installs through Blender's add-on installer and renders the default scene;
   so does the README's install.py, run from another folder with a relative binary path.
5. Disabling the add-on closes the stock panels to GLINT again and removes scene.glint.
"""

import argparse
import glob
import json
import os
import shlex
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_env  # noqa: E402
import bpy  # noqa: E402
import numpy as np  # noqa: E402
from plugin_test_util import blender_binary, fail, run, script_args  # noqa: E402


def load(path):
    img = bpy.data.images.load(path, check_existing=False)
    w, h = img.size
    a = np.empty(w * h * img.channels, dtype=np.float32)
    img.pixels.foreach_get(a)
    a = a.reshape(h, w, img.channels)
    bpy.data.images.remove(img)
    return a


def rerender(folder, glint, out):
    """command.txt of a kept render folder, run with the glint under test into `out`."""
    with open(os.path.join(folder, "command.txt")) as f:
        argv = shlex.split(f.read())
    argv[0] = glint
    argv[argv.index("-o") + 1] = out
    argv[argv.index("--progress") + 1] = "none"
    r = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        fail("CLI re-render of %s failed:\n%s" % (folder, r.stdout))
    return load(out)


def check_same(label, blender_img, cli_img):
    a, b = blender_img[:, :, :3], cli_img[:, :, :3]
    if a.shape != b.shape:
        fail("%s: Blender's image is %s, the CLI's %s" % (label, a.shape, b.shape))
    diff = float(np.abs(a - b).max())
    if diff != 0.0:
        fail("%s: Blender's image differs from the CLI re-render (max |diff| %g)"
             % (label, diff))


def test_render(glint, work):
    scene = addon_env.build_scene(width=128, height=96, samples=8, light=None)
    scene.render.resolution_percentage = 50  # the image must be 64 x 48
    tmp = os.path.join(work, "tmp_render")
    os.makedirs(tmp)
    tempfile.tempdir = tmp  # the add-on's mkdtemp: its kept folder lands here
    try:
        out = os.path.join(work, "engine.exr")
        addon_env.render_to(out)
    finally:
        tempfile.tempdir = None
    if not os.path.isfile(out):
        fail("the render wrote no image")
    img = load(out)
    if img.shape[:2] != (48, 64):
        fail("image is %d x %d, expected 64 x 48" % (img.shape[1], img.shape[0]))
    rgb = img[:, :, :3]
    if not np.isfinite(rgb).all() or rgb.max() <= 0.0 or rgb.std() < 1e-3:
        fail("image is empty or flat (max %g, std %g)" % (rgb.max(), rgb.std()))
    if img.shape[2] == 4 and not np.all(img[:, :, 3] == 1.0):
        fail("alpha is not 1 everywhere")
    folders = glob.glob(os.path.join(tmp, "glint_render_*"))
    if len(folders) != 1:
        fail("expected one kept render folder in %s, found %s" % (tmp, folders))
    check_same("F12 render", img, rerender(folders[0], glint, os.path.join(work, "cli.exr")))
    print("render: 64 x 48, mean %.4f, equals the CLI re-render" % rgb.mean())


def test_messages(work):
    """glint's lines as the user reads them: no location in the temporary export (with or
    without line:col), OBJ/MTL names turned into Blender's, the quoted source and caret under
    an error in scene.pov left out; other files' locations and plain lines kept."""
    from glint_blender import exporter
    d = os.path.join(work, "export")
    os.makedirs(d)
    for name in ("scene.obj", "scene.pov"):
        open(os.path.join(d, name), "w").close()
    e = exporter.Export(d, os.path.join(d, "scene.pov"), os.path.join(d, "out.exr"), 1, 1, [],
                        {"object": {"My_Cube": "object 'My Cube' (mesh 'Cube.001')"},
                         "material": {"Mat_A": "material 'Mat A'"}})
    cases = [("scene.obj: warning: material [ 'x' ] not found", "material [ 'x' ] not found"),
             (d + "/scene.obj:41:1: warning: object 'My_Cube': 1 degenerate",
              "object 'My Cube' (mesh 'Cube.001'): 1 degenerate"),
             ("error: the scene has more", "error: the scene has more"),
             ("/elsewhere/t.png:1:1: warning: material 'Mat_A' y",
              "/elsewhere/t.png:1:1: warning: material 'Mat A' y")]
    for line, expected in cases:
        got = exporter.translate_message(line, e)
        if got != expected:
            fail("translate_message(%r) = %r, expected %r" % (line, got, expected))
    got = exporter.translate_lines(["scene.pov:20:12: error: too many", '  obj_file { "x" }',
                                    "             ^", "more"], e)
    if got != ["error: too many", "more"]:
        fail("translate_lines: %r" % got)
    print("messages: %d lines translated as the user reads them" % (len(cases) + 4))


def glint_messages(glint, export):
    """Runs glint on an export (1 sample, tiny) and returns (exit code, stderr lines)."""
    r = subprocess.run([glint, "render", export.scene_path, "-o",
                        os.path.join(export.out_dir, "check.png"), "--spp", "1", "-W", "8",
                        "-H", "6"], capture_output=True, text=True)
    return r.returncode, r.stderr.splitlines()


def test_export(glint, work):
    from glint_blender import exporter, native_export
    scene = addon_env.build_scene(width=64, height=48, light=None)
    cam = scene.camera.data
    depsgraph = bpy.context.evaluated_depsgraph_get()

    def export(name):
        return native_export.export_frame_native(depsgraph, os.path.join(work, name),
                                                 warnings.append)

    cam.type = 'ORTHO'
    cam.ortho_scale = 6.0
    depsgraph.update()
    warnings = []
    ex = export("ortho")
    data = json.load(open(ex.scene_path))
    if data["camera"]["type"] != "ORTHO" or abs(data["camera"]["ortho_scale"] - 6) > 1e-6:
        fail("an orthographic camera was not written as one: %s" % data["camera"])
    if ex.argv[:2] != ["render", ex.scene_path] or ex.width != 64 or ex.height != 48:
        fail("unexpected argv/size: %s %d x %d" % (ex.argv, ex.width, ex.height))
    if not os.path.isfile(os.path.join(work, "ortho", "command.txt")):
        fail("no command.txt")
    rc, lines = glint_messages(glint, ex)
    if rc != 0:
        fail("glint failed on the orthographic export: %s" % lines)

    cam.type = 'PANO'
    cam.cycles.panorama_type = 'EQUIRECTANGULAR'
    depsgraph.update()
    ex = export("pano")
    if json.load(open(ex.scene_path))["camera"].get("panorama_type") != "EQUIRECTANGULAR":
        fail("the panorama type was not written")
    rc, lines = glint_messages(glint, ex)
    if rc != 0 or any("panoram" in l for l in lines):
        fail("a panoramic camera did not render cleanly: %d %s" % (rc, lines))

    # Depth of field and motion blur render without a word; transparent film is said once.
    cam.type = 'PERSP'
    cam.dof.use_dof = True
    scene.render.use_motion_blur = True
    scene.render.film_transparent = True
    depsgraph.update()
    warnings = []
    ex = export("warn")
    if not data["camera"].get("dof") or not json.load(open(ex.scene_path))["camera"]["dof"]["use"]:
        fail("depth of field was not written")
    rc, lines = glint_messages(glint, ex)
    for key, count in (("depth of field", 0), ("motion blur", 0), ("Transparent", 0)):
        n = sum(key in l for l in lines + warnings)
        if rc != 0 or n != count:
            fail("expected %d message(s) about %r, got %d: %s %s" % (count, key, n, lines,
                                                                      warnings))
    scene.cycles.film_transparent_glass = True
    depsgraph.update()
    ex = export("glass")
    rc, lines = glint_messages(glint, ex)
    if rc != 0 or any("Transparent" in l for l in lines) or \
            not json.load(open(ex.scene_path))["render"]["film_transparent_glass"]:
        fail("expected Transparent Glass written and rendered without a message: %d %s" %
             (rc, lines))
    scene.cycles.film_transparent_glass = False
    scene.render.use_motion_blur = False
    scene.render.film_transparent = False
    # A light's Camera ray visibility is written (Blender's default: off); Cast Shadow off,
    # which glint does not have, is said once.
    bpy.ops.object.light_add(type='POINT', location=(0, 0, 3))
    lamp = bpy.context.active_object
    lamp.name = "lamp"
    lamp.visible_camera = True
    lamp.data.cycles.cast_shadow = False
    depsgraph = bpy.context.evaluated_depsgraph_get()
    warnings = []
    ex = export("lamp")
    light = [l for l in json.load(open(ex.scene_path))["lights"] if l["name"] == "lamp"][0]
    if not light["visibility"]["camera"]:
        fail("a light visible to the camera was not written so: %s" % light)
    rc, lines = glint_messages(glint, ex)
    if sum("Cast Shadow" in l for l in lines) != 1:
        fail("expected one warning about Cast Shadow off: %s" % lines)
    bpy.data.objects.remove(lamp)
    for name in ("Plane", "Cube", "Sphere"):  # no meshes: the world only
        bpy.data.objects.remove(bpy.data.objects[name])
    depsgraph = bpy.context.evaluated_depsgraph_get()
    ex = export("empty")
    if json.load(open(ex.scene_path))["objects"]:
        fail("a scene without meshes still has objects")
    rc, lines = glint_messages(glint, ex)
    if rc != 0:
        fail("glint failed on a scene without meshes: %s" % lines)
    print("export: orthographic and panoramic cameras, depth of field, warnings once, "
          "empty scene")
    del exporter


def test_animation(glint, work):
    addon_env.build_scene(width=64, height=48, samples=4, light=None, animated_camera=True)
    blend = os.path.join(work, "anim.blend")
    bpy.ops.wm.save_as_mainfile(filepath=blend)
    tmp = os.path.join(work, "tmp_anim")
    os.makedirs(tmp)
    keep = ("import bpy; bpy.context.preferences.addons['glint_blender']"
            ".preferences.keep_temp = True")
    cmd = [blender_binary(), "-b", "--factory-startup", blend, "--python",
           addon_env.__file__, "--python-expr", keep, "-E", "GLINT",
           "-o", os.path.join(work, "anim_####"), "-F", "OPEN_EXR", "-a"]
    r = run(cmd, dict(os.environ, GLINT_BINARY=glint, TMPDIR=tmp))
    if r.returncode != 0:
        fail("blender -a failed:\n" + r.stdout)
    frames = [load(os.path.join(work, "anim_%04d.exr" % f)) for f in (1, 2, 3)]
    folders = {}
    for folder in glob.glob(os.path.join(tmp, "glint_render_*")):
        frame = json.load(open(os.path.join(folder, "scene.json")))["render"]["frame"]
        folders[int(frame)] = folder
    if sorted(folders) != [1, 2, 3]:
        fail("expected kept folders for frames 1-3, got %s" % sorted(folders))
    for f in (1, 2, 3):
        cli = rerender(folders[f], glint, os.path.join(work, "cli_%d.exr" % f))
        check_same("frame %d" % f, frames[f - 1], cli)
    objs = [(json.load(open(os.path.join(folders[f], "scene.json")))["objects"],
             open(os.path.join(folders[f], "scene.bin"), "rb").read()) for f in (1, 2, 3)]
    if objs[0] == objs[1] or objs[1] == objs[2]:
        fail("the animated sphere is the same in two frames' exports (stale evaluation)")
    for f in (1, 2):
        d = float(np.abs(frames[f - 1] - frames[f]).mean())
        if d < 1e-3:
            fail("frames %d and %d are the same (mean |diff| %g)" % (f, f + 1, d))
    print("animation: 3 frames, each equal to its export's CLI re-render, all different")


# Renders the factory startup scene's cube under a grey world (its light removed: lights have
# tests of their own) to `out`, through the add-on, whatever installed it.
RENDER_CUBE = """
scene = bpy.context.scene
bpy.data.objects.remove(bpy.data.objects["Light"])
scene.world.color = (0.5, 0.5, 0.5)
scene.render.engine = "GLINT"
scene.render.resolution_x, scene.render.resolution_y = 32, 24
scene.glint.samples = 2
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
"""

INSTALL_SCRIPT = """
import sys, addon_utils, bpy
zip_path, glint, out = sys.argv[sys.argv.index("--") + 1:]
bpy.ops.preferences.addon_install(filepath=zip_path)
addon_utils.modules_refresh()
assert addon_utils.enable("glint_blender", default_set=True, handle_error=None) is not None
bpy.context.preferences.addons["glint_blender"].preferences.binary = glint
""" + RENDER_CUBE


def test_zip_install(glint, work):
    """make_zip.sh's zip installs with Blender's own add-on installer and renders the default
    scene's cube under a grey world."""
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    zip_path = os.path.join(work, "glint_blender.zip")
    subprocess.run([os.path.join(root, "plugin", "blender", "make_zip.sh"), zip_path],
                   check=True, stdout=subprocess.DEVNULL)
    script = os.path.join(work, "install.py")
    with open(script, "w") as f:
        f.write(INSTALL_SCRIPT)
    user = os.path.join(work, "user_scripts")
    os.makedirs(user)
    out = os.path.join(work, "installed.exr")
    r = run([blender_binary(), "-b", "--factory-startup", "--python-exit-code", "1", "--python",
             script, "--", zip_path, glint, out], dict(os.environ, BLENDER_USER_SCRIPTS=user))
    if r.returncode != 0 or not os.path.isfile(out):
        fail("installing the zip and rendering the default scene failed:\n" + r.stdout)
    if not os.path.isfile(os.path.join(user, "addons", "glint_blender", "engine.py")):
        fail("the zip did not install as addons/glint_blender")
    img = load(out)
    if img.shape[:2] != (24, 32) or img[:, :, :3].max() <= 0:
        fail("the default scene rendered wrong: shape %s max %g"
             % (img.shape, img[:, :, :3].max()))
    print("zip install: installed, enabled, rendered the default scene (32 x 24)")


RENDER_DEFAULT_SCENE = """
import sys, bpy
out = sys.argv[sys.argv.index("--") + 1]
""" + RENDER_CUBE


def test_install_script(glint, work):
    """The README's install (plugin/blender/install.py) from another folder, with the binary
    given by a relative path, into a fresh user configuration: exits 0 with no error or
    "not disabled" message, twice (the second replaces the first); then a plain `blender -b`
    with that configuration renders the default scene through the add-on."""
    root = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    env = dict(os.environ, BLENDER_USER_CONFIG=os.path.join(work, "user_config"),
               BLENDER_USER_SCRIPTS=os.path.join(work, "user_scripts_2"))
    elsewhere = os.path.join(work, "elsewhere")
    os.makedirs(elsewhere)
    relative = os.path.relpath(glint, elsewhere)
    install = os.path.join(root, "plugin", "blender", "install.py")
    for attempt in ("first", "again"):
        r = subprocess.run([blender_binary(), "-b", "--python-exit-code", "1", "--python",
                            install, "--", "--binary", relative], env=env, cwd=elsewhere,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           timeout=120)
        if r.returncode != 0 or "add-on installed" not in r.stdout:
            fail("install.py (%s) failed:\n%s" % (attempt, r.stdout))
        for alarming in ("not disabled", "Error", "Traceback"):
            if alarming in r.stdout:
                fail("install.py (%s) printed %r:\n%s" % (attempt, alarming, r.stdout))
    script = os.path.join(work, "render_default.py")
    with open(script, "w") as f:
        f.write(RENDER_DEFAULT_SCENE)
    out = os.path.join(work, "install_script.exr")
    r = subprocess.run([blender_binary(), "-b", "--python-exit-code", "1", "--python", script,
                        "--", out], env=env, cwd=elsewhere, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, timeout=120)
    if r.returncode != 0 or not os.path.isfile(out):
        fail("rendering with the installed add-on failed:\n" + r.stdout)
    img = load(out)
    if img.shape[:2] != (24, 32) or img[:, :, :3].max() <= 0:
        fail("the default scene rendered wrong after install.py: shape %s" % (img.shape,))
    print("install.py: installed twice from another folder, rendered the default scene")


def test_unregister():
    """Disabling the add-on removes GLINT from every stock panel and scene.glint."""
    import addon_utils
    opened = [p.__name__ for p in bpy.types.Panel.__subclasses__()
              if "GLINT" in getattr(p, "COMPAT_ENGINES", ())]
    for name in ("EEVEE_MATERIAL_PT_surface", "EEVEE_WORLD_PT_surface", "RENDER_PT_format",
                 "RENDER_PT_color_management", "DATA_PT_lens"):
        if name not in opened:
            fail("stock panel %s is not open to GLINT" % name)
    addon_utils.disable("glint_blender", default_set=True)
    left = [p.__name__ for p in bpy.types.Panel.__subclasses__()
            if "GLINT" in getattr(p, "COMPAT_ENGINES", ())
            and not p.__name__.startswith("GLINT_")]
    left += [p.__name__ for p in bpy.types.Panel.__subclasses__()
             if p.__name__.startswith("GLINT_") and getattr(p, "is_registered", False)]
    if left or hasattr(bpy.types.Scene, "glint"):
        fail("after unregister: panels still open to GLINT %s / scene.glint %s"
             % (left, hasattr(bpy.types.Scene, "glint")))
    print("unregister: %d stock panels were open to GLINT, none after" % len(opened))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--glint", required=True)
    args = ap.parse_args(script_args())
    glint = os.path.abspath(args.glint)
    work = tempfile.mkdtemp(prefix="glint_test_engine_")
    addon_env.enable(glint, keep_temp=True)
    test_render(glint, work)
    test_messages(work)
    test_export(args.glint, work)
    test_animation(glint, work)
    test_zip_install(glint, work)
    test_install_script(glint, work)
    test_unregister()
    shutil.rmtree(work, ignore_errors=True)
    print("PASS test_engine")


main()
