"""Checks glint's `blender_light` against Cycles 3.4, light type by light type.

    blender -b --factory-startup --python tests/plugin/lights_check.py -- \
        --glint build/glint --out DIR [--spp 128] [--cases point0,sun5] [--whitted]

For each case a Blender scene holds a Lambert plane (albedo 0.8, 8 x 8 m), a camera that sees
the plane and the light, and one light; the world is black (glossy_*: a Principled plane of
roughness 0.15, where BSDF rays that hit the light carry the highlight). Cycles renders it with the
settings of tests/cycles/make_scenes.py (setup_render); glint renders the same scene, exported
the same way (OBJ + camera of make_scenes.py) with the light written by hand as the
`blender_light` block the add-on writes. One line per case gives the ratio glint / Cycles of
the image mean and of the means of the four quadrants, and the standard error of the mean
difference estimated from 8 x 8-pixel blocks of the difference image; --whitted adds glint's Whitted render (shading
from the light's centre, so area lights differ near them). Exit code 1 when a ratio is off by
more than 4 standard errors + 1 %.
"""

import argparse
import math
import os
import subprocess
import sys

import bpy
import numpy as np
from mathutils import Vector

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "cycles"))
import make_scenes as ms  # noqa: E402

ms.W, ms.H = 96, 72

# name: light settings (Blender units: metres, W, degrees)
CASES = {
    "point0": dict(type="POINT", loc=(0.3, 0.5, 1.5), power=100, radius=0.0),
    "point03": dict(type="POINT", loc=(0.3, 0.5, 1.5), power=100, radius=0.3),
    "point03_seen": dict(type="POINT", loc=(0.3, 0.5, 1.5), power=100, radius=0.3, camera=True),
    "spot": dict(type="SPOT", loc=(-0.5, -0.3, 2.0), aim=(0.3, 0.6, 0), power=400, radius=0.1,
                 spot_size=50, spot_blend=0.5),
    "spot_sharp": dict(type="SPOT", loc=(0.2, 0.1, 1.6), aim=(0, 0.4, 0), power=300,
                       radius=0.0, spot_size=70, spot_blend=0.0),
    "sun0": dict(type="SUN", aim_dir=(0.4, 0.3, -1), power=2.0, angle=0.0),
    "sun5": dict(type="SUN", aim_dir=(0.4, 0.3, -1), power=2.0, angle=5.0),
    "sun_visible": dict(type="SUN", aim_dir=(-0.05, -0.985, 0.174), power=2.0, angle=10.0,
                        camera=True),
    "area_square": dict(type="AREA", loc=(0, 0.8, 1.2), aim=(0.2, 0.3, 0), power=150,
                        shape="SQUARE", size=1.0),
    "area_rect": dict(type="AREA", loc=(-0.3, 0.6, 1.0), aim=(0.2, -1.5, 0), power=150,
                      shape="RECTANGLE", size=1.5, size_y=0.5, roll=30, camera=True),
    "area_disk": dict(type="AREA", loc=(0, 0.8, 1.2), aim=(0.2, 0.3, 0), power=150,
                      shape="DISK", size=1.0),
    "area_ellipse": dict(type="AREA", loc=(-0.3, 0.6, 1.0), aim=(0.2, 0.2, 0), power=150,
                         shape="ELLIPSE", size=1.2, size_y=0.6, roll=-20),
    "area_spread": dict(type="AREA", loc=(0, 0.5, 0.8), aim=(0.4, 0.6, 0), power=150,
                        shape="RECTANGLE", size=1.5, size_y=1.0, spread=60),
    # A glossy plane: BSDF rays that hit the lights carry much of the highlight (MIS).
    "glossy_point03": dict(type="POINT", loc=(0.3, 1.5, 1.0), power=100, radius=0.3,
                           glossy=True),
    "glossy_area": dict(type="AREA", loc=(0, 1.5, 1.0), aim=(0, 0.5, 0), power=150,
                        shape="RECTANGLE", size=1.0, size_y=0.4, glossy=True),
    "glossy_sun5": dict(type="SUN", aim_dir=(0, -0.95, -0.35), power=2.0, angle=5.0,
                        glossy=True),
}


def pov(v):
    return ms.fmt(ms.to_pov(v))


def build(case):
    ms.reset()
    if case.get("glossy"):
        white = ms.principled_material("white", base=(0.8, 0.8, 0.8), roughness=0.15)
    else:
        white = ms.diffuse_material("white", (0.8, 0.8, 0.8))
    ms.add_quad("plane", (0, 0, 0), 8, 8, white, z_normal_down=False)
    ms.add_camera((0, -4.0, 2.6), (0, 0.6, 0.4), lens_mm=30.0)
    ms.set_world_color((0, 0, 0))
    kind = case["type"]
    data = bpy.data.lights.new("light", kind)
    data.color = (1.0, 0.9, 0.8)
    data.energy = case["power"]
    if kind in ("POINT", "SPOT"):
        data.shadow_soft_size = case["radius"]
    if kind == "SPOT":
        data.spot_size = math.radians(case["spot_size"])
        data.spot_blend = case["spot_blend"]
    if kind == "SUN":
        data.angle = math.radians(case["angle"])
    if kind == "AREA":
        data.shape = case["shape"]
        data.size = case["size"]
        if "size_y" in case:
            data.size_y = case["size_y"]
        data.spread = math.radians(case.get("spread", 180.0))
    ob = bpy.data.objects.new("light", data)
    bpy.context.scene.collection.objects.link(ob)
    ob.location = case.get("loc", (0, 0, 5))
    ob.visible_camera = case.get("camera", False)
    if "aim" in case:
        d = Vector(case["aim"]) - Vector(ob.location)
    else:
        d = Vector(case.get("aim_dir", (0, 0, -1)))
    q = d.to_track_quat("-Z", "Y")
    ob.rotation_euler = q.to_euler()
    if "roll" in case:
        ob.rotation_euler.rotate_axis("Z", math.radians(case["roll"]))
    bpy.context.view_layer.update()
    return ob


def light_block(ob):
    """The `blender_light` block the add-on writes for the light object `ob`."""
    light = ob.data
    m = ob.matrix_world
    r = m.to_3x3().normalized()
    col = lambda i: Vector((r[0][i], r[1][i], r[2][i]))  # noqa: E731
    kind = light.type.lower()
    lines = ["blender_light {", "  " + kind]
    if kind != "sun":
        lines.append("  location " + pov(m.translation))
    if kind != "point":
        lines.append("  direction " + pov(-col(2)))
    lines.append("  color rgb <%.6f, %.6f, %.6f>" % tuple(light.color))
    lines.append("  power %.6f" % light.energy)
    if kind in ("point", "spot"):
        lines.append("  radius %.6f" % light.shadow_soft_size)
    if kind == "spot":
        lines.append("  spot_size %.6f  spot_blend %.6f" % (math.degrees(light.spot_size),
                                                           light.spot_blend))
    if kind == "sun":
        lines.append("  angle %.6f" % math.degrees(light.angle))
    if kind == "area":
        sx = light.size
        sy = light.size_y if light.shape in ("RECTANGLE", "ELLIPSE") else light.size
        shape = "ellipse" if light.shape in ("DISK", "ELLIPSE") else "rectangle"
        sc = m.to_scale()
        lines.append("  shape %s" % shape)
        lines.append("  size <%.6f, %.6f>" % (sx * sc[0], sy * sc[1]))
        lines.append("  axis_x %s  axis_y %s" % (pov(col(0)), pov(col(1))))
        lines.append("  spread %.6f" % math.degrees(light.spread))
    if ob.visible_camera:
        lines.append("  visible_camera on")
    lines.append("}")
    return "\n".join(lines) + "\n"


def write_glint_scene(out_dir, name, ob):
    ms.export_obj(os.path.join(out_dir, name + ".obj"))
    text = ("#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n" + ms.camera_pov() +
            "background { color rgb <0, 0, 0> }\n" + 'obj_file { "%s.obj" }\n' % name +
            light_block(ob))
    path = os.path.join(out_dir, name + ".pov")
    with open(path, "w") as f:
        f.write(text)
    return path


def block_stderr(diff, b=8):
    h, w = diff.shape
    blocks = diff[:h - h % b, :w - w % b].reshape(h // b, b, w // b, b).mean(axis=(1, 3))
    return blocks.std(ddof=1) / math.sqrt(blocks.size)


def main(argv):
    ap = argparse.ArgumentParser(prog="lights_check.py")
    ap.add_argument("--glint", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--spp", type=int, default=128)
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--whitted", action="store_true")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    bad = 0
    for name in args.cases.split(","):
        ob = build(CASES[name])
        scene_path = write_glint_scene(args.out, name, ob)
        cyc = os.path.join(args.out, name + "_cycles.exr")
        ms.render_to(cyc, args.spp, 1)
        a = ms.load_pixels(cyc).mean(axis=2)
        out = os.path.join(args.out, name + "_glint.exr")
        cmd = [args.glint, "render", scene_path, "-o", out, "-W", str(ms.W), "-H", str(ms.H),
               "--integrator", "path", "--spp", str(args.spp), "--max-depth", "8", "--seed", "1"]
        subprocess.run(cmd, check=True, stderr=subprocess.DEVNULL)
        g = ms.load_pixels(out).mean(axis=2)
        se = block_stderr(g - a)
        h2, w2 = a.shape[0] // 2, a.shape[1] // 2
        quads = [(slice(0, h2), slice(0, w2)), (slice(0, h2), slice(w2, None)),
                 (slice(h2, None), slice(0, w2)), (slice(h2, None), slice(w2, None))]
        q = " ".join("%.3f" % (g[s].mean() / a[s].mean()) if a[s].mean() > 0 else "-"
                     for s in quads)
        ratio = g.mean() / a.mean()
        tol = 4 * se / a.mean() + 0.01
        ok = abs(ratio - 1) <= tol
        bad += not ok
        line = "%-13s cycles mean %.5f  glint/cycles %.4f (+-%.4f)  quadrants %s" % (
            name, a.mean(), ratio, se / a.mean(), q)
        if args.whitted:
            wout = os.path.join(args.out, name + "_whitted.exr")
            subprocess.run([args.glint, "render", scene_path, "-o", wout, "-W", str(ms.W),
                            "-H", str(ms.H)], check=True, stderr=subprocess.DEVNULL)
            line += "  whitted/cycles %.4f" % (ms.load_pixels(wout).mean(axis=2).mean() / a.mean())
        print(("ok   " if ok else "FAIL ") + line, flush=True)
    return 1 if bad else 0


if __name__ == "__main__":
    code = main(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
    sys.stdout.flush()
    os._exit(code)
