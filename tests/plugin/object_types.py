"""One Blender 3.4 scene holding an object of every type Blender has (issue 28), for the tests
that render it through the add-on headless (test_object_types.py) and with F12 (test_ui.py).

    build(scene=None) -> scene

Starts from Blender's default scene (the cube, the light, the camera) as a user's file does and
adds, each in its own spot so that nothing hides the cube:

- Empties of every display type, one of them a Track To target of the camera, one the camera's
  depth-of-field focus object (DOF itself off, so the image compares with the plain render), one
  with an image (an Image Empty, the reference-image kind);
- a force field (an Empty with a field), light probes (reflection cubemap, planar, irradiance grid), a
  speaker, an armature with a bone, a lattice;
- a Grease Pencil object with a stroke, a hair Curves object, a point cloud, a Volume (no grid);
- geometry the OBJ exporter converts: a text, a metaball, a NURBS surface, a bevelled curve;
- a floor mesh without a material (Cycles' default surface, not the material of the object
  written before it);
- a collection holding one object of each of these types (and a mesh with a material), and two
  collection instances of it: one plain, one of them nested in a second instanced collection.

Every object without surface geometry must be skipped before anything touches its materials;
the meshes, text, metaball, surface and curve must render.
"""

import math

import bpy

EMPTY_DISPLAY_TYPES = ('PLAIN_AXES', 'ARROWS', 'SINGLE_ARROW', 'CIRCLE', 'CUBE', 'SPHERE',
                       'CONE', 'IMAGE')
# Object types the scene holds beyond the default scene's MESH, LIGHT and CAMERA.
EXTRA_TYPES = ('EMPTY', 'LIGHT_PROBE', 'SPEAKER', 'ARMATURE', 'LATTICE', 'GPENCIL', 'CURVES',
               'POINTCLOUD', 'VOLUME', 'FONT', 'META', 'SURFACE', 'CURVE')


def _material(name, color):
    m = bpy.data.materials.new(name)
    # use_nodes makes a Principled BSDF, or a Principled Volume while a volume is active.
    active = bpy.context.view_layer.objects.active
    bpy.context.view_layer.objects.active = None
    m.use_nodes = True
    bpy.context.view_layer.objects.active = active
    for node in m.node_tree.nodes:
        for socket in ("Base Color", "Color"):
            if socket in node.inputs:
                node.inputs[socket].default_value = (*color, 1.0)
    m.diffuse_color = (*color, 1.0)
    return m


def _link(ob, collection):
    collection.objects.link(ob)
    return ob


def _grease_pencil(name, collection):
    gp = bpy.data.grease_pencils.new(name)
    layer = gp.layers.new("Lines")
    frame = layer.frames.new(1)
    stroke = frame.strokes.new()
    stroke.points.add(3)
    for i, p in enumerate(stroke.points):
        p.co = (i * 0.3, 0.0, 0.2 * i)
    gp_mat = bpy.data.materials.new(name + " stroke")
    bpy.data.materials.create_gpencil_data(gp_mat)
    gp.materials.append(gp_mat)
    return _link(bpy.data.objects.new(name, gp), collection)


def _hair_curves(name, collection):
    ob = _from_operator(bpy.ops.object.curves_random_add, name, collection)
    ob.scale = (0.15, 0.15, 0.15)  # Blender's random hair ball would hide the scene
    ob.data.materials.append(_material(name + " material", (0.8, 0.6, 0.2)))
    return ob


def _point_cloud(name, collection):
    # Point clouds are an experimental type in Blender 3.4 (Preferences > Experimental).
    bpy.context.preferences.experimental.use_new_point_cloud_type = True
    ob = _from_operator(bpy.ops.object.pointcloud_add, name, collection)
    ob.scale = (0.3, 0.3, 0.3)
    ob.data.materials.append(_material(name + " material", (0.2, 0.8, 0.6)))
    return ob


def _volume(name, collection):
    ob = _from_operator(bpy.ops.object.volume_add, name, collection)  # no grid file
    ob.data.materials.append(_material(name + " material", (0.5, 0.5, 0.9)))
    return ob


def _text(name, collection):
    text = bpy.data.curves.new(name, 'FONT')
    text.body = "glint"
    text.size = 0.4
    text.extrude = 0.02
    text.materials.append(_material(name + " material", (0.9, 0.9, 0.2)))
    return _link(bpy.data.objects.new(name, text), collection)


def _metaball(name, collection):
    mb = bpy.data.metaballs.new(name)
    mb.elements.new().radius = 0.3
    mb.resolution = 0.1
    mb.render_resolution = 0.1
    mb.materials.append(_material(name + " material", (0.2, 0.9, 0.2)))
    return _link(bpy.data.objects.new(name, mb), collection)


def _from_operator(add, name, collection):
    """The object an Add-menu operator makes, renamed and moved into `collection`."""
    add()
    ob = bpy.context.active_object
    for c in list(ob.users_collection):
        c.objects.unlink(ob)
    ob.name = name
    if ob.data is not None:
        ob.data.name = name
    return _link(ob, collection)


def _surface(name, collection):
    """Blender's Add > Surface > NURBS Surface (a 4 x 4 patch)."""
    ob = _from_operator(lambda: bpy.ops.surface.primitive_nurbs_surface_surface_add(radius=0.3),
                        name, collection)
    ob.data.materials.append(_material(name + " material", (0.9, 0.3, 0.9)))
    return ob


def _curve(name, collection):
    cu = bpy.data.curves.new(name, 'CURVE')
    cu.dimensions = '3D'
    cu.bevel_depth = 0.05
    spline = cu.splines.new('BEZIER')
    spline.bezier_points.add(1)
    spline.bezier_points[0].co = (0, 0, 0)
    spline.bezier_points[1].co = (0.6, 0, 0.3)
    for p in spline.bezier_points:
        p.handle_left_type = p.handle_right_type = 'AUTO'
    cu.materials.append(_material(name + " material", (0.3, 0.3, 0.9)))
    return _link(bpy.data.objects.new(name, cu), collection)


def _no_geometry_objects(prefix, collection):
    """An object of every type that has no surface geometry glint can render."""
    obs = []
    image = bpy.data.images.new(prefix + " reference", 4, 4)
    for t in EMPTY_DISPLAY_TYPES:
        ob = bpy.data.objects.new("%s Empty %s" % (prefix, t.lower()), None)
        ob.empty_display_type = t
        if t == 'IMAGE':
            ob.data = image
        obs.append(_link(ob, collection))
    obs.append(_from_operator(lambda: bpy.ops.object.effector_add(type='FORCE'),
                              prefix + " Force Field", collection))
    for kind in ('CUBE', 'PLANAR', 'GRID'):
        probe = bpy.data.lightprobes.new("%s probe %s" % (prefix, kind.lower()), kind)
        obs.append(_link(bpy.data.objects.new(probe.name, probe), collection))
    speaker = bpy.data.speakers.new(prefix + " Speaker")
    obs.append(_link(bpy.data.objects.new(speaker.name, speaker), collection))
    arm = bpy.data.armatures.new(prefix + " Armature")
    obs.append(_link(bpy.data.objects.new(arm.name, arm), collection))
    lattice = bpy.data.lattices.new(prefix + " Lattice")
    obs.append(_link(bpy.data.objects.new(lattice.name, lattice), collection))
    obs.append(_grease_pencil(prefix + " Grease Pencil", collection))
    obs.append(_hair_curves(prefix + " Hair", collection))
    obs.append(_point_cloud(prefix + " Point Cloud", collection))
    obs.append(_volume(prefix + " Volume", collection))
    return obs


def _geometry_objects(prefix, collection):
    return [_text(prefix + " Text", collection), _metaball(prefix + " Metaball", collection),
            _surface(prefix + " Surface", collection), _curve(prefix + " Curve", collection)]


def _add_armature_bone(ob):
    """A bone needs edit mode; done once the armature is in the view layer."""
    bpy.context.view_layer.objects.active = ob
    bpy.ops.object.mode_set(mode='EDIT')
    bone = ob.data.edit_bones.new("Bone")
    bone.head, bone.tail = (0, 0, 0), (0, 0, 0.5)
    bpy.ops.object.mode_set(mode='OBJECT')


def build(scene=None):
    """Adds every object type (see the module doc) to `scene` (default: the context's), which
    should hold Blender's default scene. Returns the scene."""
    scene = scene or bpy.context.scene
    root = scene.collection

    # The user's objects, spread on a ring around the default cube.
    mine = _no_geometry_objects("Scene", root) + _geometry_objects("Scene", root)
    for i, ob in enumerate(mine):
        a = 2 * math.pi * i / len(mine)
        ob.location = (3.2 * math.cos(a), 3.2 * math.sin(a), 0.0)
    _add_armature_bone(bpy.data.objects["Scene Armature"])

    cam = scene.camera
    target = bpy.data.objects["Scene Empty plain_axes"]
    target.location = (0.0, 0.0, 0.0)  # the cube's centre: the view stays on the cube
    track = cam.constraints.new('TRACK_TO')
    track.target = target
    track.track_axis, track.up_axis = 'TRACK_NEGATIVE_Z', 'UP_Y'
    cam.data.dof.focus_object = bpy.data.objects["Scene Empty sphere"]
    cam.data.dof.use_dof = False

    # A floor without a material (Cycles' default surface), below the cube.
    floor = bpy.data.meshes.new("Floor")
    floor.from_pydata([(-6, -6, -1), (6, -6, -1), (6, 6, -1), (-6, 6, -1)], [], [(0, 1, 2, 3)])
    root.objects.link(bpy.data.objects.new("Floor", floor))

    # A collection of every type, instanced twice (once through a second, nested instance).
    kit = bpy.data.collections.new("Every Type")
    for ob in _no_geometry_objects("Kit", kit) + _geometry_objects("Kit", kit):
        ob.location = (0.0, 0.0, 0.0)
    block = bpy.data.meshes.new("Kit Block")
    block.from_pydata([(-.2, -.2, 0), (.2, -.2, 0), (.2, .2, 0), (-.2, .2, 0),
                       (-.2, -.2, .4), (.2, -.2, .4), (.2, .2, .4), (-.2, .2, .4)], [],
                      [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6),
                       (3, 0, 4, 7)])
    block.materials.append(_material("Kit Block material", (0.9, 0.1, 0.1)))
    _link(bpy.data.objects.new("Kit Block", block), kit)
    inst = bpy.data.objects.new("Every Type instance", None)
    inst.instance_type = 'COLLECTION'
    inst.instance_collection = kit
    inst.location = (2.0, -0.6, 0.0)
    root.objects.link(inst)
    outer = bpy.data.collections.new("Every Type nested")
    nested = bpy.data.objects.new("Every Type nested instance", None)
    nested.instance_type = 'COLLECTION'
    nested.instance_collection = kit
    outer.objects.link(nested)
    outer_inst = bpy.data.objects.new("Every Type outer instance", None)
    outer_inst.instance_type = 'COLLECTION'
    outer_inst.instance_collection = outer
    outer_inst.location = (-0.6, -2.0, 0.0)
    root.objects.link(outer_inst)
    return scene


def types_in(scene):
    """The object types the scene's view layer holds, instances included."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    return {inst.object.type for inst in depsgraph.object_instances} | \
        {ob.type for ob in scene.objects}
