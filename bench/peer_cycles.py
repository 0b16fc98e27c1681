#!/usr/bin/env python3
"""glint's path tracer against Cycles 3.4 at equal error: `glint report --peer` on a set of
scenes, one summary table (issue 34's check).

    bench/peer_cycles.py --build BUILD [--out DIR] [--scenes cycles:cornell,lamps,...]
                         [--spp-steps 16,64,256] [--seeds 2] [--threads 2]

Scenes are `cycles:NAME` (tests/cycles' cross-check scenes: glint reads the .pov, Cycles
renders the same scene built by tests/cycles/make_scenes.py) or an add-on scene NAME
(tests/plugin: glint renders the folder the add-on exported, Cycles the .blend it came from,
with the settings the references were rendered with). The add-on scenes' exports come from
their CTest (`ctest -R ^plugin.NAME$`, run here when BUILD has none). Each scene's error is
measured against its committed Cycles reference (16 seeds x 256 spp for the add-on scenes),
except where --reference-spp asks for a finer one, rendered once here by Cycles (seeds 1..16
at that many spp) and cached in DIR/refs: a reference's own noise adds to both renderers'
error alike and pulls the ratio towards 1.

Both renderers get --threads threads and take turns step by step; seconds are each one's
render call (glint: parse + render; Cycles: bpy.ops.render.render), not process start-up.
The table's equal-error column is the report's: the time Cycles needs to reach glint's error
at the last step, divided by glint's time (above 1: glint is ahead).
"""

import argparse
import glob
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# Blender's environment as the add-on tests make it (no pyenv Python shadowing Debian's).
sys.path.insert(0, os.path.join(ROOT, "tests", "plugin"))
from run_scene import blender_env  # noqa: E402
DEFAULT_SCENES = ("cycles:cornell,cycles:spheres,cycles:hdr,cornell,principled,textured,lamps,"
                  "msglass,many_lights")


def run(cmd, log=None, **kw):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)
    if log:
        with open(log, "w") as f:
            f.write(r.stdout)
    if r.returncode != 0:
        sys.exit("bench/peer_cycles.py: %s failed (%d):\n%s"
                 % (" ".join(cmd[:3]), r.returncode, r.stdout[-3000:]))
    return r.stdout


def addon_export(build, name):
    """The scene.json the add-on exported for NAME in its CTest's folder (run it if absent)."""
    pattern = os.path.join(build, "tests", "plugin", "out", name, "tmp", "*", "scene.json")
    if not glob.glob(pattern):
        # Blender's environment: run from a pyenv Python, the tests' Blender would take that
        # Python's standard library, which lacks numpy.
        run(["ctest", "--test-dir", build, "-R", "^plugin\\.(scenes|%s)$" % name],
            env=blender_env())
    found = sorted(glob.glob(pattern), key=os.path.getmtime)
    if not found:
        sys.exit("bench/peer_cycles.py: no export for %s under %s" % (name, pattern))
    return found[-1]


def fine_reference(args, name, refs):
    """Cycles' mean of seeds 1..16 at --reference-spp, rendered once into refs/."""
    path = os.path.join(refs, "%s_%d_mean.exr" % (name, args.reference_spp))
    if not os.path.exists(path):
        run(["blender", "-b", "--factory-startup", "--python-exit-code", "1", "--python",
             os.path.join(ROOT, "tests", "plugin", "make_scenes.py"), "--",
             "--out", os.path.join(refs, "scenes"), "--scenes", name, "--references",
             "--spp", str(args.reference_spp), "--seeds", "16", "--ref", refs,
             "--threads", str(args.threads), "--tmp", os.path.join(refs, "tmp")],
            env=blender_env())
        os.replace(os.path.join(refs, name + "_mean.exr"), path)
    return path


def scene_command(args, scene, refs):
    """(glint's scene, reference EXR, peer command) for one scene."""
    glint_threads = "--threads %d" % args.threads
    if scene.startswith("cycles:"):
        name = scene.split(":", 1)[1]
        peer = ("blender -b --factory-startup --python %s -- --scene %s --spp {spp} --out {out} "
                "--time-file {time} --seed-index {seed} %s"
                % (os.path.join(ROOT, "tests", "cycles", "render_cycles.py"), name,
                   glint_threads))
        return (os.path.join(ROOT, "tests", "cycles", "scenes", name + ".pov"),
                os.path.join(ROOT, "tests", "cycles", "ref", name + "_mean.exr"), peer)
    blend = os.path.join(args.build, "tests", "plugin", "scenes", scene + ".blend")
    export = addon_export(args.build, scene)
    peer = ("blender -b %s --python %s -- --spp {spp} --out {out} --time-file {time} "
            "--seed-index {seed} %s" % (blend, os.path.join(ROOT, "tests", "plugin",
                                                            "peer_cycles.py"), glint_threads))
    ref = os.path.join(ROOT, "tests", "plugin", "ref", scene + "_mean.exr")
    if scene in args.fine:
        ref = fine_reference(args, scene, refs)
    return export, ref, peer


def main():
    ap = argparse.ArgumentParser(prog="bench/peer_cycles.py")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default="peer-cycles")
    ap.add_argument("--scenes", default=DEFAULT_SCENES)
    ap.add_argument("--spp-steps", default="16,64,256")
    ap.add_argument("--seeds", type=int, default=2)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--reference-spp", type=int, default=2048)
    ap.add_argument("--fine", default="many_lights",
                    help="scenes measured against a reference of 16 x --reference-spp")
    args = ap.parse_args()
    args.build = os.path.abspath(args.build)
    args.fine = set(filter(None, args.fine.split(",")))
    glint = os.path.join(args.build, "glint")
    refs = os.path.abspath(os.path.join(args.out, "refs"))
    os.makedirs(refs, exist_ok=True)
    rows = []
    for scene in args.scenes.split(","):
        scene_file, ref, peer = scene_command(args, scene, refs)
        out = os.path.join(args.out, scene.replace(":", "-"))
        text = run([glint, "report", scene_file, "--reference", ref, "--spp-steps",
                    args.spp_steps, "--seeds", str(args.seeds), "--threads", str(args.threads),
                    "--out", out, "--peer-name", "cycles", "--peer", peer],
                   log=out + ".log", env=blender_env())
        csv = {}
        for line in text.splitlines():
            f = line.split(",")
            if len(f) >= 4 and f[0] in ("glint", "cycles") and f[1].isdigit():
                csv[(f[0], int(f[1]))] = (float(f[2]), float(f[3]))
        m = re.search(r"equal-error: .* needs ([0-9.]+)x", text)
        last = max(int(s) for s in args.spp_steps.split(","))
        g, c = csv[("glint", last)], csv[("cycles", last)]
        ratio = float(m.group(1)) if m else float("nan")
        rows.append((scene, g, c, ratio))
        print("%-16s glint %7.2f s relMSE %.3g | Cycles %7.2f s relMSE %.3g | equal-error %.2f"
              % (scene, g[0], g[1], c[0], c[1], ratio), flush=True)
    good = [r[3] for r in rows if r[3] > 0]
    print("\n| scene | glint %d spp: s / relMSE | Cycles %d spp: s / relMSE | equal-error |"
          % (last, last))
    print("|---|---:|---:|---:|")
    for scene, g, c, ratio in rows:
        print("| %s | %.2f / %.2g | %.2f / %.2g | %.2f |" % (scene, g[0], g[1], c[0], c[1], ratio))
    if good:
        print("geometric mean of equal-error: %.2f (lowest %.2f)"
              % (math.exp(sum(map(math.log, good)) / len(good)), min(good)))


if __name__ == "__main__":
    main()
