"""Blender scene -> glint scene folder (one frame).

    export_frame(depsgraph, out_dir, warn) -> Export

writes into out_dir:
    scene.obj, scene.mtl   Blender's OBJ exporter (meshes, modifiers applied for render)
    scene.pov              camera, world, lights and `obj_file { "scene.obj" }`
    textures/              world images that exist only inside Blender (packed, generated)
    command.txt            the glint command line that renders it (binary `glint`)

Must run on Blender's main thread (the OBJ exporter is an operator); the engine arranges that.

Axes. The OBJ is written with forward -Z, up Y, so a Blender point (x, y, z) is (x, z, -y) in the
file, and glint's obj_file mirrors z into POV-Ray's left-handed axes: a Blender point lands at POV
(x, z, y). Everything written here goes through to_pov() for the same reason. The swap of y and z
is a reflection, so the camera is written with explicit direction/right/up vectors (the image's
right is the `right` vector whatever the handedness) rather than with look_at.

Cameras: perspective and orthographic, with Blender's sensor fit, lens shift and pixel aspect
(all read from calc_matrix_camera). Panoramic cameras fail the export. Features glint does not
have (depth of field, motion blur, transparent film, ...) are reported through warn(), once each.
"""

import math
import os
import re
import shlex

import bpy
from mathutils import Vector

from . import images, materials

SCENE_NAME = "scene"


class ExportError(Exception):
    """A scene the add-on cannot hand to glint; the message is shown to the user."""


class Export:
    """What export_frame wrote: the scene file, the output image glint will write, the image
    size, glint's arguments (without the binary), and `names`: for each kind of thing glint
    names in its messages ('object', 'material'), the exported name -> what the user knows it
    as in Blender (translate_message)."""

    def __init__(self, out_dir, scene_path, output_path, width, height, argv, names=None):
        self.out_dir = out_dir
        self.scene_path = scene_path
        self.output_path = output_path
        self.width = width
        self.height = height
        self.argv = argv
        self.names = names or {}


_LOCATED = re.compile(r"^(?P<path>[^:]+?)(?::(?P<line>\d+):(?P<col>\d+))?: (?P<rest>.*)$")
_NAMED = re.compile(r"\b(?P<kind>object|material) '(?P<name>[^']*)'")


def _in_export(path, export):
    """Whether a message's location is a file of the export (which still exists while the
    render's messages are read)."""
    full = path if os.path.isabs(path) else os.path.join(export.out_dir, path)
    return (os.path.abspath(full).startswith(os.path.join(os.path.abspath(export.out_dir), ""))
            and os.path.exists(full))


def translate_message(line, export):
    """One line glint printed, as the user can read it: the location in the temporary export
    (which is gone once the render ends) is dropped, and the OBJ object and MTL material names
    become the Blender object (with its mesh) and material."""
    text = line.strip()
    m = _LOCATED.match(text)
    if m and _in_export(m.group("path"), export):
        text = m.group("rest")
        if text.startswith("warning: "):
            text = text[len("warning: "):]  # the report itself is a warning
    text = text.replace(os.path.join(export.out_dir, ""), "")

    def name(match):
        known = export.names.get(match.group("kind"), {}).get(match.group("name"))
        return known if known is not None else match.group(0)
    return _NAMED.sub(name, text)


def translate_lines(lines, export):
    """translate_message over glint's output; the source line and caret glint quotes under a
    message located in the temporary export (a line of scene.pov or scene.obj) are left out."""
    out, skip = [], 0
    for line in lines:
        if skip and line.startswith("  "):
            skip -= 1
            continue
        skip = 0
        m = _LOCATED.match(line.strip())
        if m and _in_export(m.group("path"), export):
            skip = 2
        out.append(translate_message(line, export))
    return out


# ----------------------------------------------------------------------------- helpers

def to_pov(v):
    """Blender world point/direction -> glint POV coordinates (see the module doc)."""
    return (v[0], v[2], v[1])


def fmt(v):
    return "<%.9g, %.9g, %.9g>" % tuple(v)


def pov_string(path):
    return '"%s"' % path.replace("\\", "\\\\").replace('"', '\\"')


def render_size(scene):
    """The image size Blender renders: resolution times percentage (integer, as Blender)."""
    r = scene.render
    return (max(1, r.resolution_x * r.resolution_percentage // 100),
            max(1, r.resolution_y * r.resolution_percentage // 100))


def _follow(socket):
    """The node feeding an input socket, through reroutes; None when unlinked."""
    while socket.is_linked:
        link = socket.links[0]
        if not link.is_valid or link.is_muted:
            return None, None
        node = link.from_node
        if node.type == 'REROUTE':
            socket = node.inputs[0]
            continue
        return node, link.from_socket
    return None, None


def _active_output(node_tree, kind):
    outputs = [n for n in node_tree.nodes if n.type == kind]
    for n in outputs:
        if n.is_active_output and n.target in {'ALL', 'CYCLES'}:
            return n
    for n in outputs:
        if n.target in {'ALL', 'CYCLES'}:
            return n
    return outputs[0] if outputs else None


# ----------------------------------------------------------------------------- camera

def camera_block(depsgraph, width, height, warn):
    scene = depsgraph.scene_eval
    cam_ob = scene.camera
    if cam_ob is None:
        raise ExportError("the scene has no camera")
    cam = cam_ob.data
    if cam.type == 'PANO':
        raise ExportError("camera '%s' is panoramic: glint's add-on renders perspective and "
                          "orthographic cameras only" % cam_ob.name)
    r = scene.render
    if cam.dof.use_dof:
        warn("depth of field (camera '%s') is not supported by glint: rendered all in focus"
             % cam_ob.name)
    if r.use_motion_blur:
        warn("motion blur is not supported by glint: rendered without it")
    if r.use_multiview:
        warn("stereoscopy/multiview is not supported by glint: only the scene camera is "
             "rendered")
    proj = cam_ob.calc_matrix_camera(depsgraph, x=width, y=height,
                                     scale_x=r.pixel_aspect_x, scale_y=r.pixel_aspect_y)
    inv = proj.inverted()
    m = cam_ob.matrix_world
    rot = m.to_3x3().normalized()
    x_axis, y_axis, z_axis = (rot.col[0].normalized(), rot.col[1].normalized(),
                              rot.col[2].normalized())
    loc = m.translation

    def unproject(u, v, z_ndc):
        p = inv @ Vector((u, v, z_ndc, 1.0))
        return Vector((p.x / p.w, p.y / p.w, p.z / p.w))

    if cam.type == 'ORTHO':
        # Rays run along -Z from the camera plane; the view spans 2/p00 x 2/p11 around the
        # (shifted) centre.
        c = unproject(0.0, 0.0, -1.0)
        w = unproject(1.0, 0.0, -1.0).x - unproject(-1.0, 0.0, -1.0).x
        h = unproject(0.0, 1.0, -1.0).y - unproject(0.0, -1.0, -1.0).y
        origin = loc + x_axis * c.x + y_axis * c.y
        direction = -z_axis
        kind = "orthographic"
    else:
        # Camera-space rays through the image centre and edges, scaled to z = -1.
        def ray(u, v):
            p = unproject(u, v, -1.0)
            return p / -p.z
        c = ray(0.0, 0.0)
        w = ray(1.0, 0.0).x - ray(-1.0, 0.0).x
        h = ray(0.0, 1.0).y - ray(0.0, -1.0).y
        origin = loc
        direction = x_axis * c.x + y_axis * c.y - z_axis
        kind = "perspective"
    right = x_axis * w
    up = y_axis * h
    return ("camera {  // '%s' (%s, %d x %d)\n  %s\n  location %s\n  direction %s\n"
            "  right %s\n  up %s\n}\n" % (cam_ob.name, cam.type.lower(), width, height, kind,
                                          fmt(to_pov(origin)), fmt(to_pov(direction)),
                                          fmt(to_pov(right)), fmt(to_pov(up))))


# ----------------------------------------------------------------------------- world

_IMAGE_KEYWORDS = {".exr": "exr", ".hdr": "hdr", ".png": "png", ".jpg": "jpeg", ".jpeg": "jpeg",
                   ".tif": "tiff", ".tiff": "tiff", ".tga": "tga", ".bmp": "bmp", ".ppm": "ppm",
                   ".pgm": "pgm", ".gif": "gif"}
_FORMAT_EXTENSIONS = {'OPEN_EXR': ".exr", 'OPEN_EXR_MULTILAYER': ".exr", 'HDR': ".hdr",
                      'PNG': ".png", 'JPEG': ".jpg", 'TIFF': ".tif", 'TARGA': ".tga",
                      'TARGA_RAW': ".tga", 'BMP': ".bmp"}


def image_file(image, out_dir, warn):
    """A file glint can read holding `image`: its own file when it is saved and unchanged,
    else a copy written into out_dir/textures (packed images byte for byte, generated or
    modified ones saved by Blender, float as OpenEXR)."""
    path = bpy.path.abspath(image.filepath_raw, library=image.library) if image.filepath_raw \
        else ""
    tex_dir = os.path.join(out_dir, "textures")
    safe = bpy.path.clean_name(image.name)
    if image.packed_file is not None:
        ext = os.path.splitext(path)[1].lower() or _FORMAT_EXTENSIONS.get(image.file_format,
                                                                          ".png")
        os.makedirs(tex_dir, exist_ok=True)
        dest = os.path.join(tex_dir, safe + ext)
        with open(dest, "wb") as f:
            f.write(image.packed_file.data)
        return dest
    if image.source == 'FILE' and path and os.path.isfile(path) and not image.is_dirty:
        return path
    if not image.has_data and image.source == 'FILE':
        raise ExportError("image '%s' cannot be read (%s)" % (image.name, path or "no file"))
    os.makedirs(tex_dir, exist_ok=True)
    ext = ".exr" if image.is_float else ".png"
    dest = os.path.join(tex_dir, safe + ext)
    copy = image.copy()
    try:
        copy.file_format = 'OPEN_EXR' if image.is_float else 'PNG'
        copy.filepath_raw = dest
        copy.save(filepath=dest)
    finally:
        bpy.data.images.remove(copy)
    return dest


def _environment_text(env, strength, out_dir, warn, missing):
    image = env.image
    problem = None if image is None else images.image_problem(image)
    if image is None or problem is not None:  # Cycles' magenta
        if image is None:
            warn("world: the Environment Texture has no image: the world renders magenta, as "
                 "in Cycles")
        else:
            missing.add(image, problem, "the world")  # one warning an image: missing.report
        return "background { color rgb %s }\n" % fmt(
            tuple(c * strength for c in images.MISSING_RGBA[:3]))
    if env.projection != 'EQUIRECTANGULAR':
        warn("world: Environment Texture projection %s is not supported (equirectangular "
             "only): the world renders black" % env.projection)
        return "background { color rgb 0 }\n"
    rotate_deg = 0.0
    vec_node, vec_socket = _follow(env.inputs["Vector"])
    if vec_node is not None:
        ok = vec_node.type == 'MAPPING' and vec_node.vector_type in {'POINT', 'VECTOR'}
        if ok:
            loc_in, rot_in = vec_node.inputs.get("Location"), vec_node.inputs["Rotation"]
            scale_in = vec_node.inputs["Scale"]
            if rot_in.is_linked or scale_in.is_linked or (loc_in and loc_in.is_linked):
                ok = False
            else:
                rx, ry, rz = rot_in.default_value
                sx, sy, sz = scale_in.default_value
                if abs(rx) > 1e-6 or abs(ry) > 1e-6:
                    warn("world: the Mapping node's X/Y rotation is not supported: only its Z "
                         "rotation is used")
                if not (abs(sx - sy) < 1e-6 and abs(sy - sz) < 1e-6 and sx > 0):
                    warn("world: the Mapping node's non-uniform scale is not supported: ignored")
                if (vec_node.vector_type == 'POINT' and loc_in is not None
                        and Vector(loc_in.default_value).length > 1e-6):
                    warn("world: the Mapping node's location is not supported: ignored")
                rotate_deg = math.degrees(rz)
            src, _ = _follow(vec_node.inputs["Vector"])
            if src is None or src.type != 'TEX_COORD':
                ok = False
        elif vec_node.type == 'TEX_COORD':
            ok = True
        if not ok:
            warn("world: the Environment Texture's vector input (%s) is not supported: the "
                 "image is mapped by direction, Z rotation of a Mapping node only"
                 % vec_node.name)
            rotate_deg = 0.0 if vec_node.type != 'MAPPING' else rotate_deg
    path = image_file(image, out_dir, warn)
    ext = os.path.splitext(path)[1].lower()
    keyword = _IMAGE_KEYWORDS.get(ext)
    if keyword is None:
        raise ExportError("world image '%s': glint cannot read %s files" % (image.name, ext))
    if env.interpolation == 'Closest':
        interp = ""
    else:
        interp = " interpolate 2"
        if env.interpolation in {'Cubic', 'Smart'}:
            warn("world: %s interpolation of the Environment Texture is rendered as linear"
                 % env.interpolation)
    rotate = " rotate <0, %.9g, 0>" % rotate_deg if abs(rotate_deg) > 1e-9 else ""
    # Blender's equirect u runs the other way round from POV-Ray's map_type 1 once y and z are
    # swapped: the mirror scale undoes it (docs/pbr-mapping.md, "Blender world textures").
    return ("background { color rgb 0 }\n"
            "sky_sphere {\n  pigment { image_map { %s %s map_type 1%s } }\n"
            "  scale <-1, 1, 1>%s\n  emission %.9g\n}\n"
            % (keyword, pov_string(path), interp, rotate, strength))


def world_text(scene, out_dir, warn, missing):
    world = scene.world
    black = "background { color rgb 0 }\n"
    if world is None:
        return black
    if not world.use_nodes or world.node_tree is None:
        return "background { color rgb %s }\n" % fmt(world.color)
    out = _active_output(world.node_tree, 'OUTPUT_WORLD')
    if out is None:
        return black
    if out.inputs["Volume"].is_linked:
        warn("world: volumes are not supported: the world volume is left out")
    node, _ = _follow(out.inputs["Surface"])
    if node is None:
        return black
    if node.type != 'BACKGROUND':
        warn("world: shader '%s' (%s) is not supported (Background only): the world renders "
             "black" % (node.name, node.type))
        return black
    strength = node.inputs["Strength"].default_value
    if node.inputs["Strength"].is_linked:
        warn("world: a linked Background strength is not supported: using %.3g" % strength)
    cnode, _ = _follow(node.inputs["Color"])
    if cnode is None:
        c = node.inputs["Color"].default_value
        return "background { color rgb %s }\n" % fmt((c[0] * strength, c[1] * strength,
                                                      c[2] * strength))
    if cnode.type == 'TEX_ENVIRONMENT':
        return _environment_text(cnode, strength, out_dir, warn, missing)
    c = node.inputs["Color"].default_value
    warn("world: color from node '%s' (%s) is not supported (a color or an Environment "
         "Texture): using the Background's own color" % (cnode.name, cnode.type))
    return "background { color rgb %s }\n" % fmt((c[0] * strength, c[1] * strength,
                                                  c[2] * strength))


# ----------------------------------------------------------------------------- lights

def light_block(name, light, matrix, warn, ob=None):
    """One blender_light block (the shared contract; glint's parser reads it). `ob`, the light's
    object, carries its ray visibility: Camera ticked makes the light visible to the camera
    (Blender 3.4's default is off); the settings glint does not have are warned."""
    kind = light.type.lower()
    if kind not in {"point", "spot", "sun", "area"}:
        warn("light '%s': type %s is not supported: left out" % (name, light.type))
        return ""
    if light.use_nodes and light.node_tree is not None and len(light.node_tree.nodes) > 2:
        warn("light '%s': light node trees are not supported: the light's color and power "
             "are used" % name)
    # Cycles' own light settings live in an add-on property group that the evaluated copy does
    # not carry over (it reads the defaults): take them from the original datablock.
    cyc = getattr(ob.data if ob is not None and ob.data is not None else light, "cycles", None)
    if cyc is not None and getattr(cyc, "is_portal", False):
        warn("light '%s': portals are not supported: left out" % name)
        return ""
    if light.energy < 0:
        warn("light '%s': negative power is not supported: left out" % name)
        return ""
    unsupported = []
    if cyc is not None and not getattr(cyc, "cast_shadow", True):
        unsupported.append("Cast Shadow off")
    if cyc is not None and not getattr(cyc, "use_multiple_importance_sampling", True):
        unsupported.append("Multiple Importance off")
    if ob is not None:
        for attr, label in (("visible_diffuse", "Diffuse"), ("visible_glossy", "Glossy"),
                            ("visible_transmission", "Transmission"),
                            ("visible_volume_scatter", "Volume Scatter")):
            if not getattr(ob, attr, True):
                unsupported.append("ray visibility %s off" % label)
    if unsupported:
        warn("light '%s': %s not supported: rendered as if on" % (name, ", ".join(unsupported)))
    rot = matrix.to_3x3()
    loc = matrix.translation
    direction = (rot @ Vector((0.0, 0.0, -1.0))).normalized()
    lines = ["blender_light {  // '%s'" % name, "  " + kind]
    if kind != "sun":
        lines.append("  location %s" % fmt(to_pov(loc)))
    if kind != "point":
        lines.append("  direction %s" % fmt(to_pov(direction)))
    lines.append("  color rgb %s" % fmt(light.color))
    lines.append("  power %.9g" % light.energy)
    if kind in {"point", "spot"}:
        lines.append("  radius %.9g" % light.shadow_soft_size)
    if kind == "spot":
        lines.append("  spot_size %.9g  spot_blend %.9g" % (math.degrees(light.spot_size),
                                                            light.spot_blend))
    if kind == "sun":
        lines.append("  angle %.9g" % math.degrees(light.angle))
    if kind == "area":
        ax, ay = rot.col[0], rot.col[1]
        sx = light.size
        sy = light.size if light.shape in {'SQUARE', 'DISK'} else light.size_y
        shape = "rectangle" if light.shape in {'SQUARE', 'RECTANGLE'} else "ellipse"
        if not (sx * ax.length > 0 and sy * ay.length > 0):
            warn("light '%s': an area light of zero size emits nothing: left out" % name)
            return ""
        lines.append("  shape %s" % shape)
        lines.append("  size <%.9g, %.9g>" % (sx * ax.length, sy * ay.length))
        lines.append("  axis_x %s  axis_y %s" % (fmt(to_pov(ax.normalized())),
                                                 fmt(to_pov(ay.normalized()))))
        lines.append("  spread %.9g" % math.degrees(light.spread))
    if ob is not None and getattr(ob, "visible_camera", False):
        lines.append("  visible_camera on")
    lines.append("}")
    return "\n".join(lines) + "\n"


def lights_text(depsgraph, warn):
    blocks = []
    for inst in depsgraph.object_instances:
        ob = inst.object
        if ob.type != 'LIGHT':
            continue
        name = ob.original.name if ob.original else ob.name
        blocks.append(light_block(name, ob.data, inst.matrix_world.copy(), warn,
                                  ob.original if ob.original else ob))
    return "".join(blocks)


# ----------------------------------------------------------------------------- meshes

def _context_override(scene, view_layer):
    wm = bpy.context.window_manager
    kw = {"scene": scene, "view_layer": view_layer}
    window = bpy.context.window or (wm.windows[0] if wm and wm.windows else None)
    if window is not None:
        kw["window"] = window
    return bpy.context.temp_override(**kw)


def export_obj(depsgraph, path):
    """Meshes with modifiers as the render sees them, through Blender's OBJ exporter (which
    evaluates the view layer itself, hence the frame_set: the render's frame may not have been
    evaluated for the view layer yet). Faces go out as Blender holds them: the exporter's own
    triangulation cuts quads on the shorter diagonal, Cycles renders Blender's cut (0-2 unless
    the quad is concave there), and glint's OBJ importer makes Blender's cut, which decides how
    a smooth quad's normals interpolate."""
    scene = depsgraph.scene
    view_layer = depsgraph.view_layer
    with _context_override(scene, view_layer):
        scene.frame_set(scene.frame_current, subframe=scene.frame_subframe)
        result = bpy.ops.wm.obj_export(
            filepath=path, export_animation=False, export_eval_mode='DAG_EVAL_RENDER',
            apply_modifiers=True, forward_axis='NEGATIVE_Z', up_axis='Y', global_scale=1.0,
            export_selected_objects=False, export_uv=True, export_normals=True,
            export_colors=False, export_materials=True, export_pbr_extensions=True,
            path_mode='ABSOLUTE', export_triangulated_mesh=False, export_curves_as_nurbs=False,
            export_object_groups=False, export_material_groups=False,
            export_vertex_groups=False, export_smooth_groups=False)
    if 'FINISHED' not in result or not os.path.isfile(path):
        raise ExportError("Blender's OBJ exporter failed (%s)" % ", ".join(result))


# Cycles renders an object without a material with its default surface, a Diffuse BSDF of 0.8
# grey. Blender's OBJ exporter writes no `usemtl` for such an object (so OBJ readers give it the
# material of the object before it, which usemtl statements carry over) or an empty one (a
# geometry-nodes instance); both get this material, written after the rewritten MTL.
DEFAULT_SURFACE = "glint_blender_default_surface"
DEFAULT_SURFACE_MTL = ("\nnewmtl %s\n# Cycles' surface for objects without a material: Diffuse "
                       "BSDF, 0.8 grey\nKd 0.800000 0.800000 0.800000\nKs 0.000000 0.000000 "
                       "0.000000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\nd 1.000000\n"
                       "illum 1\n" % DEFAULT_SURFACE)


def give_default_surface(obj_path, mtl_path):
    """Gives every OBJ object whose faces come before any `usemtl` (and every empty `usemtl`)
    the DEFAULT_SURFACE material, added to the MTL file. Returns whether it was needed."""
    with open(obj_path, "rb") as f:
        data = f.read()
    tag = b"usemtl " + DEFAULT_SURFACE.encode() + b"\n"
    parts = data.split(b"\no ")
    changed = False
    for i in range(1, len(parts)):
        chunk = parts[i]
        first_face, first_usemtl = chunk.find(b"\nf "), chunk.find(b"\nusemtl ")
        if first_face >= 0 and (first_usemtl < 0 or first_usemtl > first_face):
            name_end = chunk.find(b"\n") + 1
            parts[i] = chunk[:name_end] + tag + chunk[name_end:]
            changed = True
    data = b"\no ".join(parts)
    if b"\nusemtl \n" in data:
        data = data.replace(b"\nusemtl \n", b"\n" + tag)
        changed = True
    if not changed:
        return False
    with open(obj_path, "wb") as f:
        f.write(data)
    with open(mtl_path, "a", encoding="utf-8") as f:
        f.write(DEFAULT_SURFACE_MTL)
    return True


def _has_faces(obj_path):
    """Whether the OBJ has a face (glint rejects an obj_file without one; Blender renders an
    empty scene as the world alone)."""
    with open(obj_path, "rb") as f:
        return any(line.startswith(b"f ") for line in f)


# Objects with geometry that the OBJ exchange cannot carry, by type: what the user is told.
_LEFT_OUT = {
    "CURVES": "hair curves are not supported by glint",
    "POINTCLOUD": "point clouds are not supported by glint",
    "VOLUME": "volume objects are not supported by glint",
    "GPENCIL": "Grease Pencil objects are not drawn by glint",
}


def left_out_warnings(depsgraph, warn):
    """One warning for each object type glint leaves out, naming its objects (instances
    included, each object once). Only the type is read: never an object's materials."""
    names = {}
    for inst in depsgraph.object_instances:
        ob = inst.object
        if ob.type in _LEFT_OUT:
            name = ob.original.name if ob.original else ob.name
            objects = names.setdefault(ob.type, [])
            if name not in objects:
                objects.append(name)
    for kind, objects in names.items():
        shown = ", ".join("'%s'" % n for n in objects[:5])
        if len(objects) > 5:
            shown += " and %d more" % (len(objects) - 5)
        warn("%s: %s left out" % (_LEFT_OUT[kind], shown))


def object_names(depsgraph):
    """The OBJ exporter's name of each object with a surface -> how a message names it in
    Blender's terms: "object 'Name' (mesh 'Data')"."""
    names = {}
    for inst in depsgraph.object_instances:
        ob = inst.object
        if ob.type not in materials.SURFACE_TYPES:
            continue
        original = ob.original if ob.original else ob
        data = original.data
        label = "object '%s'" % original.name
        if data is not None and data.name != original.name:
            label += " (%s '%s')" % ("mesh" if ob.type == 'MESH' else ob.type.lower(),
                                     data.name)
        names.setdefault(materials.mtl_name(original.name), label)
    return names


# ----------------------------------------------------------------------------- settings

def glint_argv(settings, scene_path, output_path, width, height):
    integrator = "whitted" if settings is not None and settings.integrator == 'WHITTED' \
        else "path"
    get = (lambda k, d: getattr(settings, k)) if settings is not None else (lambda k, d: d)
    argv = ["render", scene_path, "-o", output_path, "-W", str(width), "-H", str(height),
            "--integrator", integrator,
            "--spp", str(get("samples", 64)),
            "--max-depth", str(get("max_depth", 8)),
            "--seed", str(get("seed", 0)),
            "--threads", str(get("threads", 0))]
    time_limit = get("time_limit", 0.0)
    if time_limit > 0:
        argv += ["--time-limit", "%g" % time_limit]
    # --exit-with-parent: a Blender that crashes or is killed leaves no glint rendering on.
    argv += ["--progress", "lines", "--exit-with-parent"]
    return argv


def render_warnings(scene, warn):
    r = scene.render
    if r.film_transparent:
        warn("Film > Transparent is not supported by glint: the world is rendered behind the "
             "objects (alpha 1)")
    # A render region needs no warning: glint renders the whole frame and the engine loads the
    # region's pixels from it (same pixels, full-frame time).


# ----------------------------------------------------------------------------- entry point

def export_frame(depsgraph, out_dir, warn):
    """Writes the glint scene for depsgraph's current frame into out_dir (see the module doc).
    Raises ExportError for a scene glint cannot render; calls warn(msg) for each feature that
    renders differently (the caller de-duplicates)."""
    os.makedirs(out_dir, exist_ok=True)
    scene = depsgraph.scene_eval
    width, height = render_size(scene)
    render_warnings(scene, warn)
    camera = camera_block(depsgraph, width, height, warn)  # first: a camera error stops early

    left_out_warnings(depsgraph, warn)

    missing = images.MissingImages()
    obj_path = os.path.join(out_dir, SCENE_NAME + ".obj")
    export_obj(depsgraph, obj_path)
    mtl_path = os.path.join(out_dir, SCENE_NAME + ".mtl")
    materials.rewrite_mtl(mtl_path, depsgraph, out_dir, warn, missing)
    give_default_surface(obj_path, mtl_path)

    parts = ["// glint scene written by the glint Blender add-on (Blender %s), scene '%s', "
             "frame %d.\n" % (bpy.app.version_string, scene.name, scene.frame_current),
             "// Blender (x, y, z) is POV (x, z, y) here (plugin/blender/glint_blender/"
             "exporter.py).\n",
             "#version 3.7;\n",
             "global_settings { assumed_gamma 1.0 }\n",
             camera,
             world_text(scene, out_dir, warn, missing),
             lights_text(depsgraph, warn),
             'obj_file { "%s.obj" }\n' % SCENE_NAME if _has_faces(obj_path) else
             "// no meshes to render: the world and lights only\n"]
    missing.report(warn)
    scene_path = os.path.join(out_dir, SCENE_NAME + ".pov")
    with open(scene_path, "w", encoding="utf-8") as f:
        f.write("".join(parts))

    output_path = os.path.join(out_dir, "out.exr")
    settings = getattr(scene, "glint", None)
    argv = glint_argv(settings, scene_path, output_path, width, height)
    with open(os.path.join(out_dir, "command.txt"), "w", encoding="utf-8") as f:
        f.write(shlex.join(["glint"] + argv) + "\n")
    material_names = {k: "material '%s'" % m.name
                      for k, m in materials.scene_materials(depsgraph)[0].items()}
    return Export(out_dir, scene_path, output_path, width, height, argv,
                  {"object": object_names(depsgraph), "material": material_names})

