"""Reference values for tests/unit/shader_textures_test.cpp, rendered by Cycles itself.

    blender -b --factory-startup --python tests/shader/make_texture_refs.py -- \
        [--out-dir DIR] [--only FILE[,FILE...]] [--points N] [--seed S]

Each test case (one node setting, one set of socket values, one sample point) is one face of a
grid of unit squares that fills an orthographic camera's view pixel for pixel. The face's
material holds the texture node with its enum settings and its socket values as constants;
the node's Vector and W inputs come from Attribute nodes reading face-domain attributes (the
sample point, as float32), so the point is exact whatever the pixel's sample position is and
no input is constant-folded. The node's output (a color, a vector, one float, or three floats
combined with Combine XYZ) feeds an Emission shader of strength 1. The image is rendered by
Cycles on the CPU with 1 sample, a pixel filter 0.01 px wide, no bounces, the 'Standard' view
and written as a 32-bit float OpenEXR, whose pixels are read back: an emission shader seen by
the camera gives its colour exactly, negative values included.

The output is C++ (tests/unit/shader_textures_refs_{noise,voronoi,procedural}.inc): one table
per node, whose rows are the node's params and inputs structs as glint declares them and the
expected output.
Floats print with 9 significant digits, so float32 values round-trip exactly.
"""

import argparse
import math
import os
import random
import struct
import sys
import tempfile

import bpy


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def cf(x):
    """A float32 as a C++ float literal."""
    s = "%.9g" % f32(x)
    if "e" not in s and "." not in s:
        s += ".0"
    return s + "f"


def c3(v):
    return "{%s, %s, %s}" % (cf(v[0]), cf(v[1]), cf(v[2]))


# Enumerators print unqualified where the test brings them in with `using enum` (the Wave and
# output-selector enums, whose names collide, stay qualified).
DIMS = {"1D": "D1", "2D": "D2", "3D": "D3", "4D": "D4"}


class Config:
    """One node setting: the node type, its enum/int properties, its socket constants, the
    output (one socket, or three float sockets packed into a vector), and how its C++ row
    prints."""

    def __init__(self, node, props, sockets, outs, row):
        self.node = node
        self.props = props
        self.sockets = sockets
        self.outs = outs
        self.row = row  # callable(point, w, result) -> C++ initializer

    def key(self):
        return repr((self.node, sorted(self.props.items()), sorted(self.sockets.items()),
                     self.outs))


TABLES = {}  # node -> (C++ row type, list of configs)


def table(name, row_type):
    TABLES[name] = (row_type, [])
    return TABLES[name][1]


# --------------------------------------------------------------------------------------------
# The cases
# --------------------------------------------------------------------------------------------


def noise_cases():
    out = table("noise", "NoiseRef")
    settings = [
        (5.0, 2.0, 0.5, 0.0), (2.5, 0.0, 0.5, 0.0), (5.0, 3.5, 0.65, 0.0), (1.5, 8.0, 0.8, 0.0),
        (5.0, 2.0, 0.5, 1.7), (0.75, 15.0, 1.0, -0.4)]
    for dim in ["1D", "2D", "3D", "4D"]:
        for scale, detail, rough, dist in settings:
            def row(p, w, r, dim=dim, scale=scale, detail=detail, rough=rough, dist=dist):
                return "{{%s}, {%s, %s, %s, %s, %s, %s}, %s}" % (
                    DIMS[dim], c3(p), cf(w), cf(scale), cf(detail), cf(rough), cf(dist), c3(r))
            out.append(Config("ShaderNodeTexNoise", {"noise_dimensions": dim},
                              {"Scale": scale, "Detail": detail, "Roughness": rough,
                               "Distortion": dist}, ("Color",), row))


def white_noise_cases():
    out = table("white_noise", "WhiteNoiseRef")
    for dim in ["1D", "2D", "3D", "4D"]:
        def row(p, w, r, dim=dim):
            return "{{%s}, {%s, %s}, %s}" % (DIMS[dim], c3(p), cf(w), c3(r))
        out.append(Config("ShaderNodeTexWhiteNoise", {"noise_dimensions": dim}, {}, ("Color",),
                          row))
        # Value is Color's first component in Cycles; the test checks that property, and this
        # case checks Value itself.
        def vrow(p, w, r, dim=dim):
            return "{{%s}, {%s, %s}, {%s, -1.0f, -1.0f}}" % (DIMS[dim], c3(p), cf(w), cf(r[0]))
        out.append(Config("ShaderNodeTexWhiteNoise", {"noise_dimensions": dim}, {}, ("Value",),
                          vrow))


MUSGRAVE_TYPES = ["MULTIFRACTAL", "RIDGED_MULTIFRACTAL", "HYBRID_MULTIFRACTAL", "FBM",
                  "HETERO_TERRAIN"]


def musgrave_cases():
    out = table("musgrave", "MusgraveRef")
    settings = [  # scale, detail, dimension, lacunarity, offset, gain
        (5.0, 2.0, 2.0, 2.0, 0.0, 1.0), (3.0, 5.5, 1.2, 2.3, 0.8, 1.6),
        (1.25, 0.0, 0.5, 1.5, 1.0, 0.5), (2.0, 9.25, 0.0, 3.0, 0.25, 2.5)]
    for dim in ["1D", "2D", "3D", "4D"]:
        for mtype in MUSGRAVE_TYPES:
            for s in settings:
                def row(p, w, r, dim=dim, mtype=mtype, s=s):
                    return "{{%s, %s}, {%s, %s, %s}, %s}" % (
                        mtype, DIMS[dim], c3(p), cf(w), ", ".join(cf(v) for v in s), cf(r[0]))
                out.append(Config(
                    "ShaderNodeTexMusgrave", {"musgrave_dimensions": dim, "musgrave_type": mtype},
                    dict(zip(["Scale", "Detail", "Dimension", "Lacunarity", "Offset", "Gain"], s)),
                    ("Fac",), row))


VORONOI_OUTS = {"COLOR": ("Color",), "POSITION": ("Position",),
                "SCALARS": ("Distance", "W", "Radius")}


def voronoi_cases():
    out = table("voronoi", "VoronoiRef")
    combos = []
    for dim in ["1D", "2D", "3D", "4D"]:
        for feature in ["F1", "F2", "SMOOTH_F1", "DISTANCE_TO_EDGE", "N_SPHERE_RADIUS"]:
            combos.append((dim, feature, "EUCLIDEAN", 5.0, 1.0, 0.5, 1.0))
        if dim != "1D":
            for metric in ["MANHATTAN", "CHEBYCHEV", "MINKOWSKI"]:
                for feature in ["F1", "F2", "SMOOTH_F1"]:
                    combos.append((dim, feature, metric, 3.0, 0.6, 1.7, 0.8))
    combos.append(("3D", "F1", "MINKOWSKI", 4.0, 1.0, 4.5, 0.35))
    combos.append(("2D", "SMOOTH_F1", "EUCLIDEAN", 2.0, 0.15, 0.5, 1.0))
    combos.append(("3D", "F2", "EUCLIDEAN", 5.0, 1.0, 0.5, 0.0))
    for dim, feature, metric, scale, smooth, expo, rand in combos:
        for which, outs in VORONOI_OUTS.items():
            if (feature in ("DISTANCE_TO_EDGE", "N_SPHERE_RADIUS") and which != "SCALARS") or (
                    dim == "1D" and which == "POSITION"):
                continue
            def row(p, w, r, dim=dim, feature=feature, metric=metric, scale=scale,
                    smooth=smooth, expo=expo, rand=rand, which=which):
                return ("{{%s, %s, %s}, "
                        "{%s, %s, %s, %s, %s, %s}, VoronoiOut::%s, %s}") % (
                    DIMS[dim], feature, metric, c3(p), cf(w), cf(scale), cf(smooth), cf(expo),
                    cf(rand), which, c3(r))
            out.append(Config("ShaderNodeTexVoronoi",
                              {"voronoi_dimensions": dim, "feature": feature, "distance": metric},
                              {"Scale": scale, "Smoothness": smooth, "Exponent": expo,
                               "Randomness": rand}, outs, row))


def wave_cases():
    out = table("wave", "WaveRef")
    shapes = [("BANDS", d, "X") for d in ["X", "Y", "Z", "DIAGONAL"]] + [
        ("RINGS", "X", d) for d in ["X", "Y", "Z", "SPHERICAL"]]
    settings = [  # scale, distortion, detail, detail scale, detail roughness, phase
        (5.0, 0.0, 2.0, 1.0, 0.5, 0.0), (2.0, 3.5, 4.5, 1.5, 0.7, 1.25)]
    for wtype, bands, rings in shapes:
        for profile in ["SIN", "SAW", "TRI"]:
            for s in settings:
                def row(p, w, r, wtype=wtype, bands=bands, rings=rings, profile=profile, s=s):
                    return ("{{WaveType::%s, WaveBandsDirection::%s, WaveRingsDirection::%s, "
                            "WaveProfile::%s}, {%s, %s}, %s}") % (
                        wtype, bands, rings, profile, c3(p), ", ".join(cf(v) for v in s),
                        cf(r[0]))
                out.append(Config(
                    "ShaderNodeTexWave", {"wave_type": wtype, "bands_direction": bands,
                                          "rings_direction": rings, "wave_profile": profile},
                    dict(zip(["Scale", "Distortion", "Detail", "Detail Scale",
                              "Detail Roughness", "Phase Offset"], s)), ("Fac",), row))


def magic_cases():
    out = table("magic", "MagicRef")
    for depth in range(0, 11):
        for scale, dist in [(5.0, 1.0), (2.5, 3.25), (1.0, 0.0)]:
            def row(p, w, r, depth=depth, scale=scale, dist=dist):
                return "{{%d}, {%s, %s, %s}, %s}" % (depth, c3(p), cf(scale), cf(dist), c3(r))
            out.append(Config("ShaderNodeTexMagic", {"turbulence_depth": depth},
                              {"Scale": scale, "Distortion": dist}, ("Color",), row))


def gradient_cases():
    out = table("gradient", "GradientRef")
    for gtype in ["LINEAR", "QUADRATIC", "EASING", "DIAGONAL", "SPHERICAL", "QUADRATIC_SPHERE",
                  "RADIAL"]:
        def row(p, w, r, gtype=gtype):
            return "{{%s}, {%s}, %s}" % (gtype, c3(p), cf(r[0]))
        out.append(Config("ShaderNodeTexGradient", {"gradient_type": gtype}, {}, ("Fac",), row))


def checker_cases():
    out = table("checker", "CheckerRef")
    for scale in [5.0, 1.0, 3.7]:
        c1, c2 = (0.9, 0.35, 0.1), (0.05, 0.4, 0.75)
        def row(p, w, r, scale=scale, c1=c1, c2=c2):
            return "{{%s, %s, %s, %s}, %s}" % (c3(p), c3(c1), c3(c2), cf(scale), c3(r))
        out.append(Config("ShaderNodeTexChecker", {},
                          {"Color1": c1 + (1.0,), "Color2": c2 + (1.0,), "Scale": scale},
                          ("Color",), row))


def brick_cases():
    out = table("brick", "BrickRef")
    settings = [  # offset, offset freq, squash, squash freq, scale, mortar size, smooth, bias,
        # brick width, row height
        (0.5, 2, 1.0, 2, 5.0, 0.02, 0.1, 0.0, 0.5, 0.25),
        (0.3, 3, 1.6, 2, 3.0, 0.05, 0.6, 0.2, 0.7, 0.3),
        (0.7, 1, 0.5, 3, 2.0, 0.1, 0.0, -0.3, 0.4, 0.2),
        (0.25, 2, 1.0, 1, 4.0, 0.08, 1.0, 0.5, 0.9, 0.45)]
    c1, c2, mortar = (0.9, 0.35, 0.1), (0.05, 0.4, 0.75), (0.2, 0.25, 0.3)
    for s in settings:
        for which, outs in [("COLOR", ("Color",)), ("FAC", ("Fac",))]:
            def row(p, w, r, s=s, which=which):
                return ("{{%s, %d, %s, %d}, {%s, %s, %s, %s, %s}, BrickOut::%s, %s}") % (
                    cf(s[0]), s[1], cf(s[2]), s[3], c3(p), c3(c1), c3(c2), c3(mortar),
                    ", ".join(cf(v) for v in s[4:]), which, c3(r))
            out.append(Config(
                "ShaderNodeTexBrick", {"offset": s[0], "offset_frequency": s[1],
                                       "squash": s[2], "squash_frequency": s[3]},
                dict(zip(["Scale", "Mortar Size", "Mortar Smooth", "Bias", "Brick Width",
                          "Row Height"], s[4:]),
                     Color1=c1 + (1.0,), Color2=c2 + (1.0,), Mortar=mortar + (1.0,)),
                outs, row))


for make in [noise_cases, white_noise_cases, musgrave_cases, voronoi_cases, wave_cases,
             magic_cases, gradient_cases, checker_cases, brick_cases]:
    make()


def sample_points(rng, n):
    """n points: in [-3, 3] but the last (of two or more), which is in [-60, 60] to check
    precision far from the origin; W alongside."""
    pts = []
    for k in range(n):
        span = 60.0 if k == n - 1 and n > 1 else 3.0
        p = tuple(f32(rng.uniform(-span, span)) for _ in range(3))
        pts.append((p, f32(rng.uniform(-span, span))))
    return pts


# --------------------------------------------------------------------------------------------
# Scene
# --------------------------------------------------------------------------------------------


def build_material(cfg):
    mat = bpy.data.materials.new("m")
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    emit = nt.nodes.new("ShaderNodeEmission")
    emit.inputs["Strength"].default_value = 1.0
    nt.links.new(emit.outputs["Emission"], out.inputs["Surface"])
    node = nt.nodes.new(cfg.node)
    for k, v in cfg.props.items():
        setattr(node, k, v)
    for k, v in cfg.sockets.items():
        node.inputs[k].default_value = v
    vec = nt.nodes.new("ShaderNodeAttribute")
    vec.attribute_type = "GEOMETRY"
    vec.attribute_name = "in_vec"
    nt.links.new(vec.outputs["Vector"], node.inputs["Vector"])
    if "W" in node.inputs:
        w = nt.nodes.new("ShaderNodeAttribute")
        w.attribute_type = "GEOMETRY"
        w.attribute_name = "in_w"
        nt.links.new(w.outputs["Fac"], node.inputs["W"])
    if len(cfg.outs) == 1:
        res = node.outputs[cfg.outs[0]]
    else:
        comb = nt.nodes.new("ShaderNodeCombineXYZ")
        for i, name in enumerate(cfg.outs):
            nt.links.new(node.outputs[name], comb.inputs[i])
        res = comb.outputs["Vector"]
    nt.links.new(res, emit.inputs["Color"])
    return mat


def render(cases, workdir):
    """cases: list of (config, point, w). Returns one RGB triple per case."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    n = len(cases)
    w = 64
    h = max(4, (n + w - 1) // w)

    mesh = bpy.data.meshes.new("grid")
    verts, faces = [], []
    for k in range(n):
        i, j = k % w, k // w
        x0, y0 = i - w / 2.0, j - h / 2.0
        b = len(verts)
        verts += [(x0, y0, 0.0), (x0 + 1, y0, 0.0), (x0 + 1, y0 + 1, 0.0), (x0, y0 + 1, 0.0)]
        faces.append((b, b + 1, b + 2, b + 3))
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    mesh.attributes.new("in_vec", "FLOAT_VECTOR", "FACE")
    mesh.attributes.new("in_w", "FLOAT", "FACE")
    # Looked up after both exist (adding an attribute invalidates earlier references), and
    # filled before materials are added.
    mesh.attributes["in_vec"].data.foreach_set(
        "vector", [c for _, p, _ in cases for c in p])
    mesh.attributes["in_w"].data.foreach_set("value", [pw for _, _, pw in cases])
    materials = {}
    indices = []
    for cfg, _, _ in cases:
        key = cfg.key()
        if key not in materials:
            materials[key] = len(mesh.materials)
            mesh.materials.append(build_material(cfg))
        indices.append(materials[key])
    mesh.polygons.foreach_set("material_index", indices)
    mesh.update()

    obj = bpy.data.objects.new("grid", mesh)
    scene.collection.objects.link(obj)
    cam_data = bpy.data.cameras.new("cam")
    cam_data.type = "ORTHO"
    cam_data.ortho_scale = float(max(w, h))
    cam = bpy.data.objects.new("cam", cam_data)
    cam.location = (0.0, 0.0, 10.0)
    scene.collection.objects.link(cam)
    scene.camera = cam
    world = bpy.data.worlds.new("w")
    world.color = (0.0, 0.0, 0.0)
    scene.world = world

    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 1
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.use_denoising = False
    scene.cycles.filter_width = 0.01
    scene.cycles.max_bounces = 0
    scene.render.resolution_x = w
    scene.render.resolution_y = h
    scene.render.resolution_percentage = 100
    scene.render.dither_intensity = 0.0
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    path = os.path.join(workdir, "refs.exr")
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)

    img = bpy.data.images.load(path)
    px = list(img.pixels)
    res = []
    for k in range(n):
        i, j = k % w, k // w
        o = (j * w + i) * 4
        res.append((px[o], px[o + 1], px[o + 2]))
    bpy.data.images.remove(img)
    return res


# Which tables go into which generated file (one per header under test, each kept short).
FILES = {
    "shader_textures_refs_noise.inc": ["noise", "white_noise", "musgrave"],
    "shader_textures_refs_voronoi.inc": ["voronoi"],
    "shader_textures_refs_procedural.inc": ["wave", "magic", "gradient", "checker", "brick"],
}


def wrap(row, indent=4, width=100):
    """Splits a C++ initializer at ', ' so that no line passes `width` columns."""
    parts = row.split(", ")
    lines, cur = [], " " * indent + parts[0]
    for part in parts[1:]:
        if len(cur) + 2 + len(part) + 1 > width:
            lines.append(cur + ",")
            cur = " " * (indent + 4) + part
        else:
            cur += ", " + part
    lines.append(cur + ",")
    return lines


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser()
    ap.add_argument("--out-dir", default="tests/unit")
    ap.add_argument("--only", default="", help="file names (of FILES) to regenerate")
    ap.add_argument("--points", type=int, default=2)
    ap.add_argument("--seed", type=int, default=34)
    args = ap.parse_args(argv)
    only = [s for s in args.only.split(",") if s]

    with tempfile.TemporaryDirectory() as tmp:
        for fname, names in FILES.items():
            if only and fname not in only:
                continue
            lines = ["// Generated by tests/shader/make_texture_refs.py (--points %d --seed %d)"
                     " from" % (args.points, args.seed),
                     "// Blender %s's Cycles on the CPU. Do not edit by hand." %
                     bpy.app.version_string, ""]
            for name in names:
                row_type, configs = TABLES[name]
                rng = random.Random("%d/%s" % (args.seed, name))
                cases = [(cfg, p, w) for cfg in configs
                         for p, w in sample_points(rng, args.points)]
                results = render(cases, tmp)
                lines.append("const %s k%sRefs[] = {" % (
                    row_type, "".join(s.capitalize() for s in name.split("_"))))
                for (cfg, p, w), r in zip(cases, results):
                    lines += wrap(cfg.row(p, w, r))
                lines.append("};")
                lines.append("")
            path = os.path.join(args.out_dir, fname)
            with open(path, "w") as fh:
                fh.write("\n".join(lines))
            print("wrote %s (%d lines)" % (path, len(lines)))


main()
