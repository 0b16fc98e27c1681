"""Tests of the add-on's native export (plugin/blender/glint_blender/native_export.py,
formats/blender/FORMAT.md); no glint binary needed.

    blender -b --factory-startup --python-exit-code 1 --python tests/plugin/test_native_export.py
        [-- [--only NAME ...] [--keep DIR] [--timing]]

Each test builds a scene from scratch, exports it, runs check_native_export.py over the folder
and checks what it must hold. --timing adds the speed scenes (a 1M-triangle grid against a
Cycles render's sync time, 10,000 linked Suzannes) and prints their times. Exits 1 when a test
fails.
"""

import os
import shutil
import sys
import tempfile
import time
import traceback

import bpy
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "plugin", "blender"))
sys.path.insert(0, HERE)
from glint_blender import native_export as NX  # noqa: E402
import check_native_export as CHK  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
KEEP = ARGS[ARGS.index("--keep") + 1] if "--keep" in ARGS else None
TMP = KEEP or tempfile.mkdtemp(prefix="glint_test_native_")


def reset():
    bpy.ops.wm.read_factory_settings(use_empty=False)


def export(name):
    """Exports the current scene into TMP/name; returns (doc, summary, warnings, Export,
    seconds)."""
    d = os.path.join(TMP, name)
    shutil.rmtree(d, ignore_errors=True)
    warnings = []
    dg = bpy.context.evaluated_depsgraph_get()
    t = time.perf_counter()
    ex = NX.export_frame_native(dg, d, warnings.append)
    secs = time.perf_counter() - t
    doc, summary = CHK.check(d)
    return doc, summary, warnings, ex, secs


def read_view(name, view):
    """A buffer view of TMP/name/scene.bin as a numpy array (components as columns)."""
    dt = {"f32": "<f4", "u32": "<u4", "u16": "<u2", "u8": "u1"}[view["type"]]
    k = view.get("components", 1)
    a = np.fromfile(os.path.join(TMP, name, "scene.bin"), dtype=dt, count=view["count"] * k,
                    offset=view["offset"])
    return a.reshape(-1, k) if k > 1 else a


def blender_mesh_arrays(ob):
    """What the exchange must hold for an object's evaluated mesh, read the slow, plain way."""
    me = ob.evaluated_get(bpy.context.evaluated_depsgraph_get()).to_mesh()
    me.calc_loop_triangles()
    me.calc_normals_split()
    out = {"positions": np.array([v.co for v in me.vertices]),
           "loop_vertex": np.array([l.vertex_index for l in me.loops]),
           "normals": np.array([l.normal for l in me.loops]),
           "triangles": np.array([t.loops[:] for t in me.loop_triangles]),
           "smooth": np.array([t.use_smooth for t in me.loop_triangles]),
           "material_index": np.array([t.material_index for t in me.loop_triangles])}
    ob.evaluated_get(bpy.context.evaluated_depsgraph_get()).to_mesh_clear()
    return out


def compare_meshes(name, doc, objects):
    for ob in objects:
        o = next(o for o in doc["objects"] if o["name"] == ob.name)
        m = doc["meshes"][o["mesh"]]
        want = blender_mesh_arrays(ob)
        for key, expect in want.items():
            got = read_view(name, m[key])
            assert got.shape[0] == expect.shape[0], (ob.name, key, got.shape, expect.shape)
            err = np.abs(got.astype(np.float64) - expect.astype(np.float64)).max()
            assert err < 1e-6, (ob.name, key, err)


def graph_types(g):
    return [n["type"] for n in g["nodes"]]


def node_of(g, kind):
    return next(n for n in g["nodes"] if n["type"] == kind)


def inp(node, ident):
    return next(s for s in node["inputs"] if s["id"] == ident)


# ----------------------------------------------------------------------------- scenes


def noise_ramp_material():
    """Noise -> (reroute) -> ColorRamp -> group(Multiply by a group input) -> muted Invert ->
    Principled Base Color."""
    m = bpy.data.materials.new("NoiseRamp")
    m.use_nodes = True
    nt = m.node_tree
    bsdf = nt.nodes["Principled BSDF"]
    noise = nt.nodes.new("ShaderNodeTexNoise")
    noise.inputs["Scale"].default_value = 7.0
    ramp = nt.nodes.new("ShaderNodeValToRGB")
    ramp.color_ramp.elements[0].color = (0.1, 0.2, 0.8, 1)
    ramp.color_ramp.elements.new(0.6).color = (1, 0.5, 0, 1)
    reroute = nt.nodes.new("NodeReroute")
    nt.links.new(noise.outputs["Fac"], reroute.inputs[0])
    nt.links.new(reroute.outputs[0], ramp.inputs["Fac"])
    # A group: Color * Factor (a group input left unlinked on the group node -> its value).
    grp = bpy.data.node_groups.new("Tint", "ShaderNodeTree")
    gi = grp.nodes.new("NodeGroupInput")
    go = grp.nodes.new("NodeGroupOutput")
    grp.inputs.new("NodeSocketColor", "Color")
    grp.inputs.new("NodeSocketFloat", "Factor")
    grp.outputs.new("NodeSocketColor", "Color")
    mix = grp.nodes.new("ShaderNodeMixRGB")
    mix.blend_type = 'MULTIPLY'
    mix.inputs["Fac"].default_value = 1.0
    grp.links.new(gi.outputs[0], mix.inputs["Color1"])
    grp.links.new(gi.outputs[1], mix.inputs["Color2"])   # float -> colour: a constant node
    grp.links.new(mix.outputs[0], go.inputs[0])
    gnode = nt.nodes.new("ShaderNodeGroup")
    gnode.node_tree = grp
    gnode.inputs["Factor"].default_value = 0.5
    nt.links.new(ramp.outputs["Color"], gnode.inputs["Color"])
    inv = nt.nodes.new("ShaderNodeInvert")
    inv.mute = True
    nt.links.new(gnode.outputs[0], inv.inputs["Color"])
    nt.links.new(inv.outputs["Color"], bsdf.inputs["Base Color"])
    curves = nt.nodes.new("ShaderNodeRGBCurve")
    curves.mapping.curves[3].points[1].location = (0.8, 1.0)
    nt.links.new(noise.outputs["Color"], curves.inputs["Color"])
    nt.links.new(curves.outputs["Color"], bsdf.inputs["Emission"])
    img = bpy.data.images.new("Generated", 8, 8)
    tex = nt.nodes.new("ShaderNodeTexImage")
    tex.image = img
    nt.links.new(tex.outputs["Alpha"], bsdf.inputs["Roughness"])
    frame = nt.nodes.new("NodeFrame")
    noise.parent = frame
    return m


def test_default_cube():
    reset()
    cube = bpy.data.objects["Cube"]
    cube.data.materials.clear()
    cube.data.materials.append(noise_ramp_material())
    bpy.ops.mesh.primitive_plane_add(location=(0, 0, -1))
    plane = bpy.context.active_object
    plane.data.materials.append(None)               # an empty slot
    nomat = bpy.data.materials.new("NoNodes")       # a material without nodes
    nomat.use_nodes = False
    nomat.diffuse_color = (0.2, 0.4, 0.6, 1)
    bpy.ops.mesh.primitive_uv_sphere_add(location=(2, 0, 0))
    bpy.context.active_object.data.materials.append(nomat)
    bpy.context.active_object.data.color_attributes.new("Col", 'BYTE_COLOR', 'CORNER')
    bpy.ops.object.text_add(location=(0, 2, 0))     # text: converted to a mesh
    bpy.ops.mesh.primitive_uv_sphere_add(location=(-2, 0, 0))
    smooth = bpy.context.active_object             # smooth, half of it flat
    smooth.name = "Smooth"
    for p in smooth.data.polygons:
        p.use_smooth = p.index % 2 == 0
        p.material_index = p.index % 3
    bpy.ops.mesh.primitive_cube_add(location=(-4, 0, 0))
    custom = bpy.context.active_object             # auto smooth with custom normals
    custom.name = "Custom"
    custom.data.use_auto_smooth = True
    custom.data.normals_split_custom_set_from_vertices([(0.0, 0.0, 1.0)] * 8)
    custom.modifiers.new("bevel", 'BEVEL')
    doc, summary, warnings, ex, secs = export("default_cube")
    compare_meshes("default_cube", doc, [cube, plane, bpy.data.objects["Sphere"],
                                         bpy.data.objects["Text"], smooth, custom])
    names = {o["name"] for o in doc["objects"]}
    assert {"Cube", "Plane", "Sphere", "Text"} <= names, names
    cube_o = next(o for o in doc["objects"] if o["name"] == "Cube")
    assert len(cube_o["materials"]) == 1 and cube_o["materials"][0] >= 0
    plane_o = next(o for o in doc["objects"] if o["name"] == "Plane")
    assert plane_o["materials"] == [-1], plane_o["materials"]
    mesh = doc["meshes"][cube_o["mesh"]]
    assert mesh["triangles"]["count"] == 12 and mesh["positions"]["count"] == 8, mesh
    assert mesh["loop_vertex"]["count"] == 24
    assert cube_o["random"] == NX.random_float(NX.hash_uint2(NX.hash_string("Cube"), 0))
    g = doc["materials"][cube_o["materials"][0]]["graph"]
    types = graph_types(g)
    for gone in ("ShaderNodeGroup", "NodeReroute", "NodeGroupInput", "NodeGroupOutput",
                 "ShaderNodeInvert", "NodeFrame"):
        assert gone not in types, (gone, types)
    assert types[g["output"]] == "ShaderNodeOutputMaterial"
    bsdf = node_of(g, "ShaderNodeBsdfPrincipled")
    base = inp(bsdf, "Base Color")
    mix = g["nodes"][base["link"][0]]
    assert mix["type"] == "ShaderNodeMixRGB" and mix["props"]["blend_type"] == "MULTIPLY", mix
    assert mix["name"].startswith("Group/Mix"), mix["name"]
    c2 = inp(mix, "Color2")
    const = g["nodes"][c2["link"][0]]
    assert const["type"] == "ShaderNodeValue" and const["outputs"][0]["value"] == 0.5, const
    ramp_node = g["nodes"][inp(mix, "Color1")["link"][0]]
    assert ramp_node["type"] == "ShaderNodeValToRGB"
    assert g["nodes"][inp(ramp_node, "Fac")["link"][0]]["type"] == "ShaderNodeTexNoise"
    table = ramp_node["props"]["ramp"]["table"]
    assert len(table) == 256 and abs(table[0][2] - 0.8) < 1e-6, table[0]
    curves = node_of(g, "ShaderNodeRGBCurve")["props"]["curves"]
    assert curves["range"] == [0.0, 1.0] and len(curves["tables"]) == 3
    assert abs(curves["tables"][0][204] - 1.0) < 1e-3, curves["tables"][0][204]  # C(0.8) = 1
    image = node_of(g, "ShaderNodeTexImage")["props"]["image"]
    assert image["path"] and os.path.isfile(image["path"]), image
    sphere_o = next(o for o in doc["objects"] if o["name"] == "Sphere")
    nm = doc["materials"][sphere_o["materials"][0]]["graph"]
    assert graph_types(nm) == ["ShaderNodeOutputMaterial", "ShaderNodeBsdfDiffuse"]
    assert doc["meshes"][sphere_o["mesh"]]["colors"][0]["domain"] == "CORNER"
    assert doc["lights"] and doc["lights"][0]["type"] == "POINT"
    assert "graph" in doc["world"]
    assert ex.scene_path.endswith("scene.json") and ex.argv[1] == ex.scene_path, ex.argv
    assert ex.names["material"]["NoiseRamp"] == "material 'NoiseRamp'", ex.names
    assert not warnings, warnings
    print("  default cube: %s, %.3f s" % (summary, secs))


def test_muted_and_dangling():
    """A muted node's internal link from an unlinked input gives zero (Cycles' proxy), a muted
    link leaves the input its own value."""
    reset()
    m = bpy.data.materials.new("M")
    m.use_nodes = True
    nt = m.node_tree
    bsdf = nt.nodes["Principled BSDF"]
    mix = nt.nodes.new("ShaderNodeMixRGB")
    mix.inputs["Color1"].default_value = (1, 0, 0, 1)
    mix.mute = True
    nt.links.new(mix.outputs[0], bsdf.inputs["Base Color"])
    val = nt.nodes.new("ShaderNodeValue")
    link = nt.links.new(val.outputs[0], bsdf.inputs["Roughness"])
    link.is_muted = True
    bpy.data.objects["Cube"].data.materials.clear()
    bpy.data.objects["Cube"].data.materials.append(m)
    doc, _, _, _, _ = export("muted")
    g = doc["materials"][0]["graph"]
    b = node_of(g, "ShaderNodeBsdfPrincipled")
    assert inp(b, "Base Color").get("link") is None and inp(b, "Base Color")["value"][:3] == [
        0.0, 0.0, 0.0], inp(b, "Base Color")
    assert inp(b, "Roughness").get("link") is None and abs(
        inp(b, "Roughness")["value"] - 0.5) < 1e-6
    assert graph_types(g) == ["ShaderNodeOutputMaterial", "ShaderNodeBsdfPrincipled"], \
        graph_types(g)


def test_instances():
    """Collection instances, particles and geometry-node instances hold their mesh once; a
    modified object has its own mesh; linked duplicates share one."""
    reset()
    bpy.data.objects.remove(bpy.data.objects["Cube"])
    bpy.ops.mesh.primitive_monkey_add()
    monkey = bpy.context.active_object
    col = bpy.data.collections.new("Src")
    bpy.context.scene.collection.children.link(col)
    for c in list(monkey.users_collection):
        c.objects.unlink(monkey)
    col.objects.link(monkey)
    for i in range(3):
        e = bpy.data.objects.new("Inst%d" % i, None)
        e.instance_type = 'COLLECTION'
        e.instance_collection = col
        e.location = (i * 3, 5, 0)
        bpy.context.scene.collection.objects.link(e)
    # Particles instancing the monkey.
    bpy.ops.mesh.primitive_plane_add(size=4, location=(0, -5, 0))
    emitter = bpy.context.active_object
    emitter.modifiers.new("ps", 'PARTICLE_SYSTEM')
    ps = emitter.particle_systems[0].settings
    ps.count = 20
    ps.frame_start = ps.frame_end = 1
    ps.render_type = 'OBJECT'
    ps.instance_object = monkey
    # Geometry nodes: a grid's points instance the monkey.
    bpy.ops.mesh.primitive_plane_add(size=2, location=(-5, 0, 0))
    gn_ob = bpy.context.active_object
    mod = gn_ob.modifiers.new("GN", 'NODES')
    tree = bpy.data.node_groups.new("Inst", "GeometryNodeTree")
    tree.inputs.new("NodeSocketGeometry", "Geometry")
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    gi, go = tree.nodes.new("NodeGroupInput"), tree.nodes.new("NodeGroupOutput")
    iop = tree.nodes.new("GeometryNodeInstanceOnPoints")
    info = tree.nodes.new("GeometryNodeObjectInfo")
    info.inputs["Object"].default_value = monkey
    tree.links.new(gi.outputs[0], iop.inputs["Points"])
    tree.links.new(info.outputs["Geometry"], iop.inputs["Instance"])
    tree.links.new(iop.outputs["Instances"], go.inputs[0])
    mod.node_group = tree
    # Linked duplicates, and one with a modifier.
    for i in range(4):
        d = bpy.data.objects.new("Dup%d" % i, monkey.data)
        d.location = (i * 3, -10, 0)
        bpy.context.scene.collection.objects.link(d)
    bpy.data.objects["Dup3"].modifiers.new("sub", 'SUBSURF')
    doc, summary, warnings, _, secs = export("instances")
    monkeys = [o for o in doc["objects"] if o["name"].startswith(("Suzanne", "Dup"))]
    by_mesh = {}
    for o in doc["objects"]:
        by_mesh.setdefault(o["mesh"], []).append(o["name"])
    per_mesh = {"%d:%s" % (k, doc["meshes"][k]["name"]): len(v) for k, v in by_mesh.items()}
    print("  instances: %s, %.3f s; objects per mesh: %s" % (summary, secs, per_mesh))
    # The monkey itself, 3 collection instances, 20 particles and Dup0..2 share one mesh; the 4
    # geometry-node instances share the copy geometry nodes made; Dup3 has its own (subsurf).
    counts = sorted(len(v) for v in by_mesh.values())
    assert 1 + 3 + 20 + 3 in counts and 4 in counts, by_mesh
    assert summary["meshes"] == 4, summary  # and the particle emitter
    assert len(monkeys) == 1 + 3 + 20 + 4, len(monkeys)
    inst = [o for o in doc["objects"] if "instancer" in o]
    assert len({o["random_id"] for o in inst}) == len(inst), "instance random ids repeat"


def test_motion_blur():
    reset()
    scene = bpy.context.scene
    scene.render.use_motion_blur = True
    scene.render.motion_blur_shutter = 0.5
    cube = bpy.data.objects["Cube"]
    cube.location = (0, 0, 0)
    cube.keyframe_insert("location", frame=0)
    cube.location = (2, 0, 0)
    cube.keyframe_insert("location", frame=2)
    scene.frame_set(1)
    doc, _, warnings, _, _ = export("motion")
    o = next(o for o in doc["objects"] if o["name"] == "Cube")
    assert len(o["motion"]) == 3, o.get("motion")
    xs = [m[3] for m in o["motion"]]
    assert xs[0] < xs[1] < xs[2], xs
    assert doc["render"]["motion_blur"] == {"use": True, "position": "CENTER",
                                            "shutter": 0.5}
    assert scene.frame_current == 1 and scene.frame_subframe == 0.0
    assert "motion" not in doc["camera"]  # the camera does not move
    # Shutter opening at the frame: Cycles syncs the scene at the shutter's middle.
    scene.cycles.motion_blur_position = 'START'
    scene.frame_set(1, subframe=0.25)
    x_mid = cube.evaluated_get(bpy.context.evaluated_depsgraph_get()).matrix_world[0][3]
    scene.frame_set(1)
    doc, _, _, _, _ = export("motion_start")
    o = next(o for o in doc["objects"] if o["name"] == "Cube")
    assert abs(o["matrix"][3] - x_mid) < 1e-6 and abs(o["motion"][1][3] - x_mid) < 1e-6, (
        o["matrix"][3], x_mid)
    assert scene.frame_current == 1 and scene.frame_subframe == 0.0
    assert not any("shutter curve" in w for w in warnings), warnings
    # A shaped shutter curve is warned about (glint's shutter is Cycles' default box).
    curve = scene.render.motion_blur_shutter_curve
    curve.curves[0].points[0].location = (0.0, 0.2)
    curve.update()
    _, _, warnings, _, _ = export("motion_curve")
    assert any("shutter curve" in w for w in warnings), warnings


def test_camera_and_lights():
    reset()
    scene = bpy.context.scene
    cam = scene.camera
    cam.data.dof.use_dof = True
    cam.data.dof.focus_object = bpy.data.objects["Cube"]
    cam.data.shift_x = 0.1
    cam.data.sensor_fit = 'VERTICAL'
    light = bpy.data.objects["Light"]
    light.data.cycles.cast_shadow = False
    light.visible_glossy = False
    area = bpy.data.lights.new("Portal", 'AREA')
    area.cycles.is_portal = True
    po = bpy.data.objects.new("Portal", area)
    scene.collection.objects.link(po)
    doc, _, warnings, _, _ = export("camera")
    c = doc["camera"]
    loc = np.array(cam.matrix_world.translation)
    z = np.array(cam.matrix_world.col[2][:3])
    expect = abs(np.dot(z / np.linalg.norm(z), loc - np.array(
        bpy.data.objects["Cube"].matrix_world.translation)))
    assert abs(c["dof"]["focus_distance"] - expect) < 1e-5, (c["dof"], expect)
    assert c["shift_x"] == cam.data.shift_x and c["sensor_fit"] == "VERTICAL"
    assert c["panorama_type"] == "FISHEYE_EQUISOLID"
    lights = {l["name"]: l for l in doc["lights"]}
    assert "Portal" not in lights and any("portal" in w for w in warnings), warnings
    assert lights["Light"]["cast_shadow"] is False
    assert lights["Light"]["visibility"]["glossy"] is False


def test_object_kinds():
    """Curves with a bevel, text, surfaces and metaballs become meshes (a curve instanced by a
    collection instance converted once); geometry-node materials reach their instances; a
    missing image gives one warning and no path; hair particles are warned about."""
    reset()
    bpy.ops.curve.primitive_bezier_circle_add(location=(0, 3, 0))
    circle = bpy.context.active_object
    circle.data.bevel_depth = 0.1
    circle.data.materials.append(bpy.data.materials.new("CurveMat"))
    col = bpy.data.collections.new("Curves")
    bpy.context.scene.collection.children.link(col)
    for c in list(circle.users_collection):
        c.objects.unlink(circle)
    col.objects.link(circle)
    for i in range(2):
        e = bpy.data.objects.new("CurveInst%d" % i, None)
        e.instance_type = 'COLLECTION'
        e.instance_collection = col
        e.location = (i * 3, 6, 0)
        bpy.context.scene.collection.objects.link(e)
    bpy.ops.surface.primitive_nurbs_surface_sphere_add(location=(3, 0, 0))
    bpy.ops.object.metaball_add(location=(-3, 0, 0))
    # Geometry nodes: Set Material on the cube's mesh.
    red = bpy.data.materials.new("Red")
    cube = bpy.data.objects["Cube"]
    mod = cube.modifiers.new("GN", 'NODES')
    tree = bpy.data.node_groups.new("SetMat", "GeometryNodeTree")
    tree.inputs.new("NodeSocketGeometry", "Geometry")
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    gi, go = tree.nodes.new("NodeGroupInput"), tree.nodes.new("NodeGroupOutput")
    sm = tree.nodes.new("GeometryNodeSetMaterial")
    sm.inputs["Material"].default_value = red
    tree.links.new(gi.outputs[0], sm.inputs["Geometry"])
    tree.links.new(sm.outputs[0], go.inputs[0])
    mod.node_group = tree
    # A material with a missing image, used twice.
    m = bpy.data.materials.new("Missing")
    m.use_nodes = True
    tex = m.node_tree.nodes.new("ShaderNodeTexImage")
    tex.image = bpy.data.images.new("missing.png", 4, 4)
    tex.image.source = 'FILE'
    tex.image.filepath = "/nonexistent/missing.png"
    m.node_tree.links.new(tex.outputs[0], m.node_tree.nodes["Principled BSDF"].inputs[0])
    bpy.ops.mesh.primitive_plane_add(location=(0, 0, -2))
    plane = bpy.context.active_object
    plane.data.materials.append(m)
    plane.modifiers.new("hair", 'PARTICLE_SYSTEM')
    plane.particle_systems[0].settings.type = 'HAIR'
    doc, summary, warnings, _, _ = export("kinds")
    names = [o["name"] for o in doc["objects"]]
    assert names.count("BezierCircle") == 3, names  # itself (in the scene) + 2 instances
    circles = {o["mesh"] for o in doc["objects"] if o["name"] == "BezierCircle"}
    assert len(circles) == 1, circles
    for o in doc["objects"]:
        if o["name"] == "BezierCircle":
            assert [doc["materials"][k]["name"] for k in o["materials"]] == ["CurveMat"], o
    assert "SurfSphere" in names and "Mball" in names, names
    c = next(o for o in doc["objects"] if o["name"] == "Cube")
    slot = int(read_view("kinds", doc["meshes"][c["mesh"]]["material_index"])[0])
    assert doc["materials"][c["materials"][slot]]["name"] == "Red", (c["materials"], slot)
    img = next(n for n in doc["materials"][next(
        i for i, mm in enumerate(doc["materials"]) if mm["name"] == "Missing")]["graph"]["nodes"]
        if n["type"] == "ShaderNodeTexImage")["props"]["image"]
    assert "path" not in img and "missing" in img, img
    assert sum("missing.png" in w for w in warnings) == 1, warnings
    assert any("hair particles" in w for w in warnings), warnings


def test_left_out():
    reset()
    bpy.ops.object.volume_add()
    doc, _, warnings, _, _ = export("left_out")
    assert any("volume objects" in w for w in warnings), warnings


def test_smoke_domain():
    """A Quick Smoke domain is a volume object over its texture space with its frame's grids
    in an OpenVDB file (density at the domain's resolution, heat at the base one); before the
    simulation has data it is left out with a warning, never drawn as a box of uniform
    density."""
    def quick_smoke():
        reset()
        cube = bpy.data.objects["Cube"]
        bpy.context.view_layer.objects.active = cube
        cube.select_set(True)
        bpy.ops.object.quick_smoke()
        return cube, bpy.context.active_object

    reset()  # a gas domain with no flow: its grids are empty
    domain = bpy.data.objects["Cube"]
    domain.modifiers.new("Fluid", "FLUID").fluid_type = "DOMAIN"
    doc, _, warnings, _, _ = export("smoke_empty")
    assert any("has no smoke at frame 1" in w for w in warnings), warnings
    assert not any(o["name"] == domain.name for o in doc["objects"]), doc["objects"]
    cube, domain = quick_smoke()
    for frame in range(1, 6):  # the replay cache simulates frame by frame
        bpy.context.scene.frame_set(frame)
    doc, _, warnings, _, _ = export("smoke")
    assert not warnings, warnings
    entry = next(o for o in doc["objects"] if o["name"] == domain.name)
    assert entry["volume"]["space"] == "WORLD", entry["volume"]
    path = os.path.join(TMP, "smoke", entry["volume"]["file"])
    import pyopenvdb
    grids = {g.name: g for g in pyopenvdb.readAll(path)[0]}
    ev = domain.evaluated_get(bpy.context.evaluated_depsgraph_get())
    res = tuple(next(m for m in ev.modifiers if m.type == "FLUID").domain_settings
                .domain_resolution)
    assert {"density", "heat", "color"} <= set(grids), sorted(grids)
    density = grids["density"]
    assert density.activeVoxelCount() > 0
    # Voxel (0, 0, 0) starts at the texture space's corner; (res) ends at the far one.
    lo = [a - b for a, b in zip(domain.data.texspace_location, domain.data.texspace_size)]
    hi = [a + b for a, b in zip(domain.data.texspace_location, domain.data.texspace_size)]
    assert all(abs(a - b) < 1e-5 for a, b in zip(density.transform.indexToWorld((0, 0, 0)), lo))
    assert all(abs(a - b) < 1e-5 for a, b in zip(density.transform.indexToWorld(res), hi))
    vmin, vmax = density.evalActiveVoxelBoundingBox()
    assert all(0 <= v < r for v, r in zip(vmin + vmax, res + res)), (vmin, vmax, res)


# ----------------------------------------------------------------------------- timing


def cycles_render_seconds(label):
    """Seconds of a Cycles render of the scene at 1 sample, 8 x 8 pixels: Cycles' sync of the
    Blender data, its device update (BVH build) and one sample. (Cycles' own sync time alone is
    printed by `blender -b f.blend -E CYCLES --debug-cycles -f 1`: "Total time spent
    synchronizing data".)"""
    scene = bpy.context.scene
    scene.render.engine = 'CYCLES'
    scene.cycles.samples = 1
    scene.cycles.use_denoising = False
    scene.render.resolution_x = scene.render.resolution_y = 8
    scene.render.resolution_percentage = 100
    t0 = time.perf_counter()
    bpy.ops.render.render()
    total = time.perf_counter() - t0
    print("  cycles (%s): 1-sample render %.3f s" % (label, total))
    return total


def test_timing_grid():
    reset()
    bpy.data.objects.remove(bpy.data.objects["Cube"])
    bpy.ops.mesh.primitive_grid_add(x_subdivisions=1001, y_subdivisions=501, size=10)
    grid = bpy.context.active_object
    bpy.ops.object.shade_smooth()
    grid.data.uv_layers.new(name="UVMap") if not grid.data.uv_layers else None
    me = grid.data
    me.calc_loop_triangles()
    print("  grid: %d triangles" % len(me.loop_triangles))
    export("grid")  # warm-up (first calls into the evaluated mesh)
    times = []
    for _ in range(3):
        doc, summary, _, _, secs = export("grid")
        times.append(secs)
    print("  grid export: %s; %s s (best %.3f s)" % (summary, ", ".join(
        "%.3f" % t for t in times), min(times)))
    assert min(times) < cycles_render_seconds("grid"), "slower than Cycles' whole render"


def test_timing_suzannes():
    reset()
    bpy.data.objects.remove(bpy.data.objects["Cube"])
    bpy.ops.mesh.primitive_monkey_add()
    monkey = bpy.context.active_object
    mod = monkey.modifiers.new("sub", 'SUBSURF')
    mod.levels = mod.render_levels = 2
    bpy.ops.object.modifier_apply(modifier="sub")
    monkey.data.calc_loop_triangles()
    ntri = len(monkey.data.loop_triangles)
    coll = bpy.context.scene.collection
    for i in range(10000):
        d = bpy.data.objects.new("Suzanne.%05d" % i, monkey.data)  # Alt-D: linked copy
        d.location = ((i % 100) * 3.0, (i // 100) * 3.0, 0.0)
        coll.objects.link(d)
    times = []
    for _ in range(2):
        doc, summary, _, _, secs = export("suzannes")
        times.append(secs)
    print("  10,000 linked Suzannes (%d triangles each): %s; %s s" % (
        ntri, summary, ", ".join("%.3f" % t for t in times)))
    assert summary["meshes"] == 1 and summary["objects"] == 10001, summary
    assert ntri == 15744, ntri
    assert min(times) < 2.0, times
    cycles_render_seconds("suzannes")


TESTS = [test_default_cube, test_muted_and_dangling, test_instances, test_motion_blur,
         test_camera_and_lights, test_object_kinds, test_left_out,
         test_smoke_domain]
TIMING = [test_timing_grid, test_timing_suzannes]


def main():
    only = []
    if "--only" in ARGS:
        only = [a for a in ARGS[ARGS.index("--only") + 1:] if not a.startswith("--")]
    tests = TESTS + (TIMING if "--timing" in ARGS else [])
    if only:
        tests = [t for t in TESTS + TIMING if any(o in t.__name__ for o in only)]
    failed = 0
    for t in tests:
        print(t.__name__)
        try:
            t()
        except Exception:
            traceback.print_exc()
            failed += 1
    print("%d of %d tests failed (exports in %s)" % (failed, len(tests), TMP))
    if not KEEP and not failed:
        shutil.rmtree(TMP, ignore_errors=True)
    sys.exit(1 if failed else 0)


main()
