"""Per-node scenes rendered by Cycles 3.4, the references of tests/nodes (README.md).

    blender -b --factory-startup --python tests/nodes/make_node_scenes.py -- \
        --out tests/nodes/cases [--only FAMILY[,FAMILY...]]

For each family (FAMILY_MAKERS below; the cases are in families_textures.py,
families_values.py and families_scene.py, built with node_graph.py) one scene: a grid of
tiles filling an orthographic camera, one pixel per Blender unit, each tile one case (a node setting / mode), drawn by one object
whose material shows the node's output through an Emission shader of strength 1 into the
Material Output (no lights, a black world: lighting plays no part). Written into
OUT/<family>/: cycles.exr (Cycles' render: 1 sample, Blackman-Harris filter 0.01 px wide so
each pixel is sampled at its centre, 'Standard' view, 32-bit float RGB), the add-on's native
export of the same scene (scene.json gzipped as scene.json.gz, scene.bin, textures/), and
cases.json (each case's
name and pixel rectangle, for tests/nodes/case_diff.py and the README).

Most cases ("quantized") read their inputs from u, the tile's UV snapped to its pixel (Vector
Math SNAP by 1/tile, the tile a power of two): every pixel of a tile sees one exact input
whatever point of the pixel a renderer samples, so textures are compared where they are
discontinuous or vary fast too. The inputs, vector and graph families read coordinates
continuously (what they test), their values moved away from black (see below).

Each case's output is shown as it is when Cycles renders it within [0, 1] with a range of at
least 0.05; otherwise a Vector Math MULTIPLY_ADD (a, b) after it maps Cycles' own range over
the tile to [0.1, 0.9] (a first Cycles render measures it). Both renderers see the same
mapping, so an 8-bit sRGB comparison tests the values relative to their range. Shader outputs
(the shaders family) are shown as they are.
"""

import argparse
import gzip
import json
import math
import os
import shutil
import sys
import tempfile

import bpy
import bmesh
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "plugin", "blender"))
sys.path.insert(0, HERE)
from glint_blender import native_export as NX  # noqa: E402
from node_graph import Graph  # noqa: E402
from families_textures import (family_textures_noise, family_textures_voronoi,  # noqa: E402
                               family_textures_pattern, family_textures_sky,
                               family_textures_image)
from families_values import family_color, family_converters, family_vector  # noqa: E402
from families_scene import family_inputs, family_shaders, family_graphs  # noqa: E402


FAMILY_MAKERS = [family_textures_noise, family_textures_voronoi, family_textures_pattern,
                 family_textures_sky, family_textures_image, family_color, family_converters,
                 family_inputs, family_vector, family_shaders, family_graphs]


# ============================================================================ scene


def quad_mesh(name, x0, y0, x1, y1, z=0.0):
    me = bpy.data.meshes.new(name)
    me.from_pydata([(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)], [], [(0, 1, 2, 3)])
    uv = me.uv_layers.new(name="UVMap")
    for k, c in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)]):
        uv.data[k].uv = c
    me.update()
    return me


_MESHES = {}


def shared_mesh(kind, s):
    key = (kind, s)
    if key in _MESHES:
        return _MESHES[key]
    if kind == "quad":
        me = quad_mesh("quad%d" % s, 0, 0, s, s)
    elif kind == "centered":
        h = s * 0.3  # turned and scaled, it stays within its tile
        me = quad_mesh("centered%d" % s, -h, -h, h, h)
    elif kind == "sphere":
        me = bpy.data.meshes.new("sphere%d" % s)
        bm = bmesh.new()
        bmesh.ops.create_uvsphere(bm, u_segments=24, v_segments=12, radius=s * 0.45,
                                  calc_uvs=True)
        bm.to_mesh(me)
        bm.free()
        for p in me.polygons:
            p.use_smooth = True
        me.update()
    me.materials.append(None)  # one slot; each object links its own material to it
    _MESHES[key] = me
    return me


def make_object(case, name, x0, y0, s):
    """The object drawing a tile whose lower-left corner is (x0, y0)."""
    cx, cy = x0 + s / 2.0, y0 + s / 2.0
    if case.obj == "quad":
        ob = bpy.data.objects.new(name, shared_mesh("quad", s))
        ob.location = (x0, y0, 0.0)
    elif case.obj == "sphere":
        ob = bpy.data.objects.new(name, shared_mesh("sphere", s))
        ob.location = (cx, cy, 0.0)
        ob.rotation_euler = (0.35, -0.2, 0.5)
    elif case.obj == "moved":  # turned, tilted and scaled: Object, Generated, Normal differ
        ob = bpy.data.objects.new(name, shared_mesh("centered", s))
        ob.location = (cx, cy, 1.5)
        ob.rotation_euler = (0.5, 0.0, 0.6)
        ob.scale = (0.9, 1.1, 1.3)
    elif case.obj == "turned":  # the quad turned a quarter about Z, scaled: covers the tile
        ob = bpy.data.objects.new(name, shared_mesh("quad", s))
        ob.location = (x0 + s, y0, 0.5)
        ob.rotation_euler = (0.0, 0.0, math.pi / 2)
        ob.scale = (1.0, 1.0, 2.5)
    elif case.obj == "back":  # seen from behind
        ob = bpy.data.objects.new(name, shared_mesh("centered", s))
        ob.location = (cx, cy, 0.0)
        ob.rotation_euler = (math.pi, 0.0, 0.3)
    else:
        raise ValueError(case.obj)
    return ob


def new_material(name, tile):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    return mat, Graph(mat, tile)


def build_case_material(case, name, tile, display):
    """Builds the case's material; display = (a, b) or None."""
    mat, g = new_material(name, tile)
    out = g.node("ShaderNodeOutputMaterial")
    u = g.quantized_u() if case.quantized is True else None
    res = case.fn(g, u)
    if isinstance(res, tuple) and res[0] == "surface":
        g.nt.links.new(res[1], out.inputs["Surface"])
    elif res.type == "SHADER":
        g.nt.links.new(res, out.inputs["Surface"])
    else:
        if display is not None:
            a, b = display
            res = g.vm("MULTIPLY_ADD", res, (a, a, a), (b, b, b))
        em = g.node("ShaderNodeEmission", ins={"Color": res, "Strength": 1.0})
        g.nt.links.new(g.out(em, "Emission"), out.inputs["Surface"])
    return mat


def build_scene(fam, displays, case_dir):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    _MESHES.clear()
    scene = bpy.context.scene
    if getattr(fam, "before", None):
        fam.before(case_dir)
    s, cols = fam.tile, fam.cols
    n = len(fam.cases)
    rows = (n + cols - 1) // cols
    cols = min(cols, n)
    w, h = cols * s, rows * s
    layout = {"family": fam.name, "doc": fam.doc, "tile": s, "cols": cols, "rows": rows,
              "width": w, "height": h, "cases": []}
    objects = []
    for k, case in enumerate(fam.cases):
        col, row = k % cols, k // cols
        x0, y0 = -w / 2.0 + col * s, h / 2.0 - (row + 1) * s
        name = "%03d_%s" % (k, case.name)
        disp = displays.get(case.name) if case.display else None
        mat = build_case_material(case, name, s, disp)
        ob = make_object(case, name, x0, y0, s)
        scene.collection.objects.link(ob)
        ob.material_slots[0].link = "OBJECT"
        ob.material_slots[0].material = mat
        if case.setup:
            case.setup(ob, mat)
        objects.append(ob)
        layout["cases"].append({"name": case.name, "rect": [col * s, row * s, col * s + s,
                                                             row * s + s],
                                "quantized": case.quantized, "object": case.obj,
                                "display": list(disp) if disp else None})
    if fam.extra:
        fam.extra(scene, layout)

    cam_data = bpy.data.cameras.new("camera")
    cam_data.type = "ORTHO"
    cam_data.ortho_scale = float(max(w, h))
    cam_data.clip_start = 0.1
    cam_data.clip_end = 100.0
    cam = bpy.data.objects.new("camera", cam_data)
    cam.location = (0.0, 0.0, 10.0)
    scene.collection.objects.link(cam)
    scene.camera = cam
    world = bpy.data.worlds.new("black")
    world.use_nodes = False
    world.color = (0.0, 0.0, 0.0)
    scene.world = world

    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = 1
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.pixel_filter_type = "BLACKMAN_HARRIS"
    c.filter_width = 0.01
    c.max_bounces = 0
    c.diffuse_bounces = 0
    c.glossy_bounces = 0
    c.transmission_bounces = 0
    c.volume_bounces = 0
    c.transparent_max_bounces = 8
    c.caustics_reflective = False
    c.caustics_refractive = False
    c.seed = 0
    scene.render.resolution_x = w
    scene.render.resolution_y = h
    scene.render.resolution_percentage = 100
    scene.render.dither_intensity = 0.0
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    scene.sequencer_colorspace_settings.name = "sRGB"
    for prop in dir(scene.render):  # no dates or times in the file: regenerating changes nothing
        if prop.startswith("use_stamp") and prop != "use_stamp":
            setattr(scene.render, prop, False)
    st = scene.render.image_settings
    st.file_format = "OPEN_EXR"
    st.color_depth = "32"
    st.color_mode = "RGB"
    st.exr_codec = "ZIP"
    return scene, layout


def render(scene, path, transparent=False):
    scene.render.film_transparent = transparent
    st = scene.render.image_settings
    st.color_mode = "RGBA" if transparent else "RGB"
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    scene.render.film_transparent = False
    st.color_mode = "RGB"


def read_exr(path):
    """(H, W, 4) float array, row 0 at the top."""
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float32).reshape(h, w, 4)[::-1]
    bpy.data.images.remove(img)
    return px


def choose_display(pix):
    """(a, b) mapping Cycles' range over a tile's covered pixels to [0.1, 0.9], or None
    when it is already within [0, 1] with a range of at least 0.05."""
    cov = pix[..., 3] > 0.5
    v = pix[..., :3][cov]
    v = v[np.isfinite(v)]
    if v.size == 0:
        return None
    lo, hi = float(v.min()), float(v.max())
    if lo >= 0.0 and hi <= 1.0 and hi - lo >= 0.05:
        return None
    if hi - lo < 1e-6:
        a = 0.4 / max(abs(lo), 1e-3)
        return (a, 0.5 - a * lo)
    a = 0.8 / (hi - lo)
    return (a, 0.1 - a * lo)


def relativize(case_dir):
    """Image paths in scene.json relative to the case folder (the exporter writes absolute
    ones), the file gzipped (scene.json.gz, without a time stamp: the JSON of a hundred
    materials is hundreds of KB, a twentieth of it compressed); command.txt (absolute paths,
    not needed) removed."""
    path = os.path.join(case_dir, "scene.json")
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    root = os.path.abspath(case_dir)

    def walk(x):
        if isinstance(x, dict):
            for k, v in x.items():
                if k == "path" and isinstance(v, str) and os.path.isabs(v):
                    x[k] = os.path.relpath(v, root)
                else:
                    walk(v)
        elif isinstance(x, list):
            for v in x:
                walk(v)
    walk(doc)
    text = json.dumps(doc, separators=(",", ":"), allow_nan=False).encode("utf-8")
    with open(path + ".gz", "wb") as raw, \
            gzip.GzipFile(filename="", mode="wb", fileobj=raw, mtime=0, compresslevel=9) as f:
        f.write(text)
    os.remove(path)
    cmd = os.path.join(case_dir, "command.txt")
    if os.path.exists(cmd):
        os.remove(cmd)


def make_family(fam, out_root, tmp):
    case_dir = os.path.join(out_root, fam.name)
    # Pass 1: Cycles' own values, to choose each case's display mapping.
    shutil.rmtree(case_dir, ignore_errors=True)
    os.makedirs(case_dir)
    scene, layout = build_scene(fam, {}, case_dir)
    p1 = os.path.join(tmp, fam.name + "_pass1.exr")
    render(scene, p1, transparent=True)
    pix = read_exr(p1)
    displays = {}
    for case, c in zip(fam.cases, layout["cases"]):
        if not case.display:
            continue
        x0, y0, x1, y1 = c["rect"]
        d = choose_display(pix[y0:y1, x0:x1])
        if d is not None:
            displays[case.name] = (float(np.float32(d[0])), float(np.float32(d[1])))
    # Pass 2: the reference and the export.
    scene, layout = build_scene(fam, displays, case_dir)
    render(scene, os.path.join(case_dir, "cycles.exr"))
    warnings = []
    NX.export_frame_native(bpy.context.evaluated_depsgraph_get(), case_dir, warnings.append)
    relativize(case_dir)
    layout["export_warnings"] = sorted(set(warnings))
    with open(os.path.join(case_dir, "cases.json"), "w", encoding="utf-8") as f:
        cases = layout.pop("cases")
        text = json.dumps(layout, indent=1)[:-2]
        f.write(text + ',\n "cases": [\n  ' +
                ",\n  ".join(json.dumps(c, separators=(",", ":")) for c in cases) + "\n ]\n}\n")
    for wmsg in layout["export_warnings"]:
        print("%s: export warning: %s" % (fam.name, wmsg))
    print("%s: %d cases, %dx%d px" % (fam.name, len(fam.cases), layout["width"],
                                       layout["height"]))


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default=os.path.join(HERE, "cases"))
    ap.add_argument("--only", default="")
    args = ap.parse_args(argv)
    args.out = os.path.abspath(args.out)
    only = [s for s in args.only.split(",") if s]
    fams = [m() for m in FAMILY_MAKERS]
    names = [f.name for f in fams]
    for o in only:
        if o not in names:
            raise SystemExit("unknown family %s (of %s)" % (o, ", ".join(names)))
    with tempfile.TemporaryDirectory() as tmp:
        for fam in fams:
            if only and fam.name not in only:
                continue
            make_family(fam, args.out, tmp)


if __name__ == "__main__":
    main()
