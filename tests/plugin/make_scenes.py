"""Builds the glint add-on's test scenes in Blender 3.4 and (optionally) their Cycles references.

    blender -b --factory-startup --python tests/plugin/make_scenes.py -- \
        --out BUILD/tests/plugin/scenes [--scenes cornell,...] \
        [--references --spp 256 --seeds 16 --ref tests/plugin/ref]

For each scene NAME (the keys of BUILDERS: cornell, principled, textured, lamps, anim, bsdfs,
attributes, displacement, multiscatter, the panoramas, film_alpha, motion, motion_camera,
msglass) this saves --out/NAME.blend (plus the generated assets it uses: texture.png, sky.exr,
referenced relatively); --scenes picks some of them. Everything is
built from code, so the files are the same from run to run; the CTests build them at test time
into the build tree (the plugin.scenes fixture), and only the references are committed.

Scenes use Blender's own lights and Principled materials (the things the add-on converts),
unlike tests/cycles, whose scenes are limited to what an OBJ/MTL carries. Geometry helpers,
Cycles settings (setup_render: max_depth 8 -> 7 Cycles bounces, box filter, no clamping...),
the HDR sky and the image I/O come from tests/cycles/make_scenes.py.

With --references every scene (every frame of anim) is rendered by Cycles --seeds times at
--spp with seeds 1..K and --ref gets NAME_mean.exr and NAME_stderr.exr (anim: anim_fN_...),
half float, as tests/cycles does. --time-file appends "NAME seconds" per seed image.
"""

import argparse
import importlib.util
import math
import os
import sys
import time
import types

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location(
    "cycles_make_scenes", os.path.join(HERE, "..", "cycles", "make_scenes.py"))
cy = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(cy)

SAMPLES = 256      # scene.glint.samples and the spp of one Cycles seed image
MAX_DEPTH = cy.MAX_DEPTH  # 8: glint --max-depth; Cycles gets 7 bounces
ANIM_FRAMES = (1, 2, 3)


# ----------------------------------------------------------------------------- helpers

def add_light(name, kind, location, rotation=(0, 0, 0), color=(1, 1, 1), energy=10.0, **kw):
    """A Blender light object; kw sets light data attributes (size, spot_size, angle...)."""
    data = bpy.data.lights.new(name, kind)
    data.color = color
    data.energy = energy
    for k, v in kw.items():
        setattr(data, k, v)
    ob = bpy.data.objects.new(name, data)
    bpy.context.scene.collection.objects.link(ob)
    ob.location = location
    ob.rotation_euler = rotation
    return ob


def aim(ob, target):
    """Turn ob so that its -Z axis points at target (lights shine along -Z)."""
    from mathutils import Vector
    d = Vector(target) - ob.location
    ob.rotation_euler = d.to_track_quat("-Z", "Y").to_euler()


def add_sphere(name, location, radius, material, segments=32, rings=16):
    bpy.ops.mesh.primitive_uv_sphere_add(segments=segments, ring_count=rings, radius=radius,
                                         location=location)
    ob = bpy.context.active_object
    ob.name = name
    bpy.ops.object.shade_smooth()
    ob.data.materials.append(material)
    return ob


def floor(material, half=5.0):
    h = half
    return cy.add_mesh("floor", [(-h, -h, 0), (h, -h, 0), (h, h, 0), (-h, h, 0)],
                       [(0, 1, 2, 3)], material)


def glint_settings(scene):
    """scene.glint per the add-on contract. Without the add-on registered the values are stored
    as the ID properties its PointerProperty will read (the enum as its index)."""
    values = {"samples": SAMPLES, "max_depth": MAX_DEPTH, "seed": 0, "threads": 0,
              "time_limit": 0.0}
    if hasattr(scene, "glint"):
        scene.glint.integrator = "PATH"
        for k, v in values.items():
            setattr(scene.glint, k, v)
    else:
        scene["glint"] = dict(values, integrator=0)


# ----------------------------------------------------------------------------- scenes

def build_cornell(out_dir):
    """tests/cycles' Cornell box, lit by an AREA light (not an emissive mesh): a 0.5 x 0.4
    rectangle under the ceiling shining down, 11 W (about the radiance of tests/cycles'
    emissive quad: L = P / (pi A))."""
    white = cy.diffuse_material("white", (0.73, 0.73, 0.73))
    red = cy.diffuse_material("red", (0.63, 0.065, 0.05))
    green = cy.diffuse_material("green", (0.14, 0.45, 0.091))
    s = 1.0
    cy.add_mesh("floor", [(-s, -s, 0), (s, -s, 0), (s, s, 0), (-s, s, 0)], [(0, 1, 2, 3)], white)
    cy.add_mesh("ceiling", [(-s, -s, 2), (s, -s, 2), (s, s, 2), (-s, s, 2)], [(0, 3, 2, 1)],
                white)
    cy.add_mesh("back", [(-s, s, 0), (s, s, 0), (s, s, 2), (-s, s, 2)], [(0, 1, 2, 3)], white)
    cy.add_mesh("left", [(-s, -s, 0), (-s, s, 0), (-s, s, 2), (-s, -s, 2)], [(0, 1, 2, 3)], red)
    cy.add_mesh("right", [(s, -s, 0), (s, -s, 2), (s, s, 2), (s, s, 0)], [(0, 1, 2, 3)], green)
    cy.add_box("tall_box", (-0.33, 0.3, 0.6), (0.6, 0.6, 1.2), 17, white)
    cy.add_box("short_box", (0.35, -0.3, 0.3), (0.6, 0.6, 0.6), -17, white)
    add_light("area", "AREA", (0, 0, 1.98), color=(1.0, 0.85, 0.6), energy=11.0,
              shape="RECTANGLE", size=0.5, size_y=0.4)
    cy.add_camera((0, -3.9, 1.0), (0, 0, 1.0), lens_mm=35.0)
    cy.set_world_color((0, 0, 0))


def build_principled(out_dir):
    """Six Principled spheres on a Lambert floor: rough metal, smooth metal, a dielectric
    (plastic), glass IOR 1.45, an emitter and one with Alpha 0.5; a tilted square area light and
    a world color."""
    floor(cy.diffuse_material("floor", (0.5, 0.5, 0.5)))
    mats = [
        cy.principled_material("metal_rough", base=(0.95, 0.64, 0.54), metallic=1.0,
                               roughness=0.5),
        cy.principled_material("metal_smooth", base=(0.9, 0.9, 0.92), metallic=1.0,
                               roughness=0.05),
        cy.principled_material("plastic", base=(0.1, 0.2, 0.6), roughness=0.3),
        cy.principled_material("glass", base=(1, 1, 1), roughness=0.0, transmission=1.0,
                               ior=1.45),
        cy.principled_material("emitter", base=(0.1, 0.1, 0.1), roughness=0.5,
                               emission=(1.0, 0.5, 0.2), strength=3.0),
        cy.principled_material("half_alpha", base=(0.2, 0.7, 0.2), roughness=0.4),
    ]
    mats[-1].node_tree.nodes["Principled BSDF"].inputs["Alpha"].default_value = 0.5
    mats[-1].blend_method = "BLEND"
    radius = 0.42
    for k, m in enumerate(mats):
        x = (k - (len(mats) - 1) / 2) * 0.95
        add_sphere("sphere_" + m.name, (x, 0, radius), radius, m)
    light = add_light("area", "AREA", (-1.0, -2.0, 3.0), energy=60.0, shape="SQUARE", size=1.5)
    aim(light, (0, 0, 0))
    cy.add_camera((0, -5.6, 1.7), (0, 0, 0.45), lens_mm=35.0)
    cy.set_world_color((0.25, 0.3, 0.4))


TEX_W, TEX_H = 64, 64


def make_texture(path):
    """A smooth 64x64 RGB texture (no sharp edges, so the texel filter matters little) that is
    different along u and v and not symmetric, so a flipped or swapped mapping shows: red grows
    with u, green with v, blue is a low-frequency wave. Saved as an 8-bit sRGB PNG."""
    import numpy as np
    u = (np.arange(TEX_W) + 0.5) / TEX_W
    v = (np.arange(TEX_H) + 0.5) / TEX_H
    uu, vv = np.meshgrid(u, v)  # row 0 is v near 0 (bpy's bottom-up order)
    r = 0.15 + 0.75 * uu
    g = 0.15 + 0.6 * vv ** 1.5
    b = 0.35 + 0.3 * np.sin(2 * np.pi * (uu + 0.3 * vv)) * np.cos(np.pi * vv)
    rgba = np.ones((TEX_H, TEX_W, 4), dtype=np.float32)
    rgba[..., 0], rgba[..., 1], rgba[..., 2] = r, g, b
    img = bpy.data.images.new("texture", TEX_W, TEX_H, alpha=False)
    img.colorspace_settings.name = "sRGB"
    # bpy pixels of a byte image are display (sRGB-encoded) values: store the intended
    # sRGB-encoded values directly, so the PNG holds round(255 * value).
    img.pixels.foreach_set(rgba.ravel())
    img.filepath_raw = path
    img.file_format = "PNG"
    img.save()
    bpy.data.images.remove(img)


def textured_material(name, image):
    m = cy.principled_material(name, base=(0.8, 0.8, 0.8), roughness=0.6, specular=0.3)
    nt = m.node_tree
    tex = nt.nodes.new("ShaderNodeTexImage")
    tex.image = image
    tex.interpolation = "Linear"
    tex.extension = "REPEAT"
    nt.links.new(tex.outputs["Color"], nt.nodes["Principled BSDF"].inputs["Base Color"])
    return m


def build_textured(out_dir):
    """A UV-mapped floor (the texture repeated twice) and a UV sphere (the texture once round)
    with the image texture, under tests/cycles' 256x128 HDR sky."""
    tex_path = os.path.join(out_dir, "texture.png")
    make_texture(tex_path)
    image = bpy.data.images.load(tex_path)
    image.filepath = "//texture.png"
    image.colorspace_settings.name = "sRGB"
    mat = textured_material("textured", image)
    h = 2.5
    me_floor = cy.add_mesh("floor", [(-h, -h, 0), (h, -h, 0), (h, h, 0), (-h, h, 0)],
                           [(0, 1, 2, 3)], mat)
    uv = me_floor.data.uv_layers.new(name="UVMap")
    for loop, (s, t) in zip(uv.data, ((0, 0), (2, 0), (2, 2), (0, 2))):
        loop.uv = (s, t)
    add_sphere("ball", (0.1, 0.2, 0.8), 0.8, mat, segments=48, rings=24)
    cy.add_camera((0.4, -4.0, 1.8), (0, 0.2, 0.6), lens_mm=35.0)
    sky_world(out_dir)


def build_lamps(out_dir):
    """A spot (45 degree cone, blend 0.3, radius 0.1), a sun (angle 2 degrees) and a point light
    (radius 0.15) on a Lambert floor, a box, a Lambert sphere and a glossy sphere; dim world."""
    floor(cy.diffuse_material("floor", (0.6, 0.6, 0.6)))
    cy.add_box("box", (-0.9, 0.4, 0.4), (0.8, 0.8, 0.8), 25, cy.diffuse_material(
        "box", (0.7, 0.3, 0.2)))
    add_sphere("ball", (0.3, -0.2, 0.5), 0.5, cy.diffuse_material("ball", (0.3, 0.5, 0.7)))
    add_sphere("gloss", (1.3, 0.6, 0.4), 0.4, cy.principled_material(
        "gloss", base=(0.8, 0.8, 0.8), metallic=1.0, roughness=0.3))
    spot = add_light("spot", "SPOT", (-1.5, -1.5, 3.0), color=(1.0, 0.9, 0.7), energy=300.0,
                     spot_size=math.radians(45.0), spot_blend=0.3, shadow_soft_size=0.1)
    aim(spot, (-0.3, 0.1, 0.0))
    sun = add_light("sun", "SUN", (0, 0, 5), color=(0.7, 0.8, 1.0), energy=1.5,
                    angle=math.radians(2.0))
    aim(sun, (0.4, 0.6, 0.0))
    sun.location = (0, 0, 5)
    add_light("point", "POINT", (1.6, -1.0, 1.5), color=(1.0, 0.6, 0.4), energy=120.0,
              shadow_soft_size=0.15)
    cy.add_camera((0.8, -5.0, 2.4), (0, 0, 0.4), lens_mm=35.0)
    cy.set_world_color((0.03, 0.03, 0.04))


def build_anim(out_dir):
    """A simple scene (floor, box, sphere, sun, world color) and a camera keyframed over frames
    1-3 (linear interpolation), moving sideways and up; each frame is its own reference."""
    floor(cy.diffuse_material("floor", (0.6, 0.6, 0.6)))
    cy.add_box("box", (-0.6, 0.3, 0.5), (1.0, 1.0, 1.0), 30, cy.diffuse_material(
        "box", (0.2, 0.4, 0.7)))
    add_sphere("ball", (0.8, -0.2, 0.5), 0.5, cy.principled_material(
        "ball", base=(0.8, 0.3, 0.2), roughness=0.4))
    sun = add_light("sun", "SUN", (0, 0, 5), energy=3.0, angle=math.radians(3.0))
    aim(sun, (-0.5, 0.8, 0.0))
    sun.location = (0, 0, 5)
    cam = cy.add_camera((-1.5, -5.0, 1.5), (0, 0, 0.5), lens_mm=35.0)
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = ANIM_FRAMES[0], ANIM_FRAMES[-1]
    from mathutils import Vector
    for frame, loc in zip(ANIM_FRAMES, ((-1.5, -5.0, 1.5), (0.0, -4.6, 2.0), (1.6, -4.2, 2.6))):
        cam.location = loc
        d = Vector((0, 0, 0.5)) - Vector(loc)
        cam.rotation_euler = d.to_track_quat("-Z", "Y").to_euler()
        cam.keyframe_insert("location", frame=frame)
        cam.keyframe_insert("rotation_euler", frame=frame)
    for fc in cam.animation_data.action.fcurves:
        for kp in fc.keyframe_points:
            kp.interpolation = "LINEAR"
    cy.set_world_color((0.3, 0.35, 0.45))


def node_material(name, kind, **inputs):
    """A material whose surface is one BSDF node of type `kind`; `inputs` sets its input
    sockets by name, and the node properties distribution and component when given."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        if n.type != "OUTPUT_MATERIAL":
            nt.nodes.remove(n)
    node = nt.nodes.new(kind)
    for key in ("distribution", "component"):
        if key in inputs:
            setattr(node, key, inputs.pop(key))
    for k, v in inputs.items():
        node.inputs[k].default_value = v
    nt.links.new(node.outputs[0], nt.nodes["Material Output"].inputs["Surface"])
    return mat


def sky_world(out_dir):
    """tests/cycles' 256x128 HDR sky (sky.exr beside the .blend) as the world."""
    sky = os.path.join(out_dir, "sky.exr")
    cy.make_sky(sky)
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    nt = world.node_tree
    env = nt.nodes.new("ShaderNodeTexEnvironment")
    env.image = bpy.data.images.load(sky)
    env.image.filepath = "//sky.exr"
    env.interpolation = "Linear"
    env.projection = "EQUIRECTANGULAR"
    nt.links.new(env.outputs["Color"], nt.nodes["Background"].inputs["Color"])
    nt.nodes["Background"].inputs["Strength"].default_value = 1.0
    bpy.context.scene.world = world


def build_bsdfs(out_dir):
    """(issue 30) Fifteen spheres, one BSDF each beyond the plain Principled: Oren-Nayar,
    Translucent, both Toons, Velvet, Glossy Beckmann and Ashikhmin-Shirley, Anisotropic GGX
    (default tangent, rotated), Refraction and Glass (Beckmann, rough, tinted), and the
    Principled BSDF's sheen, clearcoat, specular tint, anisotropy and transmission roughness;
    under tests/cycles' HDR sky and a sun, on a grey floor."""
    P = "ShaderNodeBsdfPrincipled"
    mats = [
        node_material("oren_nayar", "ShaderNodeBsdfDiffuse", Color=(0.8, 0.5, 0.3, 1),
                      Roughness=1.0),
        node_material("translucent", "ShaderNodeBsdfTranslucent", Color=(0.8, 0.8, 0.4, 1)),
        node_material("toon_diffuse", "ShaderNodeBsdfToon", Color=(0.3, 0.6, 0.9, 1),
                      Size=0.5, Smooth=0.1),
        node_material("toon_glossy", "ShaderNodeBsdfToon", component="GLOSSY",
                      Color=(0.9, 0.9, 0.9, 1), Size=0.2, Smooth=0.2),
        node_material("velvet", "ShaderNodeBsdfVelvet", Color=(0.7, 0.2, 0.4, 1), Sigma=0.5),
        node_material("beckmann", "ShaderNodeBsdfGlossy", distribution="BECKMANN",
                      Color=(0.9, 0.7, 0.4, 1), Roughness=0.3),
        node_material("ashikhmin", "ShaderNodeBsdfGlossy", distribution="ASHIKHMIN_SHIRLEY",
                      Color=(0.6, 0.8, 0.9, 1), Roughness=0.3),
        node_material("anisotropic", "ShaderNodeBsdfAnisotropic", Color=(0.9, 0.9, 0.9, 1),
                      Roughness=0.4, Anisotropy=0.8, Rotation=0.1),
        node_material("refraction", "ShaderNodeBsdfRefraction", Color=(1, 1, 1, 1),
                      Roughness=0.2, IOR=1.45),
        node_material("glass", "ShaderNodeBsdfGlass", Color=(0.6, 0.9, 0.7, 1), Roughness=0.15,
                      IOR=1.5),
        node_material("sheen", P, **{"Base Color": (0.6, 0.1, 0.1, 1), "Roughness": 0.6,
                                     "Sheen": 1.0, "Sheen Tint": 0.5}),
        node_material("clearcoat", P, **{"Base Color": (0.05, 0.1, 0.5, 1), "Roughness": 0.5,
                                         "Clearcoat": 1.0, "Clearcoat Roughness": 0.1}),
        node_material("specular_tint", P, **{"Base Color": (0.9, 0.4, 0.1, 1),
                                             "Roughness": 0.2, "Specular": 1.0,
                                             "Specular Tint": 1.0}),
        node_material("principled_aniso", P, **{"Base Color": (0.9, 0.8, 0.6, 1),
                                                "Metallic": 1.0, "Roughness": 0.3,
                                                "Anisotropic": 0.8}),
        node_material("frosted", P, **{"Base Color": (1, 1, 1, 1), "Roughness": 0.1,
                                       "Transmission": 1.0, "Transmission Roughness": 0.5}),
    ]
    floor(cy.diffuse_material("floor", (0.5, 0.5, 0.5)))
    radius = 0.4
    for k, m in enumerate(mats):
        row, col = divmod(k, 5)
        add_sphere("sphere_" + m.name, ((col - 2) * 0.95, row * 0.95 - 0.6, radius), radius, m)
    sun = add_light("sun", "SUN", (0, 0, 5), energy=2.0, angle=math.radians(3.0))
    aim(sun, (0.5, 0.7, 0.0))
    sun.location = (0, 0, 5)
    cy.add_camera((0, -5.2, 3.2), (0, 0.4, 0.3), lens_mm=35.0)
    sky_world(out_dir)


def emission_of(name, build):
    """A material whose Emission (strength 1) colour is what build(nodes, links) returns."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        if n.type != "OUTPUT_MATERIAL":
            nt.nodes.remove(n)
    em = nt.nodes.new("ShaderNodeEmission")
    nt.links.new(build(nt.nodes, nt.links), em.inputs["Color"])
    nt.links.new(em.outputs[0], nt.nodes["Material Output"].inputs["Surface"])
    return mat


def build_attributes(out_dir):
    """(issue 30) Named mesh layers through the Attribute, Color Attribute and UV Map nodes,
    shown by Emission (no lights, black world): five 6 x 6 grids, each with a byte colour
    attribute per corner (the active render one), a float colour per vertex ("Paint") and a
    second UV map ("Second", turned and scaled)."""
    import random
    rnd = random.Random(7)

    def grid(name, x, mat):
        bpy.ops.mesh.primitive_grid_add(x_subdivisions=6, y_subdivisions=6, size=1.0,
                                        location=(x, 0, 0))
        ob = bpy.context.active_object
        ob.name = name
        me = ob.data
        corner = me.color_attributes.new("Col", "BYTE_COLOR", "CORNER")
        for d in corner.data:
            d.color = (rnd.random(), rnd.random(), rnd.random(), 1.0)
        point = me.color_attributes.new("Paint", "FLOAT_COLOR", "POINT")
        for v, d in zip(me.vertices, point.data):
            d.color = (0.5 + 0.5 * v.co.x, 0.5 + 0.5 * v.co.y, 0.3, 0.25 + 0.5 * (v.co.x + 0.5))
        me.color_attributes.active_color = corner
        me.color_attributes.render_color_index = [c.name for c in me.color_attributes].index("Col")
        second = me.uv_layers.new(name="Second")
        for loop, d in zip(me.loops, second.data):
            co = me.vertices[loop.vertex_index].co
            d.uv = (0.5 + 0.9 * co.y, 0.5 - 0.9 * co.x)
        me.uv_layers["UVMap"].active_render = True
        me.materials.append(mat)

    def color_attr(nodes, links):
        return nodes.new("ShaderNodeVertexColor").outputs["Color"]

    def paint(nodes, links):
        a = nodes.new("ShaderNodeAttribute")
        a.attribute_name = "Paint"
        return a.outputs["Color"]

    def paint_alpha(nodes, links):
        a = nodes.new("ShaderNodeAttribute")
        a.attribute_name = "Paint"
        c = nodes.new("ShaderNodeCombineXYZ")
        links.new(a.outputs["Alpha"], c.inputs["X"])
        links.new(a.outputs["Fac"], c.inputs["Y"])
        return c.outputs["Vector"]

    def second_uv(nodes, links):
        uv = nodes.new("ShaderNodeUVMap")
        uv.uv_map = "Second"
        ch = nodes.new("ShaderNodeTexChecker")
        ch.inputs["Scale"].default_value = 4.0
        links.new(uv.outputs["UV"], ch.inputs["Vector"])
        return ch.outputs["Color"]

    def second_attr(nodes, links):
        a = nodes.new("ShaderNodeAttribute")
        a.attribute_name = "Second"
        return a.outputs["Vector"]

    builders = [color_attr, paint, paint_alpha, second_uv, second_attr]
    for k, b in enumerate(builders):
        grid("grid_" + b.__name__, (k - 2) * 1.1, emission_of(b.__name__, b))
    cam = cy.add_camera((0, 0, 4.0), (0, 0, 0), lens_mm=35.0)
    cam.data.type = "ORTHO"
    cam.data.ortho_scale = 5.6
    cy.set_world_color((0, 0, 0))


def emission_stage():
    """What the emission-only scenes (displacement, normal_map) see them with: an orthographic
    camera looking along +Y at the origin, 5.6 m wide, and a black world."""
    cam = cy.add_camera((0, -6.0, 0), (0, 0, 0), lens_mm=35.0)
    cam.data.type = "ORTHO"
    cam.data.ortho_scale = 5.6
    cy.set_world_color((0, 0, 0))


def bare_material(name):
    """A node material holding only its Material Output: (material, node tree, output)."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        if n.type != "OUTPUT_MATERIAL":
            nt.nodes.remove(n)
    return mat, nt, nt.nodes["Material Output"]


def build_displacement(out_dir):
    """(issue 30) Material displacement as Cycles' default "Bump Only" renders it, seen through
    Layer Weight's Facing (which reads the bent normal) into Emission, so the image is exact:
    a Noise height through Displacement in object space on a scaled sphere, the same in world
    space, and a Vector Displacement in object space; black world, orthographic camera."""
    def material(name, kind, space, scale):
        mat, nt, out = bare_material(name)
        noise = nt.nodes.new("ShaderNodeTexNoise")
        noise.inputs["Scale"].default_value = 3.0
        disp = nt.nodes.new(kind)
        disp.space = space
        disp.inputs["Scale"].default_value = scale
        if kind == "ShaderNodeDisplacement":
            nt.links.new(noise.outputs["Fac"], disp.inputs["Height"])
        else:
            nt.links.new(noise.outputs["Color"], disp.inputs["Vector"])
            disp.inputs["Midlevel"].default_value = 0.5
        nt.links.new(disp.outputs["Displacement"], out.inputs["Displacement"])
        lw = nt.nodes.new("ShaderNodeLayerWeight")
        lw.inputs["Blend"].default_value = 0.3
        em = nt.nodes.new("ShaderNodeEmission")
        nt.links.new(lw.outputs["Facing"], em.inputs["Color"])
        nt.links.new(em.outputs[0], out.inputs["Surface"])
        return mat

    specs = [("disp_object", "ShaderNodeDisplacement", "OBJECT", 0.1),
             ("disp_world", "ShaderNodeDisplacement", "WORLD", 0.1),
             ("vector_object", "ShaderNodeVectorDisplacement", "OBJECT", 0.1)]
    for k, (name, kind, space, scale) in enumerate(specs):
        ob = add_sphere("sphere_" + name, ((k - 1) * 1.8, 0, 0), 0.8,
                        material(name, kind, space, scale), segments=64, rings=32)
        if k == 0:
            ob.scale = (1.0, 1.0, 1.3)
    emission_stage()


def build_multiscatter(out_dir):
    """(issue 30) Multiscatter GGX (Cycles' random walk): a rough gold Glossy, an anisotropic
    Glossy, a rough Principled metal and a rough Principled dielectric with specular tint,
    under the HDR sky and a sun on a grey floor."""
    P = "ShaderNodeBsdfPrincipled"
    mats = [
        node_material("ms_glossy", "ShaderNodeBsdfGlossy", distribution="MULTI_GGX",
                      Color=(1.0, 0.75, 0.35, 1), Roughness=0.7),
        node_material("ms_aniso", "ShaderNodeBsdfAnisotropic", distribution="MULTI_GGX",
                      Color=(0.8, 0.85, 0.9, 1), Roughness=0.5, Anisotropy=0.6),
        node_material("ms_metal", P, distribution="MULTI_GGX",
                      **{"Base Color": (0.95, 0.6, 0.5, 1), "Metallic": 1.0, "Roughness": 0.8}),
        node_material("ms_plastic", P, distribution="MULTI_GGX",
                      **{"Base Color": (0.2, 0.5, 0.2, 1), "Roughness": 0.5,
                         "Specular Tint": 0.5}),
    ]
    floor(cy.diffuse_material("floor", (0.5, 0.5, 0.5)))
    for k, m in enumerate(mats):
        add_sphere("sphere_" + m.name, ((k - 1.5) * 1.05, 0, 0.5), 0.5, m, segments=48,
                   rings=24)
    sun = add_light("sun", "SUN", (0, 0, 5), energy=2.0, angle=math.radians(3.0))
    aim(sun, (0.5, 0.7, 0.0))
    sun.location = (0, 0, 5)
    cy.add_camera((0, -5.0, 2.0), (0, 0, 0.4), lens_mm=35.0)
    sky_world(out_dir)


def build_msglass(out_dir):
    """Multiscatter GGX glass (Cycles' dielectric random walk): Glass BSDFs of roughness 0.3
    (clear) and 0.8 (tinted), IOR 1.45, and a Principled BSDF of transmission 1, roughness 0.5
    (Cycles' glass-with-Fresnel closure), on a grey floor under a square area light and a world
    colour."""
    mats = [
        node_material("msg_clear", "ShaderNodeBsdfGlass", distribution="MULTI_GGX",
                      Color=(1.0, 1.0, 1.0, 1), Roughness=0.3, IOR=1.45),
        node_material("msg_tinted", "ShaderNodeBsdfGlass", distribution="MULTI_GGX",
                      Color=(0.55, 0.8, 1.0, 1), Roughness=0.8, IOR=1.45),
        node_material("msg_principled", "ShaderNodeBsdfPrincipled", distribution="MULTI_GGX",
                      **{"Base Color": (1.0, 0.85, 0.6, 1), "Transmission": 1.0,
                         "Roughness": 0.5, "IOR": 1.45, "Specular Tint": 0.5}),
    ]
    floor(cy.diffuse_material("floor", (0.5, 0.5, 0.5)))
    cy.add_box("backdrop", (0.0, 1.4, 0.5), (3.6, 0.2, 1.0), 0, cy.diffuse_material(
        "backdrop", (0.7, 0.25, 0.15)))
    for k, m in enumerate(mats):
        add_sphere("sphere_" + m.name, ((k - 1) * 1.15, 0, 0.5), 0.5, m, segments=48,
                   rings=24)
    light = add_light("area", "AREA", (-1.0, -2.0, 3.0), energy=60.0, shape="SQUARE", size=1.5)
    aim(light, (0, 0, 0))
    cy.add_camera((0, -5.0, 1.6), (0, 0, 0.45), lens_mm=35.0)
    cy.set_world_color((0.25, 0.3, 0.4))


def pano_room():
    """What the panoramic cameras look at (issue 30): a floor, coloured boxes and spheres all
    around the camera's place (ahead, to each side, behind), a sun and a world colour, so every
    part of a panorama's image shows something that moves if the projection is wrong."""
    floor(cy.diffuse_material("floor", (0.55, 0.55, 0.55)))
    cy.add_box("ahead", (0.0, 3.0, 0.6), (1.2, 1.2, 1.2), 20, cy.diffuse_material(
        "red", (0.7, 0.12, 0.08)))
    cy.add_box("left", (-3.0, 0.5, 0.9), (1.0, 1.0, 1.8), 0, cy.diffuse_material(
        "green", (0.15, 0.55, 0.12)))
    add_sphere("right", (2.6, 1.2, 0.7), 0.7, cy.principled_material(
        "blue", base=(0.1, 0.2, 0.7), roughness=0.35))
    add_sphere("behind", (-0.8, -3.0, 0.5), 0.5, cy.diffuse_material(
        "yellow", (0.8, 0.7, 0.1)))
    cy.add_box("pillar", (1.5, -2.0, 1.5), (0.4, 0.4, 3.0), 0, cy.diffuse_material(
        "white", (0.8, 0.8, 0.8)))
    sun = add_light("sun", "SUN", (0, 0, 5), energy=3.0, angle=math.radians(3.0))
    aim(sun, (-0.4, 0.6, 0.0))
    sun.location = (0, 0, 5)
    cy.set_world_color((0.3, 0.35, 0.45))


def pano_camera(location, look_at, panorama_type, **settings):
    """The scene camera made a Cycles panorama of `panorama_type` (camera.cycles in 3.4)."""
    cam = cy.add_camera(location, look_at)
    cam.data.type = "PANO"
    cam.data.cycles.panorama_type = panorama_type
    for k, v in settings.items():
        setattr(cam.data.cycles, k, v)
    return cam


def build_pano_equirect(out_dir):
    """An equirectangular panorama over part of the sphere (longitude -150..120 degrees,
    latitude -50..70), so the range's four settings all matter."""
    pano_room()
    pano_camera((0.0, 0.0, 1.2), (0.0, 1.0, 1.2), "EQUIRECTANGULAR",
                longitude_min=math.radians(-150.0), longitude_max=math.radians(120.0),
                latitude_min=math.radians(-50.0), latitude_max=math.radians(70.0))


def build_pano_fisheye(out_dir):
    """An equidistant fisheye of 200 degrees, tilted down and turned, over the same room: the
    black corners outside the image circle, and things behind the camera's plane."""
    pano_room()
    pano_camera((0.3, -0.5, 1.6), (0.2, 1.0, 0.9), "FISHEYE_EQUIDISTANT",
                fisheye_fov=math.radians(200.0))


def build_pano_equisolid(out_dir):
    """An equisolid fisheye (Blender's default 10.5 mm lens, 180 degrees) on a 36 mm sensor
    fitted to the image: the circle is cut at the top and bottom."""
    pano_room()
    cam = pano_camera((0.3, -0.5, 1.6), (0.2, 1.0, 0.9), "FISHEYE_EQUISOLID",
                      fisheye_lens=10.5, fisheye_fov=math.radians(180.0))
    cam.data.sensor_width = 36.0


def build_film_alpha(out_dir):
    """Film > Transparent with what changes alpha (issue 30): an opaque sphere, a Principled
    sphere of Alpha 0.4, a box that is a holdout object (Object > Visibility > Holdout), a
    sphere whose material mixes a Diffuse BSDF and a Holdout 50/50, and a floor strip that
    leaves the world visible above and below it. The world lights the scene but is not seen."""
    cy.add_quad("strip", (0.0, 0.5, 0.0), 6.0, 2.2, cy.diffuse_material(
        "strip", (0.6, 0.6, 0.6)), z_normal_down=False)
    add_sphere("opaque", (-1.5, 0.6, 0.5), 0.5, cy.principled_material(
        "opaque", base=(0.7, 0.25, 0.1), roughness=0.4))
    see = cy.principled_material("see_through", base=(0.1, 0.5, 0.2), roughness=0.4)
    see.node_tree.nodes["Principled BSDF"].inputs["Alpha"].default_value = 0.4
    see.blend_method = "BLEND"
    add_sphere("see_through", (-0.4, 0.2, 0.55), 0.55, see)
    held = cy.add_box("held_out", (0.75, 0.8, 0.5), (0.8, 0.8, 1.0), 25, cy.diffuse_material(
        "held_out", (0.2, 0.3, 0.8)))
    held.is_holdout = True
    half = bpy.data.materials.new("half_holdout")
    half.use_nodes = True
    nt = half.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (0.8, 0.75, 0.2, 1.0)
    hold = nt.nodes.new("ShaderNodeHoldout")
    mix = nt.nodes.new("ShaderNodeMixShader")
    mix.inputs["Fac"].default_value = 0.5
    nt.links.new(diffuse.outputs["BSDF"], mix.inputs[1])
    nt.links.new(hold.outputs["Holdout"], mix.inputs[2])
    nt.links.new(mix.outputs["Shader"], out.inputs["Surface"])
    add_sphere("half_holdout", (1.8, 0.1, 0.45), 0.45, half)
    sun = add_light("sun", "SUN", (0, 0, 5), energy=3.0, angle=math.radians(3.0))
    aim(sun, (-0.5, 0.8, 0.0))
    sun.location = (0, 0, 5)
    cy.add_camera((0.0, -5.0, 1.6), (0.0, 0.4, 0.4), lens_mm=35.0)
    cy.set_world_color((0.3, 0.35, 0.45))


# Scenes whose film is transparent: rendered and saved as RGBA, with an alpha reference.
ALPHA_SCENES = ("film_alpha", "film_glass")


def film_settings(name, scene):
    """What cy.setup_render resets and a scene needs otherwise: the transparent film, saved
    with its alpha."""
    if name in ALPHA_SCENES:
        scene.render.film_transparent = True
        scene.render.image_settings.color_mode = "RGBA"


_more_spec = importlib.util.spec_from_file_location("more_scenes",
                                                    os.path.join(HERE, "more_scenes.py"))
more = importlib.util.module_from_spec(_more_spec)
_more_spec.loader.exec_module(more)
more.ms = types.SimpleNamespace(cy=cy, add_sphere=add_sphere, floor=floor, add_light=add_light,
                                aim=aim, node_material=node_material,
                                bare_material=bare_material, emission_stage=emission_stage)

BUILDERS = {"cornell": build_cornell, "principled": build_principled,
            "textured": build_textured, "lamps": build_lamps, "anim": build_anim,
            "bsdfs": build_bsdfs, "attributes": build_attributes,
            "displacement": build_displacement, "multiscatter": build_multiscatter,
            "pano_equirect": build_pano_equirect, "pano_fisheye": build_pano_fisheye,
            "pano_equisolid": build_pano_equisolid, "film_alpha": build_film_alpha,
            "motion": more.build_motion, "motion_camera": more.build_motion_camera,
            "motion_deform": more.build_motion_deform, "normal_map": more.build_normal_map,
            "msglass": build_msglass, "film_glass": more.build_film_glass,
            "volume": more.build_volume, "volume_noise": more.build_volume_noise,
            "volume_world": more.build_volume_world,
            "world_fog": more.build_world_fog, "subsurface": more.build_subsurface,
            "vdb_volume": more.build_vdb_volume, "smoke": more.build_smoke,
            "many_lights": more.build_many_lights,
            "world_camera": more.build_world_camera}


def build(name, out_dir):
    cy.reset()
    BUILDERS[name](out_dir)
    scene = bpy.context.scene
    cy.setup_render(scene, spp=SAMPLES, seed=1)
    film_settings(name, scene)
    more.AFTER_SETUP.get(name, lambda s: None)(scene)
    if name != "anim":
        scene.frame_start = scene.frame_end = 1
    scene.frame_set(scene.frame_start)
    glint_settings(scene)
    path = os.path.join(out_dir, name + ".blend")
    bpy.ops.wm.save_as_mainfile(filepath=path, compress=False, relative_remap=True)
    return path


def frames(name):
    return ANIM_FRAMES if name == "anim" else (1,)


def ref_name(name, frame):
    return "%s_f%d" % (name, frame) if name == "anim" else name


def load_alpha(path):
    """The alpha channel of an RGBA EXR, (H, W) in Blender's bottom-up row order."""
    import numpy as np
    img = bpy.data.images.load(path, check_existing=False)
    img.colorspace_settings.name = "Non-Color"
    a = np.empty(img.size[0] * img.size[1] * img.channels, dtype=np.float32)
    img.pixels.foreach_get(a)
    a = a.reshape(img.size[1], img.size[0], img.channels)[:, :, 3].astype(np.float64)
    bpy.data.images.remove(img)
    return a


def render_references(name, ref_dir, spp, seeds, tmp_dir, threads, time_file):
    import numpy as np
    scene = bpy.context.scene
    for frame in frames(name):
        scene.frame_set(frame)
        rn = ref_name(name, frame)
        images, alphas = [], []
        for k in range(1, seeds + 1):
            path = os.path.join(tmp_dir, "%s_seed%02d.exr" % (rn, k))
            t0 = time.time()
            cy.setup_render(scene, spp, k, threads=threads)
            film_settings(name, scene)
            more.AFTER_SETUP.get(name, lambda s: None)(scene)
            scene.render.filepath = path
            bpy.ops.render.render(write_still=True)
            dt = time.time() - t0
            if time_file:
                with open(time_file, "a") as f:
                    f.write("%s %d %.3f\n" % (rn, k, dt))
            images.append(cy.load_pixels(path))
            if name in ALPHA_SCENES:
                alphas.append(load_alpha(path))
        stack = np.stack(images)
        mean = stack.mean(axis=0)
        se = np.sqrt(stack.var(axis=0, ddof=1) / seeds)
        os.makedirs(ref_dir, exist_ok=True)
        cy.save_pixels(os.path.join(ref_dir, rn + "_mean.exr"), mean)
        cy.save_pixels(os.path.join(ref_dir, rn + "_stderr.exr"), se)
        if alphas:
            # Alpha's mean and standard error, each in all three channels.
            a = np.stack(alphas)
            a_mean = np.repeat(a.mean(axis=0)[:, :, None], 3, axis=2)
            a_se = np.repeat(np.sqrt(a.var(axis=0, ddof=1) / seeds)[:, :, None], 3, axis=2)
            cy.save_pixels(os.path.join(ref_dir, rn + "_alpha_mean.exr"), a_mean)
            cy.save_pixels(os.path.join(ref_dir, rn + "_alpha_stderr.exr"), a_se)
        print("reference %s: %d x %d spp, mean %.4f, median stderr %.5f" %
              (rn, seeds, spp, mean.mean(), float(np.median(se))), flush=True)


def main(argv):
    ap = argparse.ArgumentParser(prog="make_scenes.py")
    ap.add_argument("--out", required=True)
    ap.add_argument("--scenes", default=",".join(BUILDERS))
    ap.add_argument("--references", action="store_true")
    ap.add_argument("--spp", type=int, default=SAMPLES)
    ap.add_argument("--seeds", type=int, default=16)
    ap.add_argument("--ref", default=os.path.join(HERE, "ref"))
    ap.add_argument("--tmp", default="/tmp/glint_plugin_refs")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--time-file", default="")
    ap.add_argument("--timing", action="store_true",
                    help="only time one Cycles render (seed 101) per scene and frame at --spp "
                         "and --threads, appended to --time-file, the image saved as "
                         "--tmp/NAME.exr; no references written")
    args = ap.parse_args(argv)
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    os.makedirs(args.tmp, exist_ok=True)
    for name in args.scenes.split(","):
        path = build(name, out)
        print("scene %s saved to %s" % (name, path), flush=True)
        if args.timing:
            bpy.ops.wm.open_mainfile(filepath=path)
            for frame in frames(name):
                bpy.context.scene.frame_set(frame)
                t0, c0 = time.time(), time.process_time()
                cy.render_to(os.path.join(args.tmp, ref_name(name, frame) + ".exr"), args.spp,
                             101, threads=args.threads)
                # wall seconds, then CPU seconds of all threads (steadier on a busy machine)
                line = "%s %.3f %.3f" % (ref_name(name, frame), time.time() - t0,
                                         time.process_time() - c0)
                print("cycles time: " + line, flush=True)
                if args.time_file:
                    with open(args.time_file, "a") as f:
                        f.write(line + "\n")
        elif args.references:
            bpy.ops.wm.open_mainfile(filepath=path)
            render_references(name, args.ref, args.spp, args.seeds, args.tmp, args.threads,
                              args.time_file)


if __name__ == "__main__":
    main(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
