"""Builds glint's Cycles cross-check scenes in Blender 3.4, exports them, renders references.

    blender -b --factory-startup --python tests/cycles/make_scenes.py -- \
        --out tests/cycles/scenes [--references --spp 256 --seeds 16 --ref tests/cycles/ref]

For each scene (cornell, spheres, hdr) this writes, under --out:
    NAME.obj, NAME.mtl   Blender's OBJ exporter (wm.obj_export, PBR extensions on)
    NAME.pov             the glint scene: camera, `obj_file { "NAME.obj" }`, world
With --references it also renders the scene with Cycles --seeds times at --spp samples with
seeds 1..K and writes, under --ref (half-float OpenEXR):
    NAME_mean.exr        mean of the K images (a reference at K x spp samples)
    NAME_stderr.exr      per-pixel standard error of that mean: sqrt(sample variance / K)
The CTest (tests/cycles/CMakeLists.txt) renders glint at spp samples and applies a per-pixel
Z-test against these. render_cycles.py imports this file to rebuild a scene for `glint report`.

Axes. Blender is right-handed with Z up. The OBJ export uses forward -Z, up Y, so an OBJ vertex
is (bx, bz, -by); glint's obj_file mirrors z into POV-Ray's left-handed axes, so a Blender point
lands at POV (bx, bz, by): a swap of y and z, which is exactly a change of handedness. The
camera is written in the same POV coordinates: location, look_at = location + forward, sky =
the camera's up, right = x * W/H (the usual left-handed POV camera), and `angle` = the
horizontal field of view that camera.calc_matrix_camera() gives (sensor fit included).

Cycles settings (VALIDATION.md): CPU, no denoising, no adaptive sampling, dither 0, a 1-pixel
box pixel filter (uniform jitter inside the pixel, as glint's path driver), no clamping, no
glossy blur, caustics on, light threshold 0, path guiding off, Standard view transform, linear
float EXR. Bounces: Cycles' max_bounces 0 is direct light only, glint's --max-depth 1 is; so
Cycles gets max_depth - 1 for every bounce kind.
"""

import argparse
import math
import os
import sys

import bpy
from mathutils import Vector

W, H = 128, 96
MAX_DEPTH = 8  # glint --max-depth; Cycles gets MAX_DEPTH - 1 bounces
HERE = os.path.dirname(os.path.abspath(__file__))


# ----------------------------------------------------------------------------- helpers

def reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def to_pov(v):
    """Blender world point/direction -> glint POV coordinates (see the module doc)."""
    return (v[0], v[2], v[1])


def fmt(v):
    return "<%.6f, %.6f, %.6f>" % tuple(v)


def diffuse_material(name, color):
    """A pure Lambert surface: Cycles' Diffuse BSDF (roughness 0). The OBJ exporter finds no
    Principled node and writes the material's viewport values: Kd = diffuse_color, Ks =
    specular_intensity (0: no glossy lobe in glint either), Ns from roughness."""
    m = bpy.data.materials.new(name)
    m.diffuse_color = (*color, 1.0)
    m.specular_intensity = 0.0
    m.roughness = 1.0
    m.metallic = 0.0
    m.use_nodes = True
    nt = m.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    d = nt.nodes.new("ShaderNodeBsdfDiffuse")
    d.inputs["Color"].default_value = (*color, 1.0)
    d.inputs["Roughness"].default_value = 0.0
    nt.links.new(d.outputs["BSDF"], out.inputs["Surface"])
    return m


def principled_material(name, base=(0.8, 0.8, 0.8), metallic=0.0, roughness=0.5, specular=0.5,
                        transmission=0.0, ior=1.45, emission=None, strength=1.0):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nt = m.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    p = nt.nodes.new("ShaderNodeBsdfPrincipled")
    p.distribution = "GGX"
    i = p.inputs
    i["Base Color"].default_value = (*base, 1.0)
    i["Metallic"].default_value = metallic
    i["Roughness"].default_value = roughness
    i["Specular"].default_value = specular
    i["Specular Tint"].default_value = 0.0
    i["Sheen"].default_value = 0.0
    i["Clearcoat"].default_value = 0.0
    i["Transmission"].default_value = transmission
    i["Transmission Roughness"].default_value = 0.0
    i["IOR"].default_value = ior
    if emission is not None:
        i["Emission"].default_value = (*emission, 1.0)
        i["Emission Strength"].default_value = strength
    else:
        i["Emission"].default_value = (0.0, 0.0, 0.0, 1.0)
    nt.links.new(p.outputs["BSDF"], out.inputs["Surface"])
    m.diffuse_color = (*base, 1.0)
    return m


def emitter_material(name, color, strength):
    """Emission only: black base, no specular (Cycles and glint then see just the emission)."""
    return principled_material(name, base=(0, 0, 0), roughness=1.0, specular=0.0,
                               emission=color, strength=strength)


def add_mesh(name, verts, faces, material, smooth=False):
    me = bpy.data.meshes.new(name)
    me.from_pydata(verts, [], faces)
    me.update()
    for poly in me.polygons:
        poly.use_smooth = smooth
    me.materials.append(material)
    ob = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(ob)
    return ob


def add_quad(name, center, size_x, size_y, material, z_normal_down=True):
    """A horizontal rectangle at `center` (Blender coordinates)."""
    cx, cy, cz = center
    hx, hy = size_x / 2, size_y / 2
    v = [(cx - hx, cy - hy, cz), (cx + hx, cy - hy, cz), (cx + hx, cy + hy, cz),
         (cx - hx, cy + hy, cz)]
    f = [(0, 3, 2, 1)] if z_normal_down else [(0, 1, 2, 3)]
    return add_mesh(name, v, f, material)


def add_box(name, center, size, angle_deg, material):
    """An axis-aligned box rotated about Z by angle_deg, standing on z = center.z - size.z/2."""
    cx, cy, cz = center
    sx, sy, sz = (s / 2 for s in size)
    a = math.radians(angle_deg)
    ca, sa = math.cos(a), math.sin(a)
    verts = []
    for z in (-sz, sz):
        for x, y in ((-sx, -sy), (sx, -sy), (sx, sy), (-sx, sy)):
            verts.append((cx + ca * x - sa * y, cy + sa * x + ca * y, cz + z))
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    return add_mesh(name, verts, faces, material)


def add_camera(location, look_at, lens_mm=35.0):
    cam = bpy.data.cameras.new("Camera")
    cam.lens = lens_mm
    cam.sensor_fit = "AUTO"
    ob = bpy.data.objects.new("Camera", cam)
    bpy.context.scene.collection.objects.link(ob)
    ob.location = location
    d = Vector(look_at) - Vector(location)
    ob.rotation_euler = d.to_track_quat("-Z", "Y").to_euler()
    bpy.context.scene.camera = ob
    return ob


def set_world_color(color):
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    bg.inputs["Color"].default_value = (*color, 1.0)
    bg.inputs["Strength"].default_value = 1.0
    bpy.context.scene.world = world


# ----------------------------------------------------------------------------- scenes

def build_cornell():
    white = diffuse_material("white", (0.73, 0.73, 0.73))
    red = diffuse_material("red", (0.63, 0.065, 0.05))
    green = diffuse_material("green", (0.14, 0.45, 0.091))
    light = emitter_material("light", (1.0, 0.85, 0.6), 17.0)
    s = 1.0  # half size: the room spans x, y in [-1, 1], z in [0, 2]
    add_mesh("floor", [(-s, -s, 0), (s, -s, 0), (s, s, 0), (-s, s, 0)], [(0, 1, 2, 3)], white)
    add_mesh("ceiling", [(-s, -s, 2), (s, -s, 2), (s, s, 2), (-s, s, 2)], [(0, 3, 2, 1)], white)
    add_mesh("back", [(-s, s, 0), (s, s, 0), (s, s, 2), (-s, s, 2)], [(0, 1, 2, 3)], white)
    add_mesh("left", [(-s, -s, 0), (-s, s, 0), (-s, s, 2), (-s, -s, 2)], [(0, 1, 2, 3)], red)
    add_mesh("right", [(s, -s, 0), (s, -s, 2), (s, s, 2), (s, s, 0)], [(0, 1, 2, 3)], green)
    add_quad("light", (0, 0, 1.98), 0.5, 0.4, light)
    add_box("tall_box", (-0.33, 0.3, 0.6), (0.6, 0.6, 1.2), 17, white)
    add_box("short_box", (0.35, -0.3, 0.3), (0.6, 0.6, 0.6), -17, white)
    add_camera((0, -3.9, 1.0), (0, 0, 1.0), lens_mm=35.0)
    set_world_color((0, 0, 0))
    return {"world": ("color", (0, 0, 0))}


def build_spheres():
    floor = diffuse_material("floor", (0.5, 0.5, 0.5))
    add_mesh("floor", [(-6, -4, 0), (6, -4, 0), (6, 6, 0), (-6, 6, 0)], [(0, 1, 2, 3)], floor)
    mats = []
    for r in (1.0, 0.5, 0.2, 0.05):
        mats.append(principled_material("metal_r%03d" % int(r * 100), base=(0.95, 0.64, 0.54),
                                        metallic=1.0, roughness=r))
    mats.append(principled_material("glass", base=(1, 1, 1), roughness=0.0, transmission=1.0,
                                    ior=1.45))
    mats.append(principled_material("plastic", base=(0.1, 0.2, 0.6), roughness=0.3,
                                    specular=0.5))
    radius = 0.45
    for k, m in enumerate(mats):
        x = (k - (len(mats) - 1) / 2) * 1.05
        bpy.ops.mesh.primitive_uv_sphere_add(segments=40, ring_count=20, radius=radius,
                                             location=(x, 0, radius))
        ob = bpy.context.active_object
        ob.name = "sphere_" + m.name
        bpy.ops.object.shade_smooth()
        ob.data.materials.append(m)
    light = emitter_material("light", (1.0, 1.0, 1.0), 6.0)
    add_quad("light", (-1.0, -1.5, 3.0), 2.0, 1.0, light)
    add_camera((0, -5.6, 1.7), (0, 0, 0.45), lens_mm=35.0)
    set_world_color((0.25, 0.3, 0.4))
    return {"world": ("color", (0.25, 0.3, 0.4))}


SKY_W, SKY_H = 256, 128
SUN_DIR = (-0.55, -0.45, 0.70)  # Blender world direction towards the sun (normalized below)
SUN_RADIUS_DEG = 5.0


def make_sky(path):
    """The HDR environment: an equirectangular 256x128 image in Blender's convention (u = 0.5 -
    atan2(y, x) / 2pi, v = 0.5 + asin(z) / pi, row 0 at the bottom as bpy stores pixels): a sky
    from a blue zenith to a pale horizon, a dim ground below, and a sun whose radiance falls off
    smoothly (a cosine bump of SUN_RADIUS_DEG) so that texel-centre conventions barely matter."""
    import numpy as np
    u = (np.arange(SKY_W) + 0.5) / SKY_W
    v = (np.arange(SKY_H) + 0.5) / SKY_H
    uu, vv = np.meshgrid(u, v)
    phi = (0.5 - uu) * 2 * np.pi
    elev = (vv - 0.5) * np.pi
    d = np.stack([np.cos(elev) * np.cos(phi), np.cos(elev) * np.sin(phi), np.sin(elev)], -1)
    t = np.clip(d[..., 2], 0, 1)[..., None]
    zenith = np.array([0.25, 0.45, 1.0])
    horizon = np.array([1.1, 1.1, 1.2])
    ground = np.array([0.25, 0.22, 0.2])
    sky = horizon + (zenith - horizon) * np.sqrt(t)
    rgb = np.where(d[..., 2:3] >= 0, sky, ground)
    s = np.array(SUN_DIR) / np.linalg.norm(SUN_DIR)
    ang = np.degrees(np.arccos(np.clip(d @ s, -1, 1)))
    bump = np.where(ang < SUN_RADIUS_DEG, 0.5 + 0.5 * np.cos(np.pi * ang / SUN_RADIUS_DEG), 0)
    rgb = rgb + bump[..., None] * np.array([60.0, 55.0, 45.0])
    save_pixels(path, rgb, half=True)


def build_hdr(out_dir):
    sky = os.path.join(out_dir, "sky.exr")
    if not os.path.exists(sky):
        make_sky(sky)
    floor = diffuse_material("floor", (0.6, 0.6, 0.6))
    add_mesh("floor", [(-5, -5, 0), (5, -5, 0), (5, 5, 0), (-5, 5, 0)], [(0, 1, 2, 3)], floor)
    bpy.ops.mesh.primitive_monkey_add(size=1.2, location=(-0.7, 0, 0.62),
                                      rotation=(math.radians(-20), 0, math.radians(-15)))
    monkey = bpy.context.active_object
    monkey.name = "suzanne"
    bpy.ops.object.shade_smooth()
    # One level of subdivision at render time (the export applies it, DAG_EVAL_RENDER): the
    # raw 500-face Suzanne's shading normals stray so far from its facets that glint (light
    # only from the geometric normal's side) and Cycles (shading normal's side) differ there.
    sub = monkey.modifiers.new("subdivision", "SUBSURF")
    sub.levels = 0
    sub.render_levels = 1
    monkey.data.materials.append(diffuse_material("clay", (0.8, 0.45, 0.3)))
    bpy.ops.mesh.primitive_torus_add(major_radius=0.5, minor_radius=0.18, major_segments=40,
                                     minor_segments=16, location=(0.75, 0.1, 0.68),
                                     rotation=(math.radians(80), 0, math.radians(20)))
    torus = bpy.context.active_object
    torus.name = "torus"
    bpy.ops.object.shade_smooth()
    torus.data.materials.append(principled_material("gold", base=(1.0, 0.78, 0.34),
                                                    metallic=1.0, roughness=0.25))
    add_camera((0.3, -4.2, 1.5), (0, 0, 0.6), lens_mm=38.0)
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    nt = world.node_tree
    env = nt.nodes.new("ShaderNodeTexEnvironment")
    env.image = bpy.data.images.load(sky)
    env.interpolation = "Linear"
    env.projection = "EQUIRECTANGULAR"
    nt.links.new(env.outputs["Color"], nt.nodes["Background"].inputs["Color"])
    nt.nodes["Background"].inputs["Strength"].default_value = 1.0
    bpy.context.scene.world = world
    # glint's map_type 1 reads u = atan2(q.z, q.x) / 2pi (render/lights/environment.h);
    # Blender's u is 0.5 - atan2(b.y, b.x) / 2pi = 0.5 - atan2(p.z, p.x) / 2pi for the glint
    # point p = (b.x, b.z, b.y). With q = (-p.x, p.y, p.z) the two agree, so the sky is
    # mirrored in x. v = 0.5 + asin(up) / pi in both, top row up.
    return {"world": ("text", "background { color rgb 0 }\n"
                      "sky_sphere {\n  pigment { image_map { exr \"sky.exr\" map_type 1 "
                      "interpolate 2 } }\n  scale <-1, 1, 1>\n  emission 1\n}\n")}


BUILDERS = {"cornell": build_cornell, "spheres": build_spheres, "hdr": build_hdr}


def build(name, out_dir=os.path.join(HERE, "scenes")):
    reset()
    world = BUILDERS[name](out_dir) if name == "hdr" else BUILDERS[name]()
    setup_render(bpy.context.scene, spp=16, seed=1)
    return world


# ----------------------------------------------------------------------------- rendering

def setup_render(scene, spp, seed, max_depth=MAX_DEPTH, threads=0):
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.seed = seed
    c.use_animated_seed = False
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    bounces = max(0, max_depth - 1)
    c.max_bounces = bounces
    c.diffuse_bounces = bounces
    c.glossy_bounces = bounces
    c.transmission_bounces = bounces
    c.volume_bounces = 0
    c.transparent_max_bounces = bounces
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.blur_glossy = 0.0
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.light_sampling_threshold = 0.0
    if hasattr(c, "use_guiding"):
        c.use_guiding = False
    r = scene.render
    r.resolution_x, r.resolution_y, r.resolution_percentage = W, H, 100
    r.dither_intensity = 0.0
    r.film_transparent = False
    r.use_persistent_data = False
    if threads > 0:
        r.threads_mode = "FIXED"
        r.threads = threads
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    s = r.image_settings
    s.file_format = "OPEN_EXR"
    s.color_mode = "RGB"
    s.color_depth = "32"
    s.exr_codec = "ZIP"


def render_to(path, spp, seed, threads=0):
    scene = bpy.context.scene
    setup_render(scene, spp, seed, threads=threads)
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)


def load_pixels(path):
    import numpy as np
    img = bpy.data.images.load(path, check_existing=False)
    a = np.empty(img.size[0] * img.size[1] * img.channels, dtype=np.float32)
    img.pixels.foreach_get(a)
    a = a.reshape(img.size[1], img.size[0], img.channels)[:, :, :3].astype(np.float64)
    bpy.data.images.remove(img)
    return a


def save_pixels(path, rgb, half=True):
    """rgb: (H, W, 3) in Blender's bottom-up row order, saved as linear OpenEXR."""
    import numpy as np
    h, w, _ = rgb.shape
    img = bpy.data.images.new("out", w, h, alpha=True, float_buffer=True)
    rgba = np.ones((h, w, 4), dtype=np.float32)
    rgba[:, :, :3] = rgb
    img.pixels.foreach_set(rgba.ravel())
    img.filepath_raw = path
    img.file_format = "OPEN_EXR"
    scene = bpy.context.scene
    s = scene.render.image_settings
    s.file_format = "OPEN_EXR"
    s.color_mode = "RGB"
    s.color_depth = "16" if half else "32"
    s.exr_codec = "ZIP"
    img.save_render(path, scene=scene)
    bpy.data.images.remove(img)


def render_references(name, ref_dir, spp, seeds, tmp_dir):
    import numpy as np
    images = []
    for k in range(1, seeds + 1):
        path = os.path.join(tmp_dir, "%s_seed%02d.exr" % (name, k))
        render_to(path, spp, k)
        images.append(load_pixels(path))
    stack = np.stack(images)
    mean = stack.mean(axis=0)
    var_of_mean = stack.var(axis=0, ddof=1) / seeds
    os.makedirs(ref_dir, exist_ok=True)
    save_pixels(os.path.join(ref_dir, name + "_mean.exr"), mean)
    save_pixels(os.path.join(ref_dir, name + "_stderr.exr"), np.sqrt(var_of_mean))
    print("reference %s: %d x %d spp, mean %.4f, median stderr %.5f" %
          (name, seeds, spp, mean.mean(), float(np.median(np.sqrt(var_of_mean)))))


# ----------------------------------------------------------------------------- export

def export_obj(path):
    # Faces as Blender holds them, not triangulated: the exporter's triangulation cuts quads on
    # their shorter diagonal, while Cycles renders Blender's own cut (0-2 unless the quad is
    # concave there), which glint's OBJ importer makes too. On smooth-shaded quads the cut
    # decides how normals interpolate (the torus and Suzanne of `hdr` showed it).
    bpy.ops.wm.obj_export(filepath=path, export_eval_mode="DAG_EVAL_RENDER",
                          apply_modifiers=True, forward_axis="NEGATIVE_Z", up_axis="Y",
                          export_selected_objects=False, export_uv=False, export_normals=True,
                          export_materials=True, export_pbr_extensions=True,
                          path_mode="RELATIVE", export_triangulated_mesh=False,
                          export_object_groups=False, export_smooth_groups=False)


def camera_pov():
    scene = bpy.context.scene
    cam = scene.camera
    depsgraph = bpy.context.evaluated_depsgraph_get()
    proj = cam.calc_matrix_camera(depsgraph, x=W, y=H, scale_x=1.0, scale_y=1.0)
    hfov = math.degrees(2.0 * math.atan(1.0 / proj[0][0]))
    m = cam.matrix_world
    loc = m.translation
    forward = (m.to_3x3() @ Vector((0, 0, -1))).normalized()
    up = (m.to_3x3() @ Vector((0, 1, 0))).normalized()
    look = loc + forward
    return ("camera {\n  perspective\n  location %s\n  sky %s\n  right x*%d/%d\n  up y\n"
            "  angle %.6f\n  look_at %s\n}\n" % (fmt(to_pov(loc)), fmt(to_pov(up)), W, H, hfov,
                                              fmt(to_pov(look))))


def write_pov(name, out_dir, world):
    lines = ["// glint scene written by tests/cycles/make_scenes.py (Blender %s): do not edit.\n"
             % bpy.app.version_string,
             "// Blender (x, y, z) is POV (x, z, y) here; see make_scenes.py.\n",
             "#version 3.7;\n",
             "global_settings { assumed_gamma 1.0 }\n", camera_pov()]
    kind, value = world["world"]
    if kind == "color":
        lines.append("background { color rgb %s }\n" % fmt(value))
    else:
        lines.append(value)
    lines.append('obj_file { "%s.obj" }\n' % name)
    with open(os.path.join(out_dir, name + ".pov"), "w") as f:
        f.write("".join(lines))


def main(argv):
    ap = argparse.ArgumentParser(prog="make_scenes.py")
    ap.add_argument("--out", default=os.path.join(HERE, "scenes"))
    ap.add_argument("--scenes", default=",".join(BUILDERS))
    ap.add_argument("--references", action="store_true")
    ap.add_argument("--spp", type=int, default=256, help="samples per seed image")
    ap.add_argument("--seeds", type=int, default=16)
    ap.add_argument("--ref", default=os.path.join(HERE, "ref"))
    ap.add_argument("--tmp", default="/tmp/glint_cycles")
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    os.makedirs(args.tmp, exist_ok=True)
    for name in args.scenes.split(","):
        world = build(name, args.out)
        export_obj(os.path.join(args.out, name + ".obj"))
        write_pov(name, args.out, world)
        print("scene %s written to %s" % (name, args.out))
        if args.references:
            render_references(name, args.ref, args.spp, args.seeds, args.tmp)


if __name__ == "__main__":
    main(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])
