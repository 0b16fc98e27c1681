"""Enables the glint add-on from this working tree inside a Blender started with
--factory-startup, and builds the small scenes the plugin tests render.

As a --python script (before -E GLINT on the command line) it only enables the add-on:
    blender -b f.blend --python tests/plugin/addon_env.py -E GLINT -f 1
The glint binary comes from $GLINT_BINARY (the add-on's fallback when its preference is empty).
As a module: enable(binary=None), build_scene(...), render_to(path).
"""

import atexit
import math
import os
import shutil
import sys
import tempfile

import addon_utils
import bpy
from mathutils import Vector

HERE = os.path.dirname(os.path.abspath(__file__))
ADDON_SRC = os.path.normpath(os.path.join(HERE, "..", "..", "plugin", "blender",
                                          "glint_blender"))


def enable(binary=None, keep_temp=False):
    """Links the add-on into a temporary scripts folder, enables it, sets its preferences."""
    scripts = tempfile.mkdtemp(prefix="glint_addon_scripts_")
    atexit.register(shutil.rmtree, scripts, True)
    os.makedirs(os.path.join(scripts, "addons"))
    os.symlink(ADDON_SRC, os.path.join(scripts, "addons", "glint_blender"))
    bpy.context.preferences.filepaths.script_directory = scripts
    bpy.utils.refresh_script_paths()
    addons_dir = os.path.join(scripts, "addons")
    if addons_dir not in sys.path:
        sys.path.append(addons_dir)
    addon_utils.modules_refresh()
    mod = addon_utils.enable("glint_blender", default_set=True, handle_error=None)
    if mod is None:
        raise RuntimeError("cannot enable glint_blender from " + ADDON_SRC)
    prefs = bpy.context.preferences.addons["glint_blender"].preferences
    if binary is not None:
        prefs.binary = binary
    prefs.keep_temp = keep_temp
    return prefs


def _material(name, color, emission=None, strength=1.0):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    p = m.node_tree.nodes["Principled BSDF"]
    p.inputs["Base Color"].default_value = (*color, 1.0)
    p.inputs["Roughness"].default_value = 0.5
    if emission is not None:
        p.inputs["Emission"].default_value = (*emission, 1.0)
        p.inputs["Emission Strength"].default_value = strength
    m.diffuse_color = (*color, 1.0)
    return m


def build_scene(width=64, height=48, samples=8, light='AREA', animated_camera=False,
                heavy=False):
    """A floor, a cube and a sphere, a camera and one light; `heavy` makes glint take many
    seconds (large image, many samples) for the cancel test."""
    scene = bpy.context.scene
    # Start empty without read_factory_settings (which would disable the add-on again).
    bpy.data.batch_remove(list(bpy.data.objects) + list(bpy.data.meshes) +
                          list(bpy.data.materials) + list(bpy.data.lights) +
                          list(bpy.data.cameras) + list(bpy.data.worlds))
    bpy.ops.mesh.primitive_plane_add(size=8, location=(0, 0, 0))
    bpy.context.active_object.data.materials.append(_material("floor", (0.6, 0.6, 0.6)))
    bpy.ops.mesh.primitive_cube_add(size=1, location=(-0.8, 0.3, 0.5),
                                    rotation=(0, 0, math.radians(20)))
    bpy.context.active_object.data.materials.append(_material("red", (0.7, 0.1, 0.1)))
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.5, location=(0.8, -0.2, 0.5))
    bpy.ops.object.shade_smooth()
    bpy.context.active_object.data.materials.append(_material("blue", (0.1, 0.2, 0.7)))
    cam = bpy.data.cameras.new("Camera")
    cam.lens = 35
    cam_ob = bpy.data.objects.new("Camera", cam)
    scene.collection.objects.link(cam_ob)
    scene.camera = cam_ob

    def aim(location, target=(0, 0, 0.5)):
        cam_ob.location = location
        d = Vector(target) - Vector(location)
        cam_ob.rotation_euler = d.to_track_quat("-Z", "Y").to_euler()

    aim((0, -5, 2.5))
    if animated_camera:
        for frame, x in ((1, -2.0), (2, 0.0), (3, 2.0)):
            aim((x, -5, 2.5))
            cam_ob.keyframe_insert("location", frame=frame)
            cam_ob.keyframe_insert("rotation_euler", frame=frame)
        sphere = bpy.data.objects["Sphere"]
        for frame, z in ((1, 0.5), (2, 1.0), (3, 1.5)):  # the OBJ must follow the frame too
            sphere.location.z = z
            sphere.keyframe_insert("location", frame=frame)
        scene.frame_start, scene.frame_end = 1, 3
    if light is not None:
        ld = bpy.data.lights.new("Light", light)
        ld.energy = {'AREA': 300.0, 'POINT': 500.0, 'SPOT': 800.0, 'SUN': 3.0}[light]
        if light == 'AREA':
            ld.size = 1.0
        lob = bpy.data.objects.new("Light", ld)
        scene.collection.objects.link(lob)
        lob.location = (1.0, -1.5, 3.5)
        lob.rotation_euler = (math.radians(25), 0, math.radians(20))
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.05, 0.07, 0.1, 1)
    scene.world = world
    r = scene.render
    r.engine = "GLINT"
    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
    if heavy:
        r.resolution_x, r.resolution_y = 1280, 960
    s = r.image_settings
    s.file_format = "OPEN_EXR"
    s.color_mode = "RGB"
    s.color_depth = "32"
    scene.glint.samples = 100000 if heavy else samples
    scene.glint.max_depth = 8
    return scene


def render_to(path):
    bpy.context.scene.render.filepath = path
    bpy.ops.render.render(write_still=True)


if __name__ == "__main__":
    enable()
