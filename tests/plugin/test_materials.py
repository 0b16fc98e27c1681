"""Unit tests of plugin/blender/glint_blender/materials.py (no glint binary needed).

    blender -b --factory-startup --python-exit-code 1 --python tests/plugin/test_materials.py

Each test builds materials in an empty scene, exports it with Blender's OBJ exporter as the
add-on does, runs rewrite_mtl and checks the statements glint will read and the warnings.
Exits 1 when a test fails.
"""

import math
import os
import sys
import tempfile
import traceback

import bpy

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# The add-on's package, imported without enabling it (materials.py uses images.py beside it).
sys.path.insert(0, os.path.join(ROOT, "plugin", "blender"))
from glint_blender import materials as M  # noqa: E402

TMP = tempfile.mkdtemp(prefix="glint_test_materials_")


# ----------------------------------------------------------------------------- helpers

def reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def node_material(name, kind=None):
    """A material whose output is fed by a new node of `kind` (None: Principled defaults)."""
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nt = m.node_tree
    if kind is None:
        return m, next(n for n in nt.nodes if n.type == "BSDF_PRINCIPLED")
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    n = nt.nodes.new(kind)
    nt.links.new(n.outputs[0], out.inputs["Surface"])
    return m, n


def add_sphere(m, x=0.0):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=8, ring_count=4, location=(x, 0, 0))
    bpy.context.active_object.data.materials.append(m)


def export(name):
    """Export the scene, rewrite the MTL; returns ({material: {statement: value}}, warnings,
    the MTL text)."""
    d = os.path.join(TMP, name)
    os.makedirs(d, exist_ok=True)
    obj = os.path.join(d, "scene.obj")
    bpy.ops.wm.obj_export(filepath=obj, export_eval_mode="DAG_EVAL_RENDER", apply_modifiers=True,
                          forward_axis="NEGATIVE_Z", up_axis="Y", export_uv=True,
                          export_materials=True, export_pbr_extensions=True,
                          path_mode="ABSOLUTE", export_triangulated_mesh=True)
    warnings = []
    mtl = os.path.join(d, "scene.mtl")
    M.rewrite_mtl(mtl, bpy.context.evaluated_depsgraph_get(), d, warnings.append)
    with open(mtl) as f:
        text = f.read()
    blocks = {}
    for bname, lines in M.parse_mtl(text)[1]:
        st = {}
        for line in lines:
            k, _, v = line.partition(" ")
            st[k] = v
        blocks[bname] = st
    return blocks, warnings, text


def floats(s):
    return [float(x) for x in s.split()]


def close(a, b, eps=1e-5):
    a = a if isinstance(a, (list, tuple)) else [a]
    b = b if isinstance(b, (list, tuple)) else [b]
    return len(a) == len(b) and all(abs(x - y) <= eps for x, y in zip(a, b))


def image(name, w=8, h=4, color=(0.5, 0.25, 0.75, 1.0), colorspace="sRGB"):
    img = bpy.data.images.new(name, w, h)
    img.colorspace_settings.name = colorspace  # before the pixels (it regenerates the image)
    img.pixels.foreach_set([c for _ in range(w * h) for c in color])
    return img


def tex(m, img, socket, output="Color"):
    t = m.node_tree.nodes.new("ShaderNodeTexImage")
    t.image = img
    m.node_tree.links.new(t.outputs[output], socket)
    return t


def read_pfm(path):
    import numpy as np
    with open(path, "rb") as f:
        assert f.readline() == b"PF\n"
        w, h = (int(x) for x in f.readline().split())
        assert float(f.readline()) < 0
        return w, h, np.frombuffer(f.read(), dtype="<f4").reshape(h, w, 3)


# ----------------------------------------------------------------------------- tests

def test_name_mapping():
    assert M.mtl_name("My Mat.001") == "My_Mat.001"
    assert M.mtl_name("a.b#c") == "a.b#c"
    reset()
    a, p = node_material("My Mat.001")
    p.inputs["Base Color"].default_value = (0.1, 0.2, 0.3, 1)
    b, d = node_material("plain.name", "ShaderNodeBsdfDiffuse")
    d.inputs["Color"].default_value = (0.4, 0.5, 0.6, 1)
    add_sphere(a)
    add_sphere(b, 3)
    blocks, warnings, text = export("names")
    assert set(blocks) == {"My_Mat.001", "plain.name"}, blocks.keys()
    assert close(floats(blocks["My_Mat.001"]["Kd"]), [0.1, 0.2, 0.3])
    assert close(floats(blocks["plain.name"]["Kd"]), [0.4, 0.5, 0.6])
    assert warnings == [], warnings
    assert text.startswith("# Blender"), "glint recognises Blender's MTL by its first line"


def test_name_collision_warns_once():
    reset()
    a, _ = node_material("x y")
    b, _ = node_material("x_y")
    add_sphere(a)
    add_sphere(b, 3)
    blocks, warnings, _ = export("collision")
    assert len([w for w in warnings if "exported as 'x_y'" in w]) == 1, warnings


def test_parse_mtl():
    header, blocks = M.parse_mtl("# Blender 3.4.1 MTL File\n\nnewmtl a b\nKd 1 2 3\n\n"
                                 "newmtl c\n  Ns 10\n")
    assert header == ["# Blender 3.4.1 MTL File", ""]
    assert blocks == [("a b", ["Kd 1 2 3"]), ("c", ["  Ns 10"])], blocks


def test_principled_statements():
    reset()
    m, p = node_material("pbr")
    i = p.inputs
    i["Base Color"].default_value = (0.1, 0.2, 0.3, 1)
    i["Metallic"].default_value = 0.4
    i["Roughness"].default_value = 0.6
    i["Specular"].default_value = 0.3
    i["IOR"].default_value = 1.33
    i["Transmission"].default_value = 0.5
    i["Emission"].default_value = (1.0, 0.5, 0.0, 1)
    i["Emission Strength"].default_value = 2.0
    i["Alpha"].default_value = 0.7
    add_sphere(m)
    blocks, warnings, _ = export("principled")
    s = blocks["pbr"]
    assert close(floats(s["Kd"]), [0.1, 0.2, 0.3])
    assert close(float(s["Pm"]), 0.4) and close(float(s["Pr"]), 0.6)
    assert close(floats(s["Ks"]), [0.3] * 3)
    assert close(float(s["Ni"]), 1.33)
    assert close(floats(s["Tf"]), [0.5] * 3)
    assert close(floats(s["Ke"]), [2.0, 1.0, 0.0])
    assert close(float(s["d"]), 0.7)
    assert "Ps" in s, "Ps marks the material Principled (glint: Burley diffuse)"
    assert warnings == [], warnings


def test_principled_unsupported_inputs_one_warning():
    reset()
    m, p = node_material("fancy")
    i = p.inputs
    i["Sheen"].default_value = 0.5
    i["Clearcoat"].default_value = 0.3
    i["Subsurface"].default_value = 0.2
    i["Specular Tint"].default_value = 0.4
    i["Anisotropic"].default_value = 0.1
    noise = m.node_tree.nodes.new("ShaderNodeTexNoise")
    m.node_tree.links.new(noise.outputs["Fac"], i["Roughness"])
    ok, _ = node_material("clean")
    add_sphere(m)
    add_sphere(ok, 3)
    blocks, warnings, _ = export("unsupported")
    assert len(warnings) == 1, warnings
    w = warnings[0]
    assert w.startswith("material 'fancy'"), w
    for what in ("Sheen", "Clearcoat", "Subsurface", "Specular Tint", "Anisotropic",
                 "Roughness is linked to a Noise Texture"):
        assert what in w, (what, w)
    assert close(float(blocks["fancy"]["Pr"]), 0.5), "a linked socket keeps its own value"


def test_diffuse_is_lambert():
    reset()
    m, d = node_material("lambert", "ShaderNodeBsdfDiffuse")
    d.inputs["Color"].default_value = (0.7, 0.3, 0.2, 1)
    d.inputs["Roughness"].default_value = 0.5
    add_sphere(m)
    blocks, warnings, _ = export("diffuse")
    s = blocks["lambert"]
    assert close(floats(s["Kd"]), [0.7, 0.3, 0.2])
    assert close(floats(s["Ks"]), [0, 0, 0])
    for k in ("Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor", "Ns", "Tf"):
        assert k not in s, "no PBR statement: glint uses Lambert (%s)" % k
    assert len(warnings) == 1 and "Oren-Nayar" in warnings[0], warnings


def test_glossy_is_metal():
    reset()
    m, g = node_material("metal", "ShaderNodeBsdfGlossy")
    g.inputs["Color"].default_value = (0.9, 0.6, 0.3, 1)
    g.inputs["Roughness"].default_value = 0.25
    g.distribution = "BECKMANN"
    add_sphere(m)
    blocks, warnings, _ = export("glossy")
    s = blocks["metal"]
    assert close(floats(s["Kd"]), [0.9, 0.6, 0.3])
    assert close(float(s["Pm"]), 1) and close(float(s["Pr"]), 0.25)
    assert "Ps" not in s
    assert len(warnings) == 1 and "BECKMANN" in warnings[0], warnings


def test_glass():
    reset()
    m, g = node_material("glass", "ShaderNodeBsdfGlass")
    g.inputs["IOR"].default_value = 1.5
    g.inputs["Roughness"].default_value = 0.0  # sharp: Beckmann = GGX, no warning
    add_sphere(m)
    blocks, warnings, _ = export("glass")
    s = blocks["glass"]
    assert close(floats(s["Tf"]), [1, 1, 1]) and close(float(s["Ni"]), 1.5)
    assert close(float(s["Pr"]), 0) and close(float(s["Pm"]), 0)
    assert warnings == [], warnings


def test_emission_shader():
    reset()
    m, e = node_material("lamp", "ShaderNodeEmission")
    e.inputs["Color"].default_value = (1.0, 0.8, 0.5, 1)
    e.inputs["Strength"].default_value = 4.0
    add_sphere(m)
    blocks, warnings, _ = export("emission")
    s = blocks["lamp"]
    assert close(floats(s["Ke"]), [4.0, 3.2, 2.0]) and close(floats(s["Kd"]), [0, 0, 0])
    assert warnings == [], warnings


def test_mix_shaders():
    reset()
    m, d = node_material("mixed", "ShaderNodeBsdfDiffuse")
    nt = m.node_tree
    d.inputs["Color"].default_value = (0.2, 0.6, 0.8, 1)
    g = nt.nodes.new("ShaderNodeBsdfGlossy")
    mix = nt.nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = 0.3
    out = next(n for n in nt.nodes if n.type == "OUTPUT_MATERIAL")
    nt.links.new(d.outputs[0], mix.inputs[1])
    nt.links.new(g.outputs[0], mix.inputs[2])
    nt.links.new(mix.outputs[0], out.inputs["Surface"])
    # Diffuse + Transparent (alpha) + Emission: all three carried, no warning.
    m2, d2 = node_material("cutout", "ShaderNodeBsdfDiffuse")
    nt = m2.node_tree
    t = nt.nodes.new("ShaderNodeBsdfTransparent")
    e = nt.nodes.new("ShaderNodeEmission")
    e.inputs["Color"].default_value = (1, 0, 0, 1)
    mix = nt.nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = 0.25
    add = nt.nodes.new("ShaderNodeAddShader")
    out = next(n for n in nt.nodes if n.type == "OUTPUT_MATERIAL")
    nt.links.new(d2.outputs[0], add.inputs[0])
    nt.links.new(e.outputs[0], add.inputs[1])
    nt.links.new(add.outputs[0], mix.inputs[1])
    nt.links.new(t.outputs[0], mix.inputs[2])
    nt.links.new(mix.outputs[0], out.inputs["Surface"])
    add_sphere(m)
    add_sphere(m2, 3)
    blocks, warnings, _ = export("mix")
    assert close(floats(blocks["mixed"]["Kd"]), [0.2, 0.6, 0.8]), "the dominant one (0.7)"
    assert "Pm" not in blocks["mixed"]
    s = blocks["cutout"]
    assert close(float(s["d"]), 0.75), s
    assert close(floats(s["Ke"]), [0.75, 0, 0]), s
    assert len(warnings) == 1 and warnings[0].startswith("material 'mixed'"), warnings
    assert "Glossy BSDF" in warnings[0]


def test_unsupported_shaders_warn():
    reset()
    names = []
    for k, kind in enumerate(("ShaderNodeBsdfTranslucent", "ShaderNodeSubsurfaceScattering",
                              "ShaderNodeBsdfToon", "ShaderNodeHoldout",
                              "ShaderNodeBsdfHairPrincipled")):
        m, _ = node_material("u%d" % k, kind)
        add_sphere(m, 3 * k)
        names.append(m.name)
    v, _ = node_material("vol", "ShaderNodeBsdfDiffuse")
    vol = v.node_tree.nodes.new("ShaderNodeVolumePrincipled")
    out = next(n for n in v.node_tree.nodes if n.type == "OUTPUT_MATERIAL")
    v.node_tree.links.new(vol.outputs[0], out.inputs["Volume"])
    add_sphere(v, 20)
    names.append("vol")
    blocks, warnings, _ = export("unsupported_shaders")
    assert len(warnings) == len(names), warnings
    for n in names:
        assert "Kd" in blocks[n]
        assert len([w for w in warnings if w.startswith("material '%s'" % n)]) == 1, (n, warnings)


def test_no_nodes():
    reset()
    m = bpy.data.materials.new("flat")
    m.use_nodes = False
    m.diffuse_color = (0.2, 0.5, 0.3, 1)
    add_sphere(m)
    blocks, warnings, _ = export("nonodes")
    s = blocks["flat"]
    assert close(floats(s["Kd"]), [0.2, 0.5, 0.3]) and "Pr" not in s
    assert warnings == []


def test_generated_image_saved_user_image_untouched():
    reset()
    m, p = node_material("textured")
    img = image("never saved", color=(0.5, 0.25, 0.75, 1.0))
    before = (img.filepath, img.source, img.is_dirty, img.file_format, img.packed_file)
    t = tex(m, img, p.inputs["Base Color"])
    mp = m.node_tree.nodes.new("ShaderNodeMapping")
    mp.inputs["Location"].default_value = (0.25, 0.5, 0)
    mp.inputs["Scale"].default_value = (2, 3, 1)
    m.node_tree.links.new(mp.outputs[0], t.inputs["Vector"])
    uv = m.node_tree.nodes.new("ShaderNodeTexCoord")
    m.node_tree.links.new(uv.outputs["UV"], mp.inputs["Vector"])
    add_sphere(m)
    blocks, warnings, _ = export("generated")
    s = blocks["textured"]
    assert "Kd" not in s, "the map replaces the constant"
    args = s["map_Kd"].split()
    assert args[:8] == ["-o", "0.250000", "0.500000", "0", "-s", "2.000000", "3.000000", "1"], args
    assert args[8] == "textures/never_saved.pfm", args
    w, h, px = read_pfm(os.path.join(TMP, "generated", args[8]))
    assert (w, h) == (8, 4)
    assert close(list(px[0, 0]), [M.srgb_decode(0.5), M.srgb_decode(0.25), M.srgb_decode(0.75)],
                 2e-3), px[0, 0]
    assert (img.filepath, img.source, img.is_dirty, img.file_format, img.packed_file) == before
    assert warnings == [], warnings


def test_saved_images_and_colour_spaces():
    reset()
    # A Non-Color PNG on disk for roughness: glint reads it as it is (linear): its own path.
    d = os.path.join(TMP, "files")
    os.makedirs(d, exist_ok=True)
    rough = image("rough", color=(0.2, 0.2, 0.2, 1), colorspace="Non-Color")
    rough.filepath_raw = os.path.join(d, "rough.png")
    rough.file_format = "PNG"
    rough.save()
    # The same file tagged sRGB for metallic: Cycles decodes it, glint would not: a PFM.
    metal = bpy.data.images.load(os.path.join(d, "rough.png"), check_existing=False)
    metal.colorspace_settings.name = "sRGB"
    m, p = node_material("maps")
    tex(m, rough, p.inputs["Roughness"])
    tex(m, metal, p.inputs["Metallic"])
    add_sphere(m)
    blocks, warnings, _ = export("colorspaces")
    s = blocks["maps"]
    assert s["map_Pr"] == os.path.join(d, "rough.png"), s
    assert s["map_Pm"].endswith(".pfm"), s
    _, _, px = read_pfm(os.path.join(TMP, "colorspaces", s["map_Pm"]))
    assert close(float(px[0, 0, 0]), M.srgb_decode(51 / 255), 1e-4), px[0, 0]
    assert "Pr" not in s and "Pm" not in s
    assert warnings == [], warnings


def test_normal_and_bump_maps():
    reset()
    m, p = node_material("normal")
    nm = m.node_tree.nodes.new("ShaderNodeNormalMap")
    nm.inputs["Strength"].default_value = 0.7
    tex(m, image("nmap", color=(0.5, 0.5, 1, 1), colorspace="Non-Color"), nm.inputs["Color"])
    m.node_tree.links.new(nm.outputs[0], p.inputs["Normal"])
    b, d = node_material("bump", "ShaderNodeBsdfDiffuse")
    bump = b.node_tree.nodes.new("ShaderNodeBump")
    bump.inputs["Strength"].default_value = 0.5
    bump.inputs["Distance"].default_value = 0.2
    bump.invert = True
    tex(b, image("height", color=(0.9, 0.2, 0.1, 1), colorspace="Non-Color"),
        bump.inputs["Height"])
    b.node_tree.links.new(bump.outputs[0], d.inputs["Normal"])
    add_sphere(m)
    add_sphere(b, 3)
    blocks, warnings, _ = export("normals")
    a = blocks["normal"]["map_Bump"].split()
    assert a[:2] == ["-bm", "0.700000"] and a[2].endswith("nmap.pfm"), a
    a = blocks["bump"]["map_Bump"].split()
    assert a[:2] == ["-bm", "-0.100000"], a
    _, _, px = read_pfm(os.path.join(TMP, "normals", a[2]))
    lum = 0.2126 * 0.9 + 0.7152 * 0.2 + 0.0722 * 0.1
    assert close(list(px[0, 0]), [lum] * 3, 2e-3), "a colour height map becomes its gray"
    assert warnings == [], warnings


def test_unsupported_vector_input_warns():
    reset()
    m, p = node_material("objcoords")
    t = tex(m, image("c"), p.inputs["Base Color"])
    tc = m.node_tree.nodes.new("ShaderNodeTexCoord")
    m.node_tree.links.new(tc.outputs["Object"], t.inputs["Vector"])
    add_sphere(m)
    blocks, warnings, _ = export("vector")
    assert len(warnings) == 1 and "Base Color: texture coordinates from Texture Coordinate "\
        "Object" in warnings[0], warnings
    assert "map_Kd" in blocks["objcoords"]


# ----------------------------------------------------------------------------- main

def main():
    tests = [(k, v) for k, v in globals().items() if k.startswith("test_") and callable(v)]
    failed = []
    for name, fn in tests:
        try:
            fn()
            print("PASS", name)
        except Exception:
            failed.append(name)
            print("FAIL", name)
            traceback.print_exc()
    print("%d tests, %d failed" % (len(tests), len(failed)))
    sys.stdout.flush()
    if failed:
        sys.exit(1)


if __name__ == "__main__":
    main()
