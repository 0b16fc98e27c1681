"""Everyday scenes made from scratch in Blender, rendered by Cycles and by glint, compared.

Each scene starts from Blender's default startup scene (cube, light, camera) and is built the
way a user builds it in the UI. For each scene the script

  1. renders Cycles twice (seeds 1 and 2: their difference is the noise floor),
  2. exports the frame with glint_blender.native_export.export_frame_native and runs the
     exported command line with glint,
  3. computes SSIM of glint vs Cycles seed 1 and of Cycles seed 2 vs Cycles seed 1,
  4. writes docs/images/everyday_<scene>.png (glint left, Cycles seed 1 right),

then prints a Markdown table (also written to <work dir>/results.md). SSIM is a Gaussian-window
SSIM (sigma 1.5, 11x11, C1 = 0.01^2, C2 = 0.03^2) on the luma of the sRGB-encoded image
(Rec. 709 weights on the encoded, [0, 1]-clipped values), as the Standard view shows it.

Run (from the repository root; 200x150, 64 spp, takes a few minutes on two cores):

    blender -b --factory-startup --python docs/images/everyday.py -- /tmp/everyday

optionally followed by a comma-separated list of scenes (default: all). GLINT=/path/to/glint
picks the binary (default: build/glint).
"""

import math
import os
import re
import subprocess
import sys
import time

import bpy
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "plugin", "blender"))
from glint_blender import native_export  # noqa: E402

ARGS = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = ARGS[0] if ARGS else "/tmp/everyday"
GLINT = os.environ.get("GLINT", os.path.join(ROOT, "build", "glint"))
W, H = 200, 150
SPP = 64
PASS_MARGIN = 0.03


# ----------------------------------------------------------------------------- scene helpers

def base():
    """Blender's default startup scene with the comparison's render settings."""
    bpy.ops.wm.read_factory_settings(use_empty=False)
    s = bpy.context.scene
    s.render.engine = 'CYCLES'
    s.cycles.device = 'CPU'
    s.cycles.samples = SPP
    s.cycles.use_denoising = False
    s.cycles.use_adaptive_sampling = False
    s.render.resolution_x, s.render.resolution_y = W, H
    s.render.resolution_percentage = 100
    s.view_settings.view_transform = 'Standard'
    s.view_settings.look = 'None'
    s.render.image_settings.file_format = 'OPEN_EXR'
    s.render.image_settings.color_depth = '32'
    return s


def material(name, obj=None):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    if obj is not None and len(obj.data.materials):
        obj.data.materials[0] = m  # the default cube's slot holds "Material"
    elif obj is not None:
        obj.data.materials.append(m)
    return m, m.node_tree


def replace_principled(nt, node_type):
    """Swaps the new material's Principled BSDF for another shader node (as the UI does)."""
    nt.nodes.remove(nt.nodes["Principled BSDF"])
    n = nt.nodes.new(node_type)
    nt.links.new(n.outputs[0], nt.nodes["Material Output"].inputs["Surface"])
    return n


def sphere(radius=1.0, location=(0, 0, 0)):
    bpy.ops.mesh.primitive_uv_sphere_add(radius=radius, location=location, segments=64,
                                         ring_count=32)
    bpy.ops.object.shade_smooth()
    return bpy.context.active_object


def remove(name):
    bpy.data.objects.remove(bpy.data.objects[name])


# ----------------------------------------------------------------------------- the scenes

def noise_ramp():
    s = base()
    remove("Cube")
    ob = sphere(1.2)
    m, nt = material("Noisy", ob)
    pr = nt.nodes["Principled BSDF"]
    noise = nt.nodes.new("ShaderNodeTexNoise")
    noise.inputs["Scale"].default_value = 4
    ramp = nt.nodes.new("ShaderNodeValToRGB")
    ramp.color_ramp.elements[0].position = 0.4
    ramp.color_ramp.elements[0].color = (0.05, 0.1, 0.6, 1)
    ramp.color_ramp.elements[1].position = 0.6
    ramp.color_ramp.elements[1].color = (1, 0.6, 0.1, 1)
    nt.links.new(noise.outputs["Fac"], ramp.inputs["Fac"])
    nt.links.new(ramp.outputs["Color"], pr.inputs["Base Color"])
    vor = nt.nodes.new("ShaderNodeTexVoronoi")
    vor.inputs["Scale"].default_value = 8
    bump = nt.nodes.new("ShaderNodeBump")
    bump.inputs["Strength"].default_value = 0.4
    nt.links.new(vor.outputs["Distance"], bump.inputs["Height"])
    nt.links.new(bump.outputs["Normal"], pr.inputs["Normal"])
    return s


def sky():
    s = base()
    nt = s.world.node_tree
    sk = nt.nodes.new("ShaderNodeTexSky")  # Nishita, Blender's default sky type
    sk.sun_elevation = math.radians(20)
    nt.links.new(sk.outputs["Color"], nt.nodes["Background"].inputs["Color"])
    nt.nodes["Background"].inputs["Strength"].default_value = 0.15  # the sky is sunlight-bright
    remove("Light")
    bpy.data.objects["Camera"].rotation_euler = (math.radians(80), 0, math.radians(45))
    return s


def still_life():
    s = base()
    remove("Cube")
    bpy.ops.mesh.primitive_plane_add(size=20, location=(0, 0, -1))
    m, nt = material("Floor", bpy.context.active_object)
    ch = nt.nodes.new("ShaderNodeTexChecker")
    ch.inputs["Scale"].default_value = 20
    nt.links.new(ch.outputs["Color"], nt.nodes["Principled BSDF"].inputs["Base Color"])
    glass = sphere(1.0, (-1.2, 0, 0))
    m, nt = material("Glass", glass)
    replace_principled(nt, "ShaderNodeBsdfGlass")  # defaults: Beckmann, roughness 0, IOR 1.45
    metal = sphere(1.0, (1.2, 0.5, 0))
    m, nt = material("Metal", metal)
    pr = nt.nodes["Principled BSDF"]
    pr.inputs["Metallic"].default_value = 1
    pr.inputs["Roughness"].default_value = 0.2
    pr.inputs["Base Color"].default_value = (0.9, 0.6, 0.3, 1)
    cam = bpy.data.objects["Camera"].data
    cam.dof.use_dof = True
    cam.dof.focus_object = metal
    cam.dof.aperture_fstop = 1.4
    return s


def toon_fresnel():
    s = base()
    remove("Cube")
    bpy.ops.mesh.primitive_monkey_add(location=(-1.0, 0, 0))
    bpy.ops.object.shade_smooth()
    m, nt = material("Fresnel mix", bpy.context.active_object)
    nt.nodes.remove(nt.nodes["Principled BSDF"])
    d = nt.nodes.new("ShaderNodeBsdfDiffuse")
    d.inputs["Color"].default_value = (0.1, 0.5, 0.2, 1)
    gl = nt.nodes.new("ShaderNodeBsdfGlossy")
    gl.inputs["Roughness"].default_value = 0.1
    fr = nt.nodes.new("ShaderNodeFresnel")
    mix = nt.nodes.new("ShaderNodeMixShader")
    nt.links.new(fr.outputs["Fac"], mix.inputs["Fac"])
    nt.links.new(d.outputs["BSDF"], mix.inputs[1])
    nt.links.new(gl.outputs["BSDF"], mix.inputs[2])
    nt.links.new(mix.outputs["Shader"], nt.nodes["Material Output"].inputs["Surface"])
    ob = sphere(0.9, (1.3, 0.6, 0))
    m, nt = material("Toon", ob)
    toon = replace_principled(nt, "ShaderNodeBsdfToon")  # Diffuse, size 0.5, smooth 0
    toon.inputs["Color"].default_value = (0.8, 0.3, 0.1, 1)
    return s


def motion():
    s = base()
    cube = bpy.data.objects["Cube"]
    for frame, x in ((0, -2.0), (2, 2.0)):
        cube.location.x = x
        cube.rotation_euler.z = math.radians(30 * frame)
        cube.keyframe_insert("location", frame=frame)
        cube.keyframe_insert("rotation_euler", frame=frame)
    for fc in cube.animation_data.action.fcurves:
        for k in fc.keyframe_points:
            k.interpolation = 'LINEAR'
    s.frame_set(1)
    s.render.use_motion_blur = True  # shutter 0.5, centred on the frame
    return s


def armature():
    """The default cube stretched into a subdivided column, bent by one armature bone keyed
    from -35 to +35 degrees over frames 0-2, motion blur on: deformation blur alone (the object
    itself does not move)."""
    s = base()
    cube = bpy.data.objects["Cube"]
    cube.scale = (0.4, 0.4, 1.5)
    bpy.ops.object.select_all(action='DESELECT')
    cube.select_set(True)
    bpy.context.view_layer.objects.active = cube
    bpy.ops.object.transform_apply(scale=True)
    cube.modifiers.new("subdivision", 'SUBSURF').render_levels = 2
    bpy.ops.object.armature_add(location=(0, 0, -1.5))
    arm = bpy.context.active_object
    bpy.ops.object.mode_set(mode='EDIT')
    bone = arm.data.edit_bones[0]
    bone.head, bone.tail = (0, 0, 0), (0, 0, 3)
    bpy.ops.object.mode_set(mode='OBJECT')
    bpy.ops.object.select_all(action='DESELECT')
    cube.select_set(True)
    arm.select_set(True)
    bpy.context.view_layer.objects.active = arm
    bpy.ops.object.parent_set(type='ARMATURE_AUTO')
    pose = arm.pose.bones[0]
    pose.rotation_mode = 'XYZ'
    for frame, angle in ((0, -0.6), (2, 0.6)):
        pose.rotation_euler = (angle, 0, 0)
        pose.keyframe_insert("rotation_euler", frame=frame)
    for fc in arm.animation_data.action.fcurves:
        for k in fc.keyframe_points:
            k.interpolation = 'LINEAR'
    s.frame_set(1)
    s.render.use_motion_blur = True
    return s


def vertex_colors():
    s = base()
    cube = bpy.data.objects["Cube"]
    cube.location.x = -1.3
    cube.scale = (0.8, 0.8, 0.8)
    # A float colour per vertex (what Add Color Attribute makes by default) ...
    me = cube.data
    ca = me.color_attributes.new("Col", 'FLOAT_COLOR', 'POINT')
    for i, v in enumerate(me.vertices):
        ca.data[i].color = (0.5 + 0.5 * v.co.x, 0.5 + 0.5 * v.co.y, 0.5 + 0.5 * v.co.z, 1)
    m, nt = material("Cube colours", cube)
    vc = nt.nodes.new("ShaderNodeVertexColor")
    vc.layer_name = "Col"
    nt.links.new(vc.outputs["Color"], nt.nodes["Principled BSDF"].inputs["Base Color"])
    # ... and a byte colour per face corner (what Vertex Paint used to paint into).
    ob = sphere(1.0, (1.3, 0.3, 0))
    me = ob.data
    ca = me.color_attributes.new("Paint", 'BYTE_COLOR', 'CORNER')
    for poly in me.polygons:
        for li in poly.loop_indices:
            z = me.vertices[me.loops[li].vertex_index].co.z
            band = int((z + 1.0) * 4) % 3
            ca.data[li].color = ((1, 0.1, 0.1, 1), (0.1, 0.8, 0.2, 1), (0.2, 0.3, 1, 1))[band]
    m, nt = material("Sphere paint", ob)
    vc = nt.nodes.new("ShaderNodeVertexColor")
    vc.layer_name = "Paint"
    nt.links.new(vc.outputs["Color"], nt.nodes["Principled BSDF"].inputs["Base Color"])
    return s


def displacement():
    s = base()
    remove("Cube")
    ob = sphere(1.2)
    m, nt = material("Displaced", ob)  # Settings > Displacement: Bump Only (the default)
    assert m.cycles.displacement_method == 'BUMP'
    noise = nt.nodes.new("ShaderNodeTexNoise")
    noise.inputs["Scale"].default_value = 3
    disp = nt.nodes.new("ShaderNodeDisplacement")
    disp.inputs["Scale"].default_value = 0.3
    nt.links.new(noise.outputs["Fac"], disp.inputs["Height"])
    nt.links.new(disp.outputs["Displacement"], nt.nodes["Material Output"].inputs["Displacement"])
    nt.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.7, 0.5, 0.3, 1)
    return s


def empty_parent():
    s = base()
    bpy.ops.object.empty_add(type='PLAIN_AXES', location=(0, 0, 0.5))
    empty = bpy.context.active_object
    empty.rotation_euler = (math.radians(25), math.radians(15), math.radians(40))
    empty.scale = (1.2, 1.2, 1.2)
    bpy.data.objects["Cube"].parent = empty
    return s


def velvet_sheen():
    s = base()
    remove("Cube")
    ob = sphere(1.0, (-1.2, 0, 0))
    m, nt = material("Velvet", ob)
    v = replace_principled(nt, "ShaderNodeBsdfVelvet")  # sigma 1
    v.inputs["Color"].default_value = (0.6, 0.05, 0.1, 1)
    ob = sphere(1.0, (1.2, 0.5, 0))
    m, nt = material("Sheen + clearcoat", ob)
    pr = nt.nodes["Principled BSDF"]
    pr.inputs["Base Color"].default_value = (0.1, 0.2, 0.6, 1)
    pr.inputs["Sheen"].default_value = 1.0
    pr.inputs["Clearcoat"].default_value = 1.0
    pr.inputs["Clearcoat Roughness"].default_value = 0.05
    return s


def fisheye():
    s = base()
    bpy.ops.mesh.primitive_plane_add(size=12, location=(0, 0, -1))
    sphere(0.7, (-2.0, 0.5, -0.3))
    sphere(0.5, (1.8, -1.0, -0.5))
    bpy.ops.mesh.primitive_cylinder_add(radius=0.4, depth=2, location=(0.5, 2.0, 0))
    cam_ob = bpy.data.objects["Camera"]
    cam_ob.location = (0, -4.5, 1.5)
    cam_ob.rotation_euler = (math.radians(75), 0, 0)
    cam = cam_ob.data
    cam.type = 'PANO'
    cam.cycles.panorama_type = 'FISHEYE_EQUIDISTANT'  # 3.4 keeps these on cam.cycles
    cam.cycles.fisheye_fov = math.radians(180)
    return s


SCENES = [noise_ramp, sky, still_life, toon_fresnel, motion, vertex_colors, displacement,
          empty_parent, velvet_sheen, fisheye, armature]


# ----------------------------------------------------------------------------- images and SSIM

def load_exr(path):
    img = bpy.data.images.load(path, check_existing=False)
    w, h = img.size
    a = np.empty(w * h * 4, np.float32)
    img.pixels.foreach_get(a)
    bpy.data.images.remove(img)
    return a.reshape(h, w, 4)[::-1, :, :3].astype(np.float64)  # top row first


def srgb(lin):
    x = np.clip(lin, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def luma(enc):
    return enc @ np.array([0.2126, 0.7152, 0.0722])


def _blur(x, k):
    x = np.apply_along_axis(lambda r: np.convolve(r, k, mode="valid"), 1, x)
    return np.apply_along_axis(lambda c: np.convolve(c, k, mode="valid"), 0, x)


def ssim(a, b, sigma=1.5, radius=5):
    t = np.arange(-radius, radius + 1)
    k = np.exp(-0.5 * (t / sigma) ** 2)
    k /= k.sum()
    c1, c2 = 0.01 ** 2, 0.03 ** 2
    ma, mb = _blur(a, k), _blur(b, k)
    saa = _blur(a * a, k) - ma * ma
    sbb = _blur(b * b, k) - mb * mb
    sab = _blur(a * b, k) - ma * mb
    m = ((2 * ma * mb + c1) * (2 * sab + c2)) / ((ma * ma + mb * mb + c1) * (saa + sbb + c2))
    return float(m.mean())


# 5x7 bitmap letters for the labels.
FONT = {
    "g": ["00000", "01111", "10001", "10001", "01111", "00001", "01110"],
    "l": ["01100", "00100", "00100", "00100", "00100", "00100", "01110"],
    "i": ["00100", "00000", "01100", "00100", "00100", "00100", "01110"],
    "n": ["00000", "10110", "11001", "10001", "10001", "10001", "10001"],
    "t": ["01000", "11100", "01000", "01000", "01000", "01001", "00110"],
    "C": ["01110", "10001", "10000", "10000", "10000", "10001", "01110"],
    "y": ["00000", "10001", "10001", "10001", "01111", "00001", "01110"],
    "c": ["00000", "01110", "10000", "10000", "10000", "10001", "01110"],
    "e": ["00000", "01110", "10001", "11111", "10000", "10001", "01110"],
    "s": ["00000", "01111", "10000", "01110", "00001", "00001", "11110"],
    " ": ["00000"] * 7,
}


def draw_text(canvas, text, x0, y0):
    for ch in text:
        for r, row in enumerate(FONT[ch]):
            for c, bit in enumerate(row):
                if bit == "1":
                    canvas[y0 + r, x0 + c] = 1.0
        x0 += 6


def save_pair(path, left, right):
    """Side by side, sRGB-encoded, with a label strip on top; 8-bit RGB PNG."""
    strip = 11
    canvas = np.zeros((H + strip, 2 * W, 3))
    canvas[strip:, :W] = srgb(left)
    canvas[strip:, W:] = srgb(right)
    draw_text(canvas, "glint", 3, 2)
    draw_text(canvas, "Cycles", W + 3, 2)
    img = bpy.data.images.new("pair", 2 * W, H + strip, alpha=False)
    rgba = np.ones((H + strip, 2 * W, 4))
    rgba[:, :, :3] = np.round(canvas * 255) / 255
    img.pixels.foreach_set(rgba[::-1].astype(np.float32).ravel())
    img.filepath_raw = path
    img.file_format = 'PNG'
    img.save()
    bpy.data.images.remove(img)


# ----------------------------------------------------------------------------- the comparison

def render_cycles(s, path, seed):
    s.cycles.seed = seed
    s.render.filepath = path
    bpy.ops.render.render(write_still=True)


def compare(fn):
    name = fn.__name__
    d = os.path.join(OUT, name)
    os.makedirs(d, exist_ok=True)
    s = fn()
    t0 = time.time()
    render_cycles(s, os.path.join(d, "cycles1.exr"), 1)
    render_cycles(s, os.path.join(d, "cycles2.exr"), 2)
    t_cycles = (time.time() - t0) / 2
    export_warnings = []
    ex = native_export.export_frame_native(bpy.context.evaluated_depsgraph_get(), d,
                                           export_warnings.append)
    t0 = time.time()
    p = subprocess.run([GLINT] + ex.argv, cwd=d, capture_output=True, text=True)
    t_glint = time.time() - t0
    with open(os.path.join(d, "glint.log"), "w") as f:
        f.write(" ".join([GLINT] + ex.argv) + "\n" + p.stdout + p.stderr)
    if p.returncode != 0:
        raise RuntimeError("%s: glint failed (%d):\n%s" % (name, p.returncode, p.stderr))
    glint_warnings = [ln.split("warning: ", 1)[1] for ln in p.stderr.splitlines()
                      if "warning:" in ln]
    c1 = load_exr(os.path.join(d, "cycles1.exr"))
    c2 = load_exr(os.path.join(d, "cycles2.exr"))
    g = load_exr(ex.output_path)
    y1 = luma(srgb(c1))
    s_glint = ssim(luma(srgb(g)), y1)
    s_floor = ssim(luma(srgb(c2)), y1)
    e1 = srgb(c1)  # cross-check: the worst of the three per-channel SSIMs
    ch_glint = min(ssim(srgb(g)[:, :, i], e1[:, :, i]) for i in range(3))
    ch_floor = min(ssim(srgb(c2)[:, :, i], e1[:, :, i]) for i in range(3))
    save_pair(os.path.join(HERE, "everyday_%s.png" % name), g, c1)
    r = dict(scene=name, glint=s_glint, floor=s_floor, ok=s_glint >= s_floor - PASS_MARGIN,
             warnings=export_warnings + glint_warnings, ch_glint=ch_glint, ch_floor=ch_floor, t_cycles=t_cycles, t_glint=t_glint,
             mean_glint=srgb(g).mean(axis=(0, 1)), mean_cycles=srgb(c1).mean(axis=(0, 1)))
    print("RESULT", r, flush=True)
    return r


def table(results):
    rows = ["| scene | SSIM glint | SSIM floor | pass | warnings |",
            "|---|---|---|---|---|"]
    for r in results:
        w = "; ".join(re.sub(r"\s+", " ", x) for x in r["warnings"]) or "none"
        rows.append("| %s | %.3f | %.3f | %s | %s |" % (
            r["scene"], r["glint"], r["floor"], "yes" if r["ok"] else "**no**", w))
    return "\n".join(rows) + "\n"


def main():
    wanted = ARGS[1].split(",") if len(ARGS) > 1 else [f.__name__ for f in SCENES]
    os.makedirs(OUT, exist_ok=True)
    results = [compare(f) for f in SCENES if f.__name__ in wanted]
    t = table(results)
    with open(os.path.join(OUT, "results.md"), "w") as f:
        f.write(t)
    print(t)
    for r in results:
        print("%-14s cycles %.1fs/render glint %.1fs  per-channel SSIM min glint %.3f floor %.3f"
              "  mean sRGB glint %s cycles %s" % (
            r["scene"], r["t_cycles"], r["t_glint"], r["ch_glint"], r["ch_floor"],
            np.round(r["mean_glint"], 3),
            np.round(r["mean_cycles"], 3)))


main()
