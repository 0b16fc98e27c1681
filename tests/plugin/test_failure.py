"""Failure: when glint cannot render, `blender -b FILE -E GLINT -f 1` exits non-zero, prints the
reason (glint's own error message when glint ran) and writes no image. Two cases: a glint binary
that does not exist, and a scene glint rejects (the world's image file is not an image).

    blender -b --factory-startup --python-exit-code 1 --python tests/plugin/test_failure.py -- \
        --glint build/glint
"""

import argparse
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import addon_env  # noqa: E402
import bpy  # noqa: E402
from plugin_test_util import blender_render_cmd, fail, run, script_args  # noqa: E402


def check_failed(label, result, expected, work, tmp):
    print("---- %s: exit code %d\n%s" % (label, result.returncode, result.stdout[-2000:]))
    if result.returncode == 0:
        fail("%s: blender -b exited with 0" % label)
    for text in expected:
        if text not in result.stdout:
            fail("%s: the output does not contain %r" % (label, text))
    images = [f for f in os.listdir(work) if f.startswith("out_")]
    if images:
        fail("%s: a failed render wrote %s" % (label, images))
    left = [d for d in os.listdir(tmp) if d.startswith("glint_render_")]
    if left:
        fail("%s: temporary render folders left: %s" % (label, left))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--glint", required=True)
    args = ap.parse_args(script_args())
    glint = os.path.abspath(args.glint)
    work = tempfile.mkdtemp(prefix="glint_test_failure_")
    tmp = os.path.join(work, "tmp")
    os.makedirs(tmp)
    addon_env.enable(glint)

    # 1. A binary that is not there: the add-on says so and the render fails.
    addon_env.build_scene(light=None)
    good = os.path.join(work, "good.blend")
    bpy.ops.wm.save_as_mainfile(filepath=good)
    bogus = os.path.join(work, "no_such_dir", "glint")
    env = dict(os.environ, GLINT_BINARY=bogus, TMPDIR=tmp)
    r = run(blender_render_cmd(good, os.path.join(work, "out_####")), env)
    check_failed("bogus binary", r, ["glint executable was not found", bogus], work, tmp)

    # 2. glint rejects the scene: the world's Environment Texture file is not an image. The
    # message must be glint's own (file:line:col: error: ...), naming the file.
    sky = os.path.join(work, "broken_sky.exr")
    with open(sky, "wb") as f:
        f.write(b"this is not an OpenEXR file\n" * 8)
    world = bpy.context.scene.world
    nt = world.node_tree
    env_node = nt.nodes.new("ShaderNodeTexEnvironment")
    img = bpy.data.images.new("broken_sky", 4, 2, float_buffer=True)
    img.source = 'FILE'
    img.filepath = sky
    env_node.image = img
    nt.links.new(env_node.outputs["Color"], nt.nodes["Background"].inputs["Color"])
    bad = os.path.join(work, "bad.blend")
    bpy.ops.wm.save_as_mainfile(filepath=bad)
    env = dict(os.environ, GLINT_BINARY=glint, TMPDIR=tmp)
    r = run(blender_render_cmd(bad, os.path.join(work, "out_####")), env)
    check_failed("scene glint rejects", r, ["render failed (exit code", "error:",
                                            "broken_sky.exr"], work, tmp)

    shutil.rmtree(work, ignore_errors=True)
    print("PASS test_failure")


main()
