"""Failure: when glint cannot render, `blender -b FILE -E GLINT -f 1` exits non-zero, prints the
reason (glint's own error message when glint ran) and writes no image. Two cases: a glint binary
that does not exist, and a scene glint rejects (over a limit glint is given). An image file
Blender cannot read is not a failure: it renders magenta as in Cycles (test_object_types.py).

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

    # 2. glint rejects the scene: glint run with --max-triangles 1 (a wrapper adds it), which
    # the scene's 12 triangles exceed. The message must be glint's own, without the location
    # in the temporary export (gone when the user reads it), and name the limit.
    wrapper = os.path.join(work, "glint_limited")
    with open(wrapper, "w") as f:
        f.write('#!/bin/sh\nexec "%s" "$@" --max-triangles 1\n' % glint)
    os.chmod(wrapper, 0o755)
    env = dict(os.environ, GLINT_BINARY=wrapper, TMPDIR=tmp)
    r = run(blender_render_cmd(good, os.path.join(work, "out_####")), env)
    check_failed("scene glint rejects", r, ["render failed (exit code", "error: the scene has "
                                            "more than 1 mesh triangles"], work, tmp)
    # The add-on's report, up to Blender's closing line (Blender's OBJ exporter prints the
    # export's path itself before it).
    report = r.stdout[r.stdout.find("Error: glint: render failed"):]
    report = report[:report.find("Blender quit")]
    for temp_name in ("scene.json", "scene.bin", "glint_render_"):
        if temp_name in report:
            fail("scene glint rejects: the message names the temporary export (%s)"
                 % temp_name)

    shutil.rmtree(work, ignore_errors=True)
    print("PASS test_failure")


main()
