"""Issue 30's motion blur, normal map and transparent glass scenes for make_scenes.py, which
loads this file and sets `ms` to its helpers: cy, add_sphere, floor, add_light, aim,
node_material, bare_material, emission_stage."""

import math
import os
import shutil

import bpy

ms = None


def keyframe_linear(ob, path, values):
    """Keys ob.<path> at each (frame, value), linear: motion at a constant rate. `ob` may be
    a struct inside an ID (a shape key, a modifier): the keys go to that ID's action."""
    for frame, value in values:
        setattr(ob, path, value)
        ob.keyframe_insert(path, frame=frame)
    for fc in ob.id_data.animation_data.action.fcurves:
        for kp in fc.keyframe_points:
            kp.interpolation = "LINEAR"


def motion_stage():
    """The still part of the motion scenes: a floor and a sphere under a sun, world color."""
    ms.floor(ms.cy.diffuse_material("floor", (0.6, 0.6, 0.6)))
    ms.add_sphere("ball", (1.4, 0.8, 0.5), 0.5, ms.cy.diffuse_material("ball", (0.3, 0.5, 0.7)))
    sun = ms.add_light("sun", "SUN", (0, 0, 5), energy=3.0, angle=math.radians(3.0))
    ms.aim(sun, (-0.5, 0.8, 0.0))
    sun.location = (0, 0, 5)
    ms.cy.set_world_color((0.3, 0.35, 0.45))


def build_motion(out_dir):
    """Object motion blur (Cycles' defaults: shutter 0.5 frames centred on the frame, 3
    steps): a cube sliding along X at 2 m per frame and a bar turning about Z at 90 degrees
    per frame, both keyed linearly over frames 0-2 (frame 1 rendered); the camera stays."""
    motion_stage()
    cube = ms.cy.add_box("cube", (0, 0, 0), (0.6, 0.6, 0.6), 0, ms.cy.diffuse_material(
        "cube", (0.8, 0.25, 0.15)))
    keyframe_linear(cube, "location", ((0, (-2.0, -0.6, 0.3)), (2, (2.0, -0.6, 0.3))))
    bar = ms.cy.add_box("bar", (0, 0, 0), (1.8, 0.25, 0.25), 0, ms.cy.diffuse_material(
        "bar", (0.9, 0.8, 0.2)))
    bar.location = (-0.8, 1.0, 0.6)
    keyframe_linear(bar, "rotation_euler", ((0, (0, 0, 0)), (2, (0, 0, math.radians(180)))))
    ms.cy.add_camera((0.0, -5.5, 3.0), (0, 0.2, 0.3), lens_mm=35.0)
    bpy.context.scene.render.use_motion_blur = True


def build_motion_camera(out_dir):
    """Camera motion blur with the shutter opening at the frame (position START, 1 frame):
    the camera pans and rises over frames 1-2; a box turns about a tilted axis with 2 motion
    steps (5 matrices) and one object has Cycles' motion blur off (it moves, but sharp)."""
    motion_stage()
    box = ms.cy.add_box("box", (0, 0, 0), (0.8, 0.5, 0.5), 0, ms.cy.diffuse_material(
        "box", (0.8, 0.25, 0.15)))
    box.location = (-0.7, 0.2, 0.8)
    box.cycles.motion_steps = 2
    keyframe_linear(box, "rotation_euler", ((1, (0.3, 0, 0)), (2, (0.3, 0.6, 1.6))))
    sharp = ms.cy.add_box("sharp", (0, 0, 0), (0.4, 0.4, 0.4), 0, ms.cy.diffuse_material(
        "sharp", (0.2, 0.7, 0.3)))
    keyframe_linear(sharp, "location", ((1, (0.4, -1.0, 0.2)), (2, (1.4, -1.0, 0.2))))
    sharp.cycles.use_motion_blur = False
    cam = ms.cy.add_camera((-0.3, -5.5, 2.6), (0, 0.2, 0.3), lens_mm=35.0)
    keyframe_linear(cam, "location", ((1, (-0.3, -5.5, 2.6)), (2, (0.3, -5.3, 2.9))))
    keyframe_linear(cam, "rotation_euler", ((1, tuple(cam.rotation_euler)),
                                            (2, (cam.rotation_euler.x - 0.05,
                                                 cam.rotation_euler.y,
                                                 cam.rotation_euler.z + 0.06))))
    scene = bpy.context.scene
    scene.render.use_motion_blur = True
    scene.render.motion_blur_shutter = 1.0
    scene.cycles.motion_blur_position = "START"


def build_motion_deform(out_dir):
    """Deformation motion blur (Cycles' defaults: shutter 0.5 frames centred on frame 1, 3
    steps), keyed linearly over frames 0-2: a box whose top leans along X by a shape key, a
    smooth open tube bent by an animated Simple Deform (bend) that also slides (deformation
    and object motion together), and a box
    deformed by a shape key but with Deformation blur off (sharp)."""
    motion_stage()
    lean = ms.cy.add_box("lean", (0, 0, 0), (0.5, 0.5, 1.0), 0, ms.cy.diffuse_material(
        "lean", (0.8, 0.25, 0.15)))
    lean.location = (-1.3, -0.4, 0.5)
    lean.shape_key_add(name="Basis")
    key = lean.shape_key_add(name="Lean")
    for v in key.data:
        if v.co.z > 0:
            v.co.x += 1.2
    keyframe_linear(key, "value", ((0, 0.0), (2, 1.0)))
    bpy.ops.mesh.primitive_cylinder_add(vertices=24, radius=0.18, depth=2.2,
                                        end_fill_type="NOTHING", location=(0.2, 0.9, 0.45),
                                        rotation=(0, math.radians(90), 0))
    bar = bpy.context.active_object
    bar.name = "bend"
    bar.data.materials.append(ms.cy.diffuse_material("bend", (0.9, 0.8, 0.2)))
    for poly in bar.data.polygons:
        poly.use_smooth = True
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.select_all(action="SELECT")
    bpy.ops.mesh.subdivide(number_cuts=12)
    bpy.ops.object.mode_set(mode="OBJECT")
    mod = bar.modifiers.new("bend", "SIMPLE_DEFORM")
    mod.deform_method = "BEND"
    mod.deform_axis = "Y"
    keyframe_linear(mod, "angle", ((0, math.radians(-60)), (2, math.radians(120))))
    keyframe_linear(bar, "location", ((0, (0.0, 0.9, 0.45)), (2, (0.4, 0.9, 0.45))))
    still = ms.cy.add_box("still", (0, 0, 0), (0.4, 0.4, 0.4), 0, ms.cy.diffuse_material(
        "still", (0.2, 0.7, 0.3)))
    still.location = (0.3, -1.1, 0.2)
    still.shape_key_add(name="Basis")
    grow = still.shape_key_add(name="Grow")
    for v in grow.data:
        v.co *= 1.8
    keyframe_linear(grow, "value", ((0, 0.0), (2, 1.0)))
    still.cycles.use_deform_motion = False
    ms.cy.add_camera((0.0, -5.5, 3.0), (0, 0.2, 0.3), lens_mm=35.0)
    bpy.context.scene.render.use_motion_blur = True


def build_normal_map(out_dir):
    """(issue 30) The Normal Map node in tangent space, its output normal shown through
    Emission (N * 0.5 + 0.5, so the image is exact): a constant tangent-space colour on a
    low-poly smooth UV sphere (MikkTSpace's tangents are smooth where dPdu is faceted),
    Suzanne (mirrored UV islands: the bitangent sign flips) and a rotated, non-uniformly scaled
    cube through a second UV map that is not the active one; black world, orthographic camera."""
    def material(name, uv_map=""):
        mat, nt, out = ms.bare_material(name)
        nm = nt.nodes.new("ShaderNodeNormalMap")
        nm.space = "TANGENT"
        nm.uv_map = uv_map
        nm.inputs["Color"].default_value = (0.85, 0.25, 0.8, 1.0)
        half = nt.nodes.new("ShaderNodeVectorMath")
        half.operation = "MULTIPLY_ADD"
        half.inputs[1].default_value = (0.5, 0.5, 0.5)
        half.inputs[2].default_value = (0.5, 0.5, 0.5)
        nt.links.new(nm.outputs["Normal"], half.inputs[0])
        em = nt.nodes.new("ShaderNodeEmission")
        nt.links.new(half.outputs["Vector"], em.inputs["Color"])
        nt.links.new(em.outputs[0], out.inputs["Surface"])
        return mat

    ms.add_sphere("nm_sphere", (-1.8, 0, 0), 0.8, material("nm_sphere"), segments=10, rings=6)
    bpy.ops.mesh.primitive_monkey_add(size=1.4, location=(0, 0, 0), rotation=(0, 0, math.pi))
    monkey = bpy.context.active_object
    monkey.name = "nm_monkey"
    bpy.ops.object.shade_smooth()
    monkey.data.materials.append(material("nm_monkey"))
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(1.8, 0, 0),
                                    rotation=(0.4, 0.3, 0.7))
    cube = bpy.context.active_object
    cube.name = "nm_cube"
    cube.scale = (1.0, 0.7, 1.2)
    me = cube.data
    second = me.uv_layers.new(name="Rotated")
    for loop in me.loops:  # the second map turned by 60 degrees and stretched
        u, v = me.uv_layers[0].data[loop.index].uv
        c, s = math.cos(1.05), math.sin(1.05)
        second.data[loop.index].uv = (2.0 * (c * u - s * v), s * u + c * v)
    me.uv_layers.active_index = 0
    me.materials.append(material("nm_cube", uv_map="Rotated"))
    ms.emission_stage()


def build_film_glass(out_dir):
    """Film > Transparent with Transparent Glass (roughness threshold 0.1, Cycles' default)
    over a floor strip: a sharp Glass sphere (the world behind it is transparent), Glass
    spheres of roughness 0.25 and 0.5 (over the threshold: opaque), and a Principled sphere
    of transmission 1 and roughness 0.08 (under it)."""
    ms.cy.add_quad("strip", (0.0, 0.5, 0.0), 6.0, 2.2, ms.cy.diffuse_material(
        "strip", (0.6, 0.6, 0.6)), z_normal_down=False)
    glass = "ShaderNodeBsdfGlass"
    for k, (rough, color) in enumerate(((0.0, (1, 1, 1, 1)), (0.25, (0.6, 0.9, 1.0, 1)),
                                        (0.5, (1, 1, 1, 1)))):
        ms.add_sphere("glass%d" % k, (-1.8 + 1.2 * k, 0.3, 0.9), 0.5, ms.node_material(
            "glass%d" % k, glass, distribution="GGX", Roughness=rough, IOR=1.45, Color=color))
    pr = ms.cy.principled_material("glassy", base=(1.0, 0.8, 0.6), roughness=0.08)
    pr.node_tree.nodes["Principled BSDF"].inputs["Transmission"].default_value = 1.0
    ms.add_sphere("glassy", (1.8, 0.3, 0.9), 0.5, pr)
    sun = ms.add_light("sun", "SUN", (0, 0, 5), energy=3.0, angle=math.radians(3.0))
    ms.aim(sun, (-0.5, 0.8, 0.0))
    sun.location = (0, 0, 5)
    ms.cy.add_camera((0.0, -5.0, 1.6), (0.0, 0.4, 0.6), lens_mm=35.0)
    ms.cy.set_world_color((0.3, 0.35, 0.45))
    bpy.context.scene.cycles.film_transparent_glass = True
    bpy.context.scene.cycles.film_transparent_roughness = 0.1


def volume_material(name, kind, surface=None, **inputs):
    """A material whose Volume output is one volume shader node (`kind`: ShaderNodeVolume*)
    with `inputs` set by socket name; `surface`: an optional shader node type for Surface."""
    mat, nt, out = ms.bare_material(name)
    vol = nt.nodes.new(kind)
    for key, value in inputs.items():
        vol.inputs[key.replace("_", " ").title()].default_value = value
    socket = "Emission" if kind == "ShaderNodeEmission" else "Volume"
    nt.links.new(vol.outputs[socket], out.inputs["Volume"])
    if surface:
        s = nt.nodes.new(surface)
        nt.links.new(s.outputs[0], out.inputs["Surface"])
    return mat


def build_volume(out_dir):
    """(issue 31) Volumes as Cycles 3.4 renders them: a Principled Volume cube without a
    surface (scattering colour, anisotropy, absorption colour), a sphere of Volume Scatter
    behind a Transparent BSDF surface, a Volume Absorption slab, and a cube whose volume is an
    Emission shader; two volume bounces (Cycles' default is none), a point light and a dim
    world. The boxes float a little above the floor: a volume's face in the floor's plane
    leaves it to chance which surface a ray meets first, in Cycles as in glint."""
    ms.floor(ms.cy.diffuse_material("floor", (0.6, 0.6, 0.6)))
    ms.cy.add_box("smoke", (-1.2, 0.3, 0.62), (1.2, 1.2, 1.2), 20, volume_material(
        "smoke", "ShaderNodeVolumePrincipled", color=(0.8, 0.5, 0.3, 1.0), density=1.5,
        anisotropy=0.3, absorption_color=(0.2, 0.3, 0.9, 1.0)))
    ms.add_sphere("mist", (0.9, 0.0, 0.7), 0.7, volume_material(
        "mist", "ShaderNodeVolumeScatter", surface="ShaderNodeBsdfTransparent",
        color=(0.4, 0.7, 0.9, 1.0), density=2.5, anisotropy=-0.4))
    ms.cy.add_box("filter", (0.2, -1.3, 0.37), (1.6, 0.2, 0.7), 0, volume_material(
        "filter", "ShaderNodeVolumeAbsorption", color=(0.9, 0.4, 0.2, 1.0), density=3.0))
    ms.cy.add_box("glow", (2.1, 1.0, 0.32), (0.5, 0.5, 0.6), 0, volume_material(
        "glow", "ShaderNodeEmission", color=(1.0, 0.6, 0.2, 1.0), strength=1.5))
    ms.add_light("lamp", "POINT", (1.0, -2.0, 3.5), energy=600.0, shadow_soft_size=0.2)
    ms.cy.add_camera((0.0, -5.5, 2.4), (0.2, 0.2, 0.5), lens_mm=35.0)
    ms.cy.set_world_color((0.05, 0.06, 0.08))


# Render settings a scene needs after cy.setup_render's defaults.
AFTER_SETUP = {"volume": lambda scene: setattr(scene.cycles, "volume_bounces", 2)}


def noise_ramp(nt, scale, detail, low, high):
    """A Noise Texture through a ColorRamp from black at `low` to white at `high` (the everyday
    cloud density); returns the ramp."""
    noise = nt.nodes.new("ShaderNodeTexNoise")
    noise.inputs["Scale"].default_value = scale
    noise.inputs["Detail"].default_value = detail
    ramp = nt.nodes.new("ShaderNodeValToRGB")
    ramp.color_ramp.elements[0].position = low
    ramp.color_ramp.elements[1].position = high
    nt.links.new(noise.outputs["Fac"], ramp.inputs["Fac"])
    return ramp


def build_volume_noise(out_dir):
    """(issue 31) A volume that varies in space, ray marched as Cycles marches it: a cube of
    Principled Volume whose density is a Noise Texture through a ColorRamp (the everyday smoke
    cloud), Cycles' default step rate and max steps, beside a sphere whose Volume Scatter
    density follows a Gradient Texture over Object coordinates, with the material's step rate
    at 0.5; a sun and a dim world, one volume bounce."""
    ms.floor(ms.cy.diffuse_material("floor", (0.6, 0.6, 0.6)))
    mat, nt, out = ms.bare_material("cloud")
    ramp = noise_ramp(nt, 3.0, 4.0, 0.45, 0.65)
    vol = nt.nodes.new("ShaderNodeVolumePrincipled")
    vol.inputs["Color"].default_value = (0.9, 0.85, 0.8, 1.0)
    vol.inputs["Density"].default_value = 6.0
    nt.links.new(ramp.outputs["Color"], vol.inputs["Density"])
    nt.links.new(vol.outputs["Volume"], out.inputs["Volume"])
    ms.cy.add_box("cloud", (-0.8, 0.2, 0.82), (1.6, 1.6, 1.6), 15, mat)
    mat2, nt2, out2 = ms.bare_material("fade")
    coords = nt2.nodes.new("ShaderNodeTexCoord")
    grad = nt2.nodes.new("ShaderNodeTexGradient")
    grad.gradient_type = "SPHERICAL"
    scat = nt2.nodes.new("ShaderNodeVolumeScatter")
    scat.inputs["Color"].default_value = (0.5, 0.7, 1.0, 1.0)
    nt2.links.new(coords.outputs["Object"], grad.inputs["Vector"])
    nt2.links.new(grad.outputs["Fac"], scat.inputs["Density"])
    nt2.links.new(scat.outputs["Volume"], out2.inputs["Volume"])
    mat2.cycles.volume_step_rate = 0.5
    ms.add_sphere("fade", (1.2, 0.0, 0.85), 0.8, mat2)
    sun = ms.add_light("sun", "SUN", (0, 0, 5), energy=2.0, angle=0.05)
    ms.aim(sun, (-0.4, 0.7, -0.2))
    ms.cy.add_camera((0.0, -5.5, 2.4), (0.2, 0.2, 0.6), lens_mm=35.0)
    ms.cy.set_world_color((0.05, 0.06, 0.08))


AFTER_SETUP["volume_noise"] = lambda scene: setattr(scene.cycles, "volume_bounces", 1)


def build_volume_world(out_dir):
    """(issue 31) The world's volume: a thin Volume Scatter fog (density 0.04, anisotropy 0.5)
    filling the world, a spot light's beam through it past a box that cuts a shadow in it, an
    area light and a glossy sphere; Cycles' default of no volume bounces."""
    ms.floor(ms.cy.diffuse_material("floor", (0.5, 0.5, 0.5)))
    ms.cy.add_box("block", (-0.4, 0.3, 1.6), (0.5, 0.5, 0.5), 30, ms.cy.diffuse_material(
        "block", (0.7, 0.3, 0.2)))
    ms.add_sphere("ball", (1.0, 0.6, 0.5), 0.5, ms.cy.principled_material(
        "ball", base=(0.3, 0.4, 0.8), roughness=0.3))
    spot = ms.add_light("spot", "SPOT", (-0.8, 0.4, 4.0), energy=800.0, spot_size=0.7,
                        spot_blend=0.2, shadow_soft_size=0.05)
    ms.aim(spot, (-0.2, 0.2, 0.0))
    area = ms.add_light("panel", "AREA", (2.5, -1.5, 2.5), energy=150.0, size=1.0)
    ms.aim(area, (0.5, 0.5, 0.5))
    ms.cy.add_camera((0.0, -6.0, 2.2), (0.2, 0.3, 1.0), lens_mm=35.0)
    ms.cy.set_world_color((0.02, 0.02, 0.03))
    nt = bpy.context.scene.world.node_tree
    out = next(n for n in nt.nodes if n.type == "OUTPUT_WORLD")
    scat = nt.nodes.new("ShaderNodeVolumeScatter")
    scat.inputs["Color"].default_value = (0.9, 0.9, 1.0, 1.0)
    scat.inputs["Density"].default_value = 0.04
    scat.inputs["Anisotropy"].default_value = 0.5
    nt.links.new(scat.outputs["Volume"], out.inputs["Volume"])


def build_world_fog(out_dir):
    """(issue 31) A world volume that varies in space: patchy fog filling the world (Principled
    Volume whose density is a Noise Texture through a ColorRamp over world coordinates, at the
    world's own Volume step size 0.5) in a closed room, lit by a point light and an area light.
    (In Cycles a ray that meets no surface sees no light through such a world, and a sun's
    light does not come through it: the room keeps every ray on surfaces.) The camera's Clip
    Start 0.6 m leaves out a small sphere in front of it."""
    ms.cy.add_box("room", (0.0, 2.0, 2.5), (10.0, 16.0, 5.0), 0, ms.cy.diffuse_material(
        "room", (0.6, 0.6, 0.6)))
    ms.cy.add_box("block", (-0.6, 1.0, 0.5), (1.0, 1.0, 1.0), 25, ms.cy.diffuse_material(
        "block", (0.7, 0.3, 0.2)))
    ms.add_sphere("ball", (1.2, 2.0, 0.6), 0.6, ms.cy.principled_material(
        "ball", base=(0.3, 0.4, 0.8), roughness=0.3))
    ms.add_sphere("near", (0.15, -4.65, 1.45), 0.12, ms.cy.diffuse_material(
        "near", (0.9, 0.1, 0.1)))
    ms.add_light("bulb", "POINT", (0.3, 0.5, 2.6), energy=400.0, shadow_soft_size=0.1)
    area = ms.add_light("panel", "AREA", (3.0, -1.0, 3.0), energy=300.0, size=1.5)
    ms.aim(area, (0.5, 1.0, 0.5))
    cam = ms.cy.add_camera((0.0, -5.0, 1.5), (0.2, 2.0, 0.8), lens_mm=30.0)
    cam.data.clip_start = 0.6
    ms.cy.set_world_color((0.08, 0.09, 0.12))
    world = bpy.context.scene.world
    world.cycles.volume_step_size = 0.5
    nt = world.node_tree
    out = next(n for n in nt.nodes if n.type == "OUTPUT_WORLD")
    ramp = noise_ramp(nt, 0.8, 2.0, 0.5, 0.65)
    vol = nt.nodes.new("ShaderNodeVolumePrincipled")
    vol.inputs["Color"].default_value = (0.85, 0.9, 1.0, 1.0)
    vol.inputs["Anisotropy"].default_value = 0.3
    math_node = nt.nodes.new("ShaderNodeMath")
    math_node.operation = "MULTIPLY"
    math_node.inputs[1].default_value = 0.35
    nt.links.new(ramp.outputs["Color"], math_node.inputs[0])
    nt.links.new(math_node.outputs["Value"], vol.inputs["Density"])
    nt.links.new(vol.outputs["Volume"], out.inputs["Volume"])


def build_subsurface(out_dir):
    """(issue 31) Subsurface scattering as Cycles 3.4 renders it: a wax-like Principled sphere
    (Subsurface 0.2, the default Random Walk) with a Noise bump on its surface, a Principled
    sphere of anisotropic scattering (Subsurface Anisotropy 0.6, IOR 1.3) under a backlight
    that shows through its rim, and a thin slab of the Subsurface Scattering node (Random Walk
    (Fixed Radius), scale 0.3) lit from behind; an area light in front, a point light behind."""
    ms.floor(ms.cy.diffuse_material("floor", (0.5, 0.5, 0.5)))
    wax = ms.node_material("wax", "ShaderNodeBsdfPrincipled",
                           **{"Base Color": (0.9, 0.8, 0.6, 1.0), "Subsurface": 0.2,
                              "Subsurface Color": (0.9, 0.45, 0.3, 1.0), "Roughness": 0.4})
    nt = wax.node_tree
    noise = nt.nodes.new("ShaderNodeTexNoise")
    noise.inputs["Scale"].default_value = 8.0
    bump = nt.nodes.new("ShaderNodeBump")
    bump.inputs["Strength"].default_value = 0.3
    nt.links.new(noise.outputs["Fac"], bump.inputs["Height"])
    nt.links.new(bump.outputs["Normal"], nt.nodes["Principled BSDF"].inputs["Normal"])
    ms.add_sphere("wax", (-1.1, 0.2, 0.7), 0.7, wax)
    ms.add_sphere("jelly", (0.6, 0.6, 0.6), 0.6, ms.node_material(
        "jelly", "ShaderNodeBsdfPrincipled",
        **{"Base Color": (0.3, 0.8, 0.5, 1.0), "Subsurface": 0.5,
           "Subsurface Radius": (0.6, 1.0, 0.4), "Subsurface Color": (0.3, 0.9, 0.5, 1.0),
           "Subsurface IOR": 1.3, "Subsurface Anisotropy": 0.6, "Roughness": 0.2}))
    jade = ms.node_material("jade", "ShaderNodeSubsurfaceScattering",
                            **{"Color": (0.4, 0.8, 0.6, 1.0), "Scale": 0.3})
    jade.node_tree.nodes["Subsurface Scattering"].falloff = "RANDOM_WALK_FIXED_RADIUS"
    ms.cy.add_box("slab", (1.9, 0.9, 0.62), (0.12, 1.0, 1.2), -25, jade)
    front = ms.add_light("front", "AREA", (-1.5, -3.0, 3.0), energy=250.0, size=1.5)
    ms.aim(front, (0.0, 0.5, 0.5))
    ms.add_light("back", "POINT", (1.2, 2.8, 1.6), energy=400.0, shadow_soft_size=0.3)
    ms.cy.add_camera((0.0, -5.0, 2.0), (0.3, 0.4, 0.6), lens_mm=40.0)
    ms.cy.set_world_color((0.03, 0.03, 0.04))


def write_smoke_vdb(path):
    """An OpenVDB file of a smoke puff, built from code (pyopenvdb, Debian's python3-openvdb):
    a 'density' grid, a ball of 40^3 voxels of 0.05 whose density falls from the centre and
    ripples, and a 'temperature' grid hottest in its lower middle; the same bytes every run."""
    import numpy as np
    import pyopenvdb as vdb
    n = 40
    c = (np.arange(n) - (n - 1) / 2) / (n / 2)
    x, y, z = np.meshgrid(c, c, c, indexing="ij")
    r = np.sqrt(x * x + y * y + z * z)
    ripple = 0.65 + 0.35 * np.sin(7 * x + 2) * np.cos(5 * y - 1) * np.sin(6 * z + 0.5)
    density = np.clip(1 - r, 0, None) * ripple * 1.6
    temperature = np.clip(1.5 - 2.5 * np.sqrt(x * x + y * y + (z + 0.4) ** 2), 0, None)
    grids = []
    for name, data in (("density", density), ("temperature", temperature)):
        g = vdb.FloatGrid()
        g.copyFromArray(data.astype(np.float32), ijk=(-n // 2, -n // 2, -n // 2), tolerance=0)
        g.transform = vdb.createLinearTransform(voxelSize=0.05)
        g.name = name
        g.prune(0)
        grids.append(g)
    vdb.write(path, grids=grids)


def build_vdb_volume(out_dir):
    """(issue 31) Volume objects as Cycles 3.4 renders them: one OpenVDB file (smoke.vdb,
    written by write_smoke_vdb) imported twice, once without a material (Cycles' default
    volume: Principled Volume reading 'density'), once rotated and scaled to 0.75 (Cycles
    scales the density of a Volume in object space by 1/0.75) with a Principled
    Volume of its own (colour, density 4, blackbody from the 'temperature' grid), over a floor
    under a sun and a dim world; one volume bounce, step size from the voxels."""
    path = os.path.join(out_dir, "smoke.vdb")
    write_smoke_vdb(path)
    ms.floor(ms.cy.diffuse_material("floor", (0.6, 0.6, 0.6)))
    bpy.ops.object.volume_import(filepath=path, location=(-0.9, 0.3, 1.05))
    bpy.context.active_object.name = "puff"
    bpy.ops.object.volume_import(filepath=path, location=(0.9, 0.4, 0.9),
                                 rotation=(0.3, 0.0, 0.6))
    fire = bpy.context.active_object
    fire.name = "fire"
    fire.scale = (0.75, 0.75, 0.75)  # (the operator's scale is not applied)
    mat, nt, out = ms.bare_material("fire")
    vol = nt.nodes.new("ShaderNodeVolumePrincipled")
    vol.inputs["Color"].default_value = (0.8, 0.6, 0.4, 1.0)
    vol.inputs["Density"].default_value = 4.0
    vol.inputs["Blackbody Intensity"].default_value = 0.5
    nt.links.new(vol.outputs["Volume"], out.inputs["Volume"])
    fire.data.materials.append(mat)
    sun = ms.add_light("sun", "SUN", (0, 0, 5), energy=3.0, angle=0.05)
    ms.aim(sun, (-0.3, 0.6, -0.6))
    ms.cy.add_camera((0.0, -5.5, 2.2), (0.0, 0.3, 0.9), lens_mm=35.0)
    ms.cy.set_world_color((0.05, 0.06, 0.08))


AFTER_SETUP["vdb_volume"] = lambda scene: setattr(scene.cycles, "volume_bounces", 1)


def build_smoke(out_dir):
    """(issue 31) A smoke and fire simulation as Cycles 3.4 renders it: Quick Smoke (smoke and
    fire) on a small cube over a floor, baked into smoke_cache/ beside the .blend from frame
    -10 so that frame 1 shows eleven frames of it. The domain's own material (Principled
    Volume: density from 'density', blackbody from 'temperature') and grids (upscaled by the
    noise, heat kept at the base resolution) are what the add-on reads from the evaluated Fluid
    modifier; the domain is scaled unevenly and lifted. A sun, a dim world, one volume
    bounce."""
    ms.floor(ms.cy.diffuse_material("floor", (0.6, 0.6, 0.6)))
    bpy.ops.mesh.primitive_cube_add(size=0.5, location=(0.0, 0.4, 0.5))
    emitter = bpy.context.active_object
    emitter.name = "burner"
    emitter.data.materials.append(ms.cy.diffuse_material("burner", (0.2, 0.2, 0.2)))
    bpy.ops.object.select_all(action="DESELECT")
    emitter.select_set(True)
    bpy.context.view_layer.objects.active = emitter
    bpy.ops.object.quick_smoke(style="BOTH")
    domain = bpy.context.active_object
    domain.name = "smoke domain"
    domain.scale = (1.1, 0.9, 1.6)
    domain.location = (0.0, 0.4, 1.55)
    settings = next(m for m in domain.modifiers if m.type == "FLUID").domain_settings
    settings.resolution_max = 40
    settings.cache_type = "ALL"
    # A cache left by an earlier build of the scene would be read back as it is (a build
    # folder's stale bake failed the Z-test): bake from scratch every time.
    cache = os.path.join(out_dir, "smoke_cache")
    shutil.rmtree(cache, ignore_errors=True)
    settings.cache_directory = cache
    settings.cache_frame_start, settings.cache_frame_end = -10, 1
    scene = bpy.context.scene
    scene.frame_start = -10
    with bpy.context.temp_override(object=domain, active_object=domain):
        bpy.ops.fluid.bake_all()
    scene.frame_start = 1
    sun = ms.add_light("sun", "SUN", (0, 0, 5), energy=3.0, angle=0.05)
    ms.aim(sun, (-0.3, 0.6, -0.6))
    ms.cy.add_camera((0.0, -3.0, 1.3), (0.0, 0.4, 0.9), lens_mm=35.0)
    ms.cy.set_world_color((0.05, 0.06, 0.08))


AFTER_SETUP["smoke"] = lambda scene: setattr(scene.cycles, "volume_bounces", 1)


def build_many_lights(out_dir):
    """(issue 34) A street of 100 lights at night: 60 point lights (radius 0.05-0.15 m, 2-40 W)
    in rows of lanterns at heights 0.4-2.2 m and 40 spot lights (30-60 degree cones, 20-200 W)
    aimed down at the ground, all of different colours, over a floor with boxes and spheres
    (Lambert, one glossy metal) and a near-black world. Placed by a fixed random generator, so
    the scene is the same on every build. What many-light sampling is for: most lights are
    far from most shading points."""
    import random
    rng = random.Random(34)
    ms.floor(ms.cy.diffuse_material("ground", (0.5, 0.5, 0.5)), half=8.0)
    for i in range(8):
        x, y = rng.uniform(-4.0, 4.0), rng.uniform(-2.0, 6.0)
        size = rng.uniform(0.4, 1.2)
        ms.cy.add_box("box%d" % i, (x, y, size / 2), (size, size * 0.8, size),
                      rng.uniform(0, 90), ms.cy.diffuse_material(
                          "box%d" % i, (rng.uniform(0.2, 0.8), rng.uniform(0.2, 0.8),
                                        rng.uniform(0.2, 0.8))))
    for i in range(6):
        r = rng.uniform(0.25, 0.5)
        mat = (ms.cy.principled_material("metal%d" % i, base=(0.8, 0.8, 0.8), metallic=1.0,
                                         roughness=0.25) if i == 0 else
               ms.cy.diffuse_material("ball%d" % i, (0.7, 0.7, 0.7)))
        ms.add_sphere("ball%d" % i, (rng.uniform(-4, 4), rng.uniform(-2, 6), r), r, mat,
                      segments=24, rings=12)

    def colour():
        c = [rng.uniform(0.3, 1.0) for _ in range(3)]
        c[rng.randrange(3)] = 1.0
        return tuple(c)

    for i in range(60):
        ms.add_light("lantern%d" % i, "POINT",
                     (rng.uniform(-6, 6), rng.uniform(-3, 9), rng.uniform(0.4, 2.2)),
                     color=colour(), energy=rng.uniform(2.0, 40.0),
                     shadow_soft_size=rng.uniform(0.05, 0.15))
    for i in range(40):
        spot = ms.add_light("street%d" % i, "SPOT",
                            (rng.uniform(-6, 6), rng.uniform(-3, 9), rng.uniform(2.0, 3.5)),
                            color=colour(), energy=rng.uniform(20.0, 200.0),
                            spot_size=math.radians(rng.uniform(30, 60)),
                            spot_blend=rng.uniform(0.1, 0.5), shadow_soft_size=0.1)
        x, y, _ = spot.location
        ms.aim(spot, (x + rng.uniform(-1, 1), y + rng.uniform(-1, 1), 0.0))
    ms.cy.add_camera((0.0, -7.0, 3.2), (0.0, 2.5, 0.3), lens_mm=30.0)
    ms.cy.set_world_color((0.002, 0.002, 0.003))


def build_world_camera(out_dir):
    """A world that shows the camera one background and lights the scene with another, the
    Light Path trick Blender users reach for: Mix Shader of an orange Background (what bounces
    and glossy reflections see) and a blue one, by Is Camera Ray. A Lambert floor and sphere
    lit by the world alone, and a sharp-ish metal sphere that mirrors the orange one."""
    ms.floor(ms.cy.diffuse_material("floor", (0.7, 0.7, 0.7)))
    ms.add_sphere("ball", (-0.6, 0.2, 0.6), 0.6, ms.cy.diffuse_material("ball", (0.8, 0.8, 0.8)))
    ms.add_sphere("mirror", (0.8, 0.0, 0.5), 0.5, ms.cy.principled_material(
        "mirror", base=(0.9, 0.9, 0.9), metallic=1.0, roughness=0.1))
    world = bpy.data.worlds.new("World")
    world.use_nodes = True
    nt = world.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputWorld")
    lighting = nt.nodes.new("ShaderNodeBackground")
    lighting.inputs["Color"].default_value = (1.0, 0.55, 0.2, 1.0)
    lighting.inputs["Strength"].default_value = 1.0
    seen = nt.nodes.new("ShaderNodeBackground")
    seen.inputs["Color"].default_value = (0.1, 0.25, 0.8, 1.0)
    seen.inputs["Strength"].default_value = 1.0
    path = nt.nodes.new("ShaderNodeLightPath")
    mix = nt.nodes.new("ShaderNodeMixShader")
    nt.links.new(path.outputs["Is Camera Ray"], mix.inputs["Fac"])
    nt.links.new(lighting.outputs["Background"], mix.inputs[1])
    nt.links.new(seen.outputs["Background"], mix.inputs[2])
    nt.links.new(mix.outputs["Shader"], out.inputs["Surface"])
    bpy.context.scene.world = world
    ms.cy.add_camera((0.0, -4.0, 1.6), (0.0, 0.2, 0.5), lens_mm=35.0)
