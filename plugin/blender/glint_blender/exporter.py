"""What the add-on's exports share: the Export record, the errors, glint's messages as the
user reads them, the image size, glint's command line and images saved for glint.

The scene itself is written by native_export.py (scene.json + scene.bin, formats/blender/
FORMAT.md).
"""

import os
import re

import bpy

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
        self.alpha = False  # the image may have alpha below 1 (transparent film, holdouts)


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
    (which is gone once the render ends) is dropped, and the exported object and material names
    become what the user knows them as in Blender."""
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
    message located in the temporary export (a line of the scene's files) are left out."""
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


def render_size(scene):
    """The image size Blender renders: resolution times percentage (integer, as Blender)."""
    r = scene.render
    return (max(1, r.resolution_x * r.resolution_percentage // 100),
            max(1, r.resolution_y * r.resolution_percentage // 100))


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


# Objects with geometry that the exchange does not carry (yet), by type: what the user is told.
_LEFT_OUT = {
    "CURVES": "hair curves are not supported by glint",
    "POINTCLOUD": "point clouds are not supported by glint",
    "GPENCIL": "Grease Pencil objects are not drawn by glint",
    "VOLUME": "volume objects without an OpenVDB file (grids made by nodes, or a missing file) "
              "are not supported by glint",
}


def volume_file(ob):
    """The OpenVDB file a Volume object shows at this frame (absolute), None when it has none
    on disk."""
    vol = ob.data
    try:
        vol.grids.load()
        path = vol.grids.frame_filepath or vol.filepath
    except (AttributeError, RuntimeError):
        path = vol.filepath
    if not path:
        return None
    orig = vol.original if vol.original else vol
    path = bpy.path.abspath(path, library=orig.library)
    return path if os.path.isfile(path) else None


def left_out_warnings(depsgraph, warn):
    """One warning for each object type glint leaves out, naming its objects (instances
    included, each object once). Only the type is read: never an object's materials."""
    names = {}
    for inst in depsgraph.object_instances:
        ob = inst.object
        if ob.type in _LEFT_OUT and (ob.type != "VOLUME" or volume_file(ob) is None):
            name = ob.original.name if ob.original else ob.name
            objects = names.setdefault(ob.type, [])
            if name not in objects:
                objects.append(name)
    for kind, objects in names.items():
        shown = ", ".join("'%s'" % n for n in objects[:5])
        if len(objects) > 5:
            shown += " and %d more" % (len(objects) - 5)
        warn("%s: %s left out" % (_LEFT_OUT[kind], shown))


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
