"""Checks glint_blender/materials.py against Cycles, one material at a time.

    blender -b --factory-startup --python tests/plugin/materials_check.py -- \
        --glint build/glint [--cases diffuse,glossy] [--spp 64] [--out /tmp/glint_materials]

For each case: a UV sphere with the material on a gray Lambert floor, under a uniform dim world
and an emitting quad, rendered by Cycles (tests/cycles/make_scenes.py's setup_render: the
VALIDATION.md recipe) and by glint's path tracer from Blender's OBJ export with the MTL
rewritten by materials.rewrite_mtl and a .pov as make_scenes.write_pov writes it. Prints, per
case, the ratio of the image means (Cycles / glint, per channel and for the sphere's central
square), the relMSE of glint against Cycles and the warnings rewrite_mtl gave. Exits 1 when a
case is off by more than its tolerance (TOLERANCE, else --tolerance).
"""

import argparse
import math
import os
import subprocess
import sys

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "tests", "cycles"))
import make_scenes as ms  # noqa: E402

# The add-on's package, imported without enabling it (materials.py uses images.py beside it).
sys.path.insert(0, os.path.join(ROOT, "plugin", "blender"))
from glint_blender import materials as materials  # noqa: E402

W, H = 96, 72
ARGS = None


# ----------------------------------------------------------------------------- images

def np_image(name, w, h, fn, colorspace="sRGB", alpha=False):
    """A never-saved image whose pixels fn(u, v) -> (h, w, 4) gives (Blender's bottom-up rows)."""
    import numpy as np
    img = bpy.data.images.new(name, w, h, alpha=alpha)
    # Before the pixels: changing a generated image's colour space regenerates it (blank).
    img.colorspace_settings.name = colorspace
    u = (np.arange(w) + 0.5) / w
    v = (np.arange(h) + 0.5) / h
    uu, vv = np.meshgrid(u, v)
    img.pixels.foreach_set(fn(uu, vv).astype(np.float32).ravel())
    return img


def checker(uu, vv):
    import numpy as np
    c = ((np.floor(uu * 8) + np.floor(vv * 4)) % 2)[..., None]
    a = np.array([0.9, 0.75, 0.2, 1.0])
    b = np.array([0.1, 0.3, 0.7, 1.0])
    return c * a + (1 - c) * b


def stripes_normal(uu, vv):
    """A tangent-space normal map of ridges along v (8 per u turn), stored as 0.5 + n/2."""
    import numpy as np
    s = 0.6 * np.sin(uu * 2 * math.pi * 8)
    n = np.stack([s, np.zeros_like(s), np.ones_like(s)], -1)
    n /= np.linalg.norm(n, axis=-1, keepdims=True)
    return np.concatenate([0.5 + 0.5 * n, np.ones(uu.shape + (1,))], -1)


def stripes_height(uu, vv):
    import numpy as np
    h = 0.5 + 0.5 * np.sin(uu * 2 * math.pi * 8)
    return np.stack([h, h, h, np.ones_like(h)], -1)


def roughness_ramp(uu, vv):
    import numpy as np
    r = np.clip(uu, 0, 1)  # stored values; the case tags the image Non-Color
    return np.stack([r, r, r, np.ones_like(r)], -1)


# ----------------------------------------------------------------------------- cases

def node_material(name, kind):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nt = m.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    n = nt.nodes.new(kind)
    nt.links.new(n.outputs[0], out.inputs["Surface"])
    return m, n


def principled(name, **kw):
    return ms.principled_material(name, **kw)


def p_node(m):
    return next(n for n in m.node_tree.nodes if n.type == "BSDF_PRINCIPLED")


def link_image(m, img, socket, output="Color"):
    nt = m.node_tree
    t = nt.nodes.new("ShaderNodeTexImage")
    t.image = img
    t.interpolation = "Linear"
    nt.links.new(t.outputs[output], socket)
    return t


def case_principled_plastic():
    return principled("plastic", base=(0.1, 0.2, 0.6), roughness=0.3)


def case_principled_metal():
    return principled("gold", base=(1.0, 0.78, 0.34), metallic=1.0, roughness=0.25)


def case_principled_glass():
    return principled("glass", base=(1, 1, 1), roughness=0.0, transmission=1.0, ior=1.45)


def case_principled_emission():
    return principled("glow", base=(0.5, 0.5, 0.5), roughness=0.5,
                      emission=(1.0, 0.5, 0.2), strength=3.0)


def case_principled_alpha():
    m = principled("half", base=(0.8, 0.2, 0.1), roughness=0.4)
    p_node(m).inputs["Alpha"].default_value = 0.4
    return m


def case_principled_texture():
    m = principled("textured", roughness=0.5)
    link_image(m, np_image("checker", 512, 256, checker), p_node(m).inputs["Base Color"])
    return m


def case_principled_texture_file():
    """A saved PNG on disk: referenced by its path, read by glint itself (sRGB)."""
    img = np_image("checker_file", 512, 256, checker)
    path = os.path.join(ARGS.out, "checker_file.png")
    img.filepath_raw = path
    img.file_format = "PNG"
    img.save()
    bpy.data.images.remove(img)
    m = principled("textured_file", roughness=0.5)
    link_image(m, bpy.data.images.load(path), p_node(m).inputs["Base Color"])
    return m


def case_emission_texture():
    m, n = node_material("emission_texture", "ShaderNodeEmission")
    n.inputs["Strength"].default_value = 2.5
    link_image(m, np_image("checker_e", 512, 256, checker), n.inputs["Color"])
    return m


def case_principled_roughness_map():
    m = principled("rough_map", base=(0.7, 0.7, 0.7), metallic=1.0)
    img = np_image("ramp", 64, 8, roughness_ramp, colorspace="sRGB")  # Cycles decodes it
    link_image(m, img, p_node(m).inputs["Roughness"])
    return m


def case_principled_normal_map():
    m = principled("normal_mapped", base=(0.8, 0.8, 0.8), roughness=0.5)
    nt = m.node_tree
    nm = nt.nodes.new("ShaderNodeNormalMap")
    nm.inputs["Strength"].default_value = 1.0
    link_image(m, np_image("ridges_n", 256, 16, stripes_normal, "Non-Color"), nm.inputs["Color"])
    nt.links.new(nm.outputs["Normal"], p_node(m).inputs["Normal"])
    return m


def case_principled_bump():
    m = principled("bumped", base=(0.8, 0.8, 0.8), roughness=0.5)
    nt = m.node_tree
    b = nt.nodes.new("ShaderNodeBump")
    b.inputs["Strength"].default_value = 1.0
    b.inputs["Distance"].default_value = 0.1
    link_image(m, np_image("ridges_h", 256, 16, stripes_height, "Non-Color"), b.inputs["Height"])
    nt.links.new(b.outputs["Normal"], p_node(m).inputs["Normal"])
    return m


def case_principled_rough_glass():
    return principled("rough_glass", base=(0.9, 0.95, 1.0), roughness=0.3, transmission=1.0,
                      ior=1.5)


def case_principled_alpha_map():
    import numpy as np
    m = principled("alpha_map", base=(0.8, 0.3, 0.1), roughness=0.5)
    img = np_image("holes", 256, 128, lambda uu, vv: np.stack(
        [uu, vv, 0 * uu, (np.sin(uu * 2 * math.pi * 6) > 0).astype(float)], -1), alpha=True)
    link_image(m, img, p_node(m).inputs["Alpha"], output="Alpha")
    return m


def case_glass_beckmann_rough():
    m, n = node_material("glass_beckmann", "ShaderNodeBsdfGlass")
    n.inputs["Roughness"].default_value = 0.3
    n.inputs["IOR"].default_value = 1.5
    n.distribution = "BECKMANN"
    return m


def case_mix_diffuse_glossy():
    m, d = node_material("diffuse_glossy", "ShaderNodeBsdfDiffuse")
    nt = m.node_tree
    d.inputs["Color"].default_value = (0.7, 0.3, 0.2, 1)
    g = nt.nodes.new("ShaderNodeBsdfGlossy")
    g.inputs["Roughness"].default_value = 0.2
    mix = nt.nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = 0.2
    out = next(n for n in nt.nodes if n.type == "OUTPUT_MATERIAL")
    nt.links.new(d.outputs[0], mix.inputs[1])
    nt.links.new(g.outputs[0], mix.inputs[2])
    nt.links.new(mix.outputs[0], out.inputs["Surface"])
    return m


def case_principled_sheen_clearcoat():
    m = principled("sheen_clearcoat", base=(0.2, 0.4, 0.7), roughness=0.5)
    p_node(m).inputs["Sheen"].default_value = 1.0
    p_node(m).inputs["Clearcoat"].default_value = 1.0
    return m


def case_diffuse():
    m, n = node_material("diffuse", "ShaderNodeBsdfDiffuse")
    n.inputs["Color"].default_value = (0.7, 0.3, 0.2, 1)
    return m


def case_glossy():
    m, n = node_material("glossy", "ShaderNodeBsdfGlossy")
    n.inputs["Color"].default_value = (0.9, 0.6, 0.3, 1)
    n.inputs["Roughness"].default_value = 0.3
    n.distribution = "GGX"
    return m


def case_glossy_white():
    m, n = node_material("glossy_white", "ShaderNodeBsdfGlossy")
    n.inputs["Color"].default_value = (1, 1, 1, 1)
    n.inputs["Roughness"].default_value = 0.2
    n.distribution = "GGX"
    return m


def case_glass():
    m, n = node_material("glass_bsdf", "ShaderNodeBsdfGlass")
    n.inputs["Color"].default_value = (1, 1, 1, 1)
    n.inputs["Roughness"].default_value = 0.0
    n.inputs["IOR"].default_value = 1.5
    return m


def case_emission():
    m, n = node_material("emission", "ShaderNodeEmission")
    n.inputs["Color"].default_value = (1.0, 0.8, 0.5, 1)
    n.inputs["Strength"].default_value = 2.0
    return m


def case_no_nodes():
    m = bpy.data.materials.new("no nodes")
    m.use_nodes = False
    m.diffuse_color = (0.2, 0.5, 0.3, 1)
    return m


def case_mix_transparent():
    m, d = node_material("diffuse_transparent", "ShaderNodeBsdfDiffuse")
    nt = m.node_tree
    d.inputs["Color"].default_value = (0.2, 0.6, 0.8, 1)
    t = nt.nodes.new("ShaderNodeBsdfTransparent")
    mix = nt.nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = 0.6  # 60 % transparent
    out = next(n for n in nt.nodes if n.type == "OUTPUT_MATERIAL")
    nt.links.new(d.outputs[0], mix.inputs[1])
    nt.links.new(t.outputs[0], mix.inputs[2])
    nt.links.new(mix.outputs[0], out.inputs["Surface"])
    return m


def case_add_emission():
    m, d = node_material("diffuse_plus_emission", "ShaderNodeBsdfDiffuse")
    nt = m.node_tree
    d.inputs["Color"].default_value = (0.5, 0.5, 0.5, 1)
    e = nt.nodes.new("ShaderNodeEmission")
    e.inputs["Color"].default_value = (0.2, 0.4, 1.0, 1)
    e.inputs["Strength"].default_value = 1.5
    add = nt.nodes.new("ShaderNodeAddShader")
    out = next(n for n in nt.nodes if n.type == "OUTPUT_MATERIAL")
    nt.links.new(d.outputs[0], add.inputs[0])
    nt.links.new(e.outputs[0], add.inputs[1])
    nt.links.new(add.outputs[0], out.inputs["Surface"])
    return m


CASES = {k[len("case_"):]: v for k, v in globals().items() if k.startswith("case_")}


# ----------------------------------------------------------------------------- scene

def build(case):
    ms.reset()
    floor = ms.diffuse_material("floor", (0.5, 0.5, 0.5))
    ms.add_mesh("floor", [(-4, -4, 0), (4, -4, 0), (4, 4, 0), (-4, 4, 0)], [(0, 1, 2, 3)], floor)
    m = CASES[case]()
    bpy.ops.mesh.primitive_uv_sphere_add(segments=64, ring_count=32, radius=0.8,
                                         location=(0, 0, 0.8))
    ob = bpy.context.active_object
    ob.name = "sphere"
    bpy.ops.object.shade_smooth()
    ob.data.materials.append(m)
    light = ms.emitter_material("light", (1.0, 1.0, 1.0), 8.0)
    ms.add_quad("light", (-1.2, -1.2, 3.0), 1.5, 1.0, light)
    ms.add_camera((0, -4.0, 1.6), (0, 0, 0.75), lens_mm=40.0)
    ms.set_world_color((0.3, 0.32, 0.35))
    return m


def export(out_dir, warnings):
    obj = os.path.join(out_dir, "scene.obj")
    bpy.ops.wm.obj_export(filepath=obj, export_eval_mode="DAG_EVAL_RENDER", apply_modifiers=True,
                          forward_axis="NEGATIVE_Z", up_axis="Y", export_uv=True,
                          export_normals=True, export_materials=True,
                          export_pbr_extensions=True, path_mode="ABSOLUTE",
                          export_triangulated_mesh=True, export_object_groups=False,
                          export_smooth_groups=False)
    materials.rewrite_mtl(os.path.join(out_dir, "scene.mtl"),
                          bpy.context.evaluated_depsgraph_get(), out_dir, warnings.append)
    ms.W, ms.H = W, H
    ms.write_pov("scene", out_dir, {"world": ("color", (0.3, 0.32, 0.35))})


def run_case(case, args):
    import numpy as np
    out_dir = os.path.join(args.out, case)
    os.makedirs(out_dir, exist_ok=True)
    m = build(case)
    warnings = []
    export(out_dir, warnings)
    with open(os.path.join(out_dir, "scene.mtl")) as f:
        block = dict(materials.parse_mtl(f.read())[1])[materials.mtl_name(m.name)]
    ms.W, ms.H = W, H
    cyc = os.path.join(out_dir, "cycles.exr")
    if not os.path.exists(cyc) or args.force:
        ms.render_to(cyc, args.spp, 1)
    gl = os.path.join(out_dir, "glint.exr")
    subprocess.run([args.glint, "render", os.path.join(out_dir, "scene.pov"), "-o", gl,
                    "-W", str(W), "-H", str(H), "--integrator", "path", "--spp",
                    str(args.spp), "--max-depth", str(ms.MAX_DEPTH), "--seed", "1"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    a = ms.load_pixels(cyc)
    b = ms.load_pixels(gl)
    ratio = a.reshape(-1, 3).mean(0) / np.maximum(b.reshape(-1, 3).mean(0), 1e-9)
    # The sphere's middle (rows and columns 30..70 % of the image).
    sl = (slice(int(0.3 * H), int(0.7 * H)), slice(int(0.35 * W), int(0.65 * W)))
    core = a[sl].mean() / max(b[sl].mean(), 1e-9)
    relmse = float(np.mean((b - a) ** 2 / (a ** 2 + 0.01)))
    return ratio, core, relmse, warnings, block


# Tolerances on |ratio - 1| (image mean per channel and sphere core) where they differ from
# --tolerance. glossy: Cycles' Glossy BSDF has no Fresnel, glint's metal rises to white at
# grazing angles. Normal and bump maps: Cycles darkens diffuse under a bent normal (shadow
# terminator term) and keeps bent normals' reflections above the surface; glint does neither
# yet (formats/obj/MTL.md), so the sphere's core differs by ~5 % and its rim shows dark seams.
TOLERANCE = {"glossy": 0.03, "principled_normal_map": 0.08, "principled_bump": 0.08}
# Conversions that warn (approximations): measured and printed, never failed.
APPROXIMATE = {"glass_beckmann_rough", "mix_diffuse_glossy", "principled_sheen_clearcoat"}


def main(argv):
    ap = argparse.ArgumentParser(prog="materials_check.py")
    ap.add_argument("--glint", default=os.environ.get("GLINT_BINARY", "glint"))
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--spp", type=int, default=64)
    ap.add_argument("--out", default="/tmp/glint_materials")
    ap.add_argument("--tolerance", type=float, default=0.015)
    ap.add_argument("--force", action="store_true", help="re-render the Cycles images")
    ap.add_argument("--verbose", action="store_true", help="print each material's MTL block")
    args = ap.parse_args(argv)
    global ARGS
    ARGS = args
    os.makedirs(args.out, exist_ok=True)
    failed = []
    print("%-26s %-22s %7s %8s  warnings" % ("case", "Cycles/glint mean rgb", "sphere",
                                             "relMSE"))
    for case in args.cases.split(","):
        ratio, core, relmse, warnings, block = run_case(case, args)
        print("%-26s %6.3f %6.3f %6.3f   %7.3f %8.4f  %s" % (
            case, ratio[0], ratio[1], ratio[2], core, relmse, " | ".join(warnings) or "-"))
        if args.verbose:
            print("    " + "; ".join(block))
        sys.stdout.flush()
        off = max(abs(ratio - 1).max(), abs(core - 1))
        if off > TOLERANCE.get(case, args.tolerance) and case not in APPROXIMATE:
            failed.append(case)
    if failed:
        print("FAILED (off by more than %g): %s" % (args.tolerance, ", ".join(failed)))
        sys.exit(1)


if __name__ == "__main__":
    main(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
