"""Reference values for tests/unit/shader_sky_test.cpp, rendered by Cycles itself.

    blender -b --factory-startup --python tests/shader/make_sky_refs.py -- \
        [--json DIR] [--only CASE[,CASE...]] [--start I] [--every N]

Each case is a world whose Background (strength 1) is fed by a Sky Texture node with the
case's settings. A panoramic equirectangular camera at the origin sees the sky; every view is
rendered twice with the same seed: once with the sky, once with the world's Texture
Coordinate 'Generated' output (the ray direction, which is also what the Sky Texture reads
when its Vector input is unlinked) as the background colour. The second image gives each
pixel's direction exactly, whatever the camera's mapping. Renders use 1 sample, a pixel filter
0.01 px wide, the 'Standard' view (look None, exposure 0, gamma 1) and 32-bit float OpenEXR
output, whose pixels are read back.

Views: 'sphere' is the whole sphere (48 x 24 pixels); 'sun' (Nishita cases with a sun disc)
is a 24 x 24 window of +-1.25 sun diameters around the sun.

With --json DIR every pixel of every view is written to DIR/<case>_<view>.json as
[dx, dy, dz, r, g, b] rows (for a full comparison). On stdout the script prints, per case, a
C++ table of SkyRef rows {in_sun_view, dx, dy, dz, r, g, b}: every N-th pixel of the sphere
view from pixel I on (default 67 from 300, mostly above z = -0.4, where the Nishita sky is
black) and every other pixel of the sun view's middle scanline, ready to paste into
the test.
"""

import argparse
import json
import math
import os
import sys
import tempfile

import bpy
import mathutils

DEG = math.pi / 180.0

# name -> sky node settings. Keep in step with the kCase* parameters of shader_sky_test.cpp.
CASES = {
    "preetham_a": dict(sky_type="PREETHAM", sun_direction=(0.3, -0.5, 0.6), turbidity=3.0),
    "preetham_b": dict(sky_type="PREETHAM", sun_direction=(0.8, 0.2, 0.15), turbidity=2.2),
    "preetham_night": dict(sky_type="PREETHAM", sun_direction=(0.5, 0.5, -0.3), turbidity=8.0),
    "hosek_a": dict(sky_type="HOSEK_WILKIE", sun_direction=(-0.4, 0.6, 0.5), turbidity=4.5,
                    ground_albedo=0.3),
    "hosek_b": dict(sky_type="HOSEK_WILKIE", sun_direction=(0.1, -0.9, 0.12), turbidity=10.0,
                    ground_albedo=0.8),
    "hosek_c": dict(sky_type="HOSEK_WILKIE", sun_direction=(0.0, 0.0, 1.0), turbidity=1.0,
                    ground_albedo=0.0),
    "nishita_default": dict(sky_type="NISHITA"),
    "nishita_a": dict(sky_type="NISHITA", sun_elevation=40 * DEG, sun_rotation=70 * DEG,
                      altitude=2000.0, air_density=1.5, dust_density=3.0, ozone_density=2.0,
                      sun_size=2.0 * DEG, sun_intensity=0.7),
    "nishita_low": dict(sky_type="NISHITA", sun_elevation=0.5 * DEG, sun_rotation=-30 * DEG,
                        sun_size=3.0 * DEG, altitude=100.0),
    "nishita_below": dict(sky_type="NISHITA", sun_elevation=-3.0 * DEG, sun_rotation=200 * DEG,
                          sun_size=2.0 * DEG, dust_density=0.5),
    "nishita_nodisc": dict(sky_type="NISHITA", sun_elevation=10 * DEG, sun_rotation=400 * DEG,
                           sun_disc=False, altitude=30000.0, air_density=0.3),
}


def parse_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser()
    p.add_argument("--json", default=None)
    p.add_argument("--only", default=None)
    p.add_argument("--start", type=int, default=300)
    p.add_argument("--every", type=int, default=67)
    return p.parse_args(argv)


def float_literal(x):
    s = f"{x:.9g}"
    if not any(c in s for c in ".en"):
        s += ".0"
    return s + "f"


def setup_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 1
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False
    scene.cycles.seed = 0
    scene.cycles.filter_width = 0.01
    scene.cycles.max_bounces = 0
    scene.render.resolution_percentage = 100
    scene.render.use_compositing = False
    scene.render.use_sequencer = False
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.exr_codec = "NONE"

    cam_data = bpy.data.cameras.new("cam")
    cam_data.type = "PANO"
    cam_data.cycles.panorama_type = "EQUIRECTANGULAR"
    cam = bpy.data.objects.new("cam", cam_data)
    scene.collection.objects.link(cam)
    scene.camera = cam

    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    scene.world = world
    return scene, cam, world


def set_world(world, settings):
    nodes = world.node_tree.nodes
    links = world.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputWorld")
    bg = nodes.new("ShaderNodeBackground")
    bg.inputs["Strength"].default_value = 1.0
    links.new(bg.outputs["Background"], out.inputs["Surface"])
    if settings is None:
        tc = nodes.new("ShaderNodeTexCoord")
        links.new(tc.outputs["Generated"], bg.inputs["Color"])
    else:
        sky = nodes.new("ShaderNodeTexSky")
        for k, v in settings.items():
            setattr(sky, k, v)
        links.new(sky.outputs["Color"], bg.inputs["Color"])


def render(scene, path):
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    img = bpy.data.images.load(path)
    w, h = img.size
    px = list(img.pixels)
    bpy.data.images.remove(img)
    return [px[4 * i:4 * i + 3] for i in range(w * h)]


def sun_dir(settings):
    e = settings.get("sun_elevation", 15 * DEG)
    r = settings.get("sun_rotation", 0.0)
    return mathutils.Vector((math.cos(e) * math.sin(r), math.cos(e) * math.cos(r), math.sin(e)))


def views(settings):
    out = [("sphere", 48, 24, (math.pi / 2, 0.0, 0.0), (-90, 90, -180, 180))]
    if settings["sky_type"] == "NISHITA" and settings.get("sun_disc", True):
        size = settings.get("sun_size", 0.009512044489383698)
        half = math.degrees(1.25 * size)
        rot = sun_dir(settings).to_track_quat("-Z", "Y").to_euler()
        out.append(("sun", 24, 24, tuple(rot), (-half, half, -half, half)))
    return out


def main():
    args = parse_args()
    scene, cam, world = setup_scene()
    only = set(args.only.split(",")) if args.only else None
    tmp = tempfile.mkdtemp(prefix="sky_refs_")
    for name, settings in CASES.items():
        if only and name not in only:
            continue
        printed = []
        for view, w, h, rot, (lat0, lat1, lon0, lon1) in views(settings):
            scene.render.resolution_x = w
            scene.render.resolution_y = h
            cam.rotation_euler = rot
            cam.data.cycles.latitude_min = lat0 * DEG
            cam.data.cycles.latitude_max = lat1 * DEG
            cam.data.cycles.longitude_min = lon0 * DEG
            cam.data.cycles.longitude_max = lon1 * DEG
            set_world(world, None)
            dirs = render(scene, os.path.join(tmp, f"{name}_{view}_dir.exr"))
            set_world(world, settings)
            rgbs = render(scene, os.path.join(tmp, f"{name}_{view}_sky.exr"))
            rows = []
            for d, c in zip(dirs, rgbs):
                n = math.sqrt(sum(x * x for x in d))
                if abs(n - 1.0) > 1e-5:
                    raise RuntimeError(f"{name}/{view}: direction pass not unit length: {d}")
                rows.append(list(d) + list(c))
            if args.json:
                os.makedirs(args.json, exist_ok=True)
                with open(os.path.join(args.json, f"{name}_{view}.json"), "w") as f:
                    json.dump({"case": name, "view": view, "rows": rows}, f)
            if view == "sphere":
                picked = range(args.start, len(rows), args.every)
            else:  # the middle scanline, across the disc
                picked = range((h // 2) * w, (h // 2 + 1) * w, 2)
            printed.extend((view, rows[i]) for i in picked)
        cname = "".join(p.capitalize() for p in name.split("_"))
        print(f"constexpr SkyRef kRef{cname}[] = {{")
        for view, r in printed:
            vals = ", ".join(float_literal(x) for x in r)
            print(f"    {{{'true' if view == 'sun' else 'false'}, {vals}}},")
        print("};")
    sys.stdout.flush()


main()
