"""The images a material (or the world) uses, as files glint reads.

    ImageWriter(out_dir, mtl_dir, missing).file_for(image, statement, issues, kind, scale)

gives the path glint reads for a Blender image in one use: the image's own file when glint
reads it as Cycles does, else a float PFM in out_dir/textures with the linear values Cycles sees
(plugin/blender/MATERIALS.md, "Images"). An image Blender has no pixels for (missing or
unreadable file) is Cycles' magenta, and MissingImages gathers one warning per such image with
every material (and the world) using it. The user's image datablocks are only read.
"""

import os
import re
import struct


def luminance(c):
    """Blender's colour -> float conversion (Rec. 709 luma of the linear colour), which glint
    applies to its data maps too."""
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]


def write_pfm(path, width, height, rgb_rows_bottom_up):
    """A float PFM (3 channels, little endian), rows bottom first as Blender stores pixels.
    rgb_rows_bottom_up: a flat sequence of width*height*3 floats (or a numpy array)."""
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (width, height))
        try:
            import numpy as np
            f.write(np.asarray(rgb_rows_bottom_up, dtype="<f4").tobytes())
        except ImportError:
            f.write(struct.pack("<%df" % (width * height * 3), *rgb_rows_bottom_up))



SRGB_SPACES = {"sRGB"}
LINEAR_SPACES = {"Non-Color", "Linear", "Raw", "Linear Rec.709"}
FLOAT_EXTS = {".exr", ".hdr", ".pfm"}
READABLE_EXTS = {".png", ".jpg", ".jpeg", ".exr", ".hdr", ".tif", ".tiff", ".tga", ".bmp",
                 ".pfm", ".ppm", ".pgm"}

# How glint reads each map: 'srgb' (8/16-bit files sRGB-decoded) or 'linear'.
GLINT_DECODE = {"map_Kd": "srgb", "map_Ks": "srgb", "map_Ke": "srgb", "map_Pr": "linear",
                "map_Pm": "linear", "map_d": "linear", "map_Bump": "linear"}


# Cycles' colour for an image it has no pixels for (a missing or unreadable file): magenta,
# alpha 1 (TEX_IMAGE_MISSING_R/G/B/A in Cycles' kernel).
MISSING_RGBA = (1.0, 0.0, 1.0, 1.0)


def image_path(image):
    """The absolute path of an image's file ("" when it has none)."""
    import bpy
    raw = image.filepath_raw or image.filepath
    return bpy.path.abspath(raw, library=image.library) if raw else ""


def image_problem(image):
    """Why Blender has no pixels for `image` (Cycles then renders it magenta), or None."""
    if image.packed_file is not None or image.source not in ("FILE", "SEQUENCE", "MOVIE",
                                                            "TILED"):
        return None  # packed and generated images always have pixels
    path = image_path(image)
    if not path:
        return "it has no file"
    if image.source == "FILE" and not os.path.isfile(path):
        return "file not found: " + path
    if not image.has_data:
        image.size[:]  # asks Blender to load it
    if not image.has_data or image.size[0] <= 0 or image.size[1] <= 0:
        return "Blender cannot read " + path
    return None


class MissingImages:
    """Images Blender has no pixels for, with everything that uses them: ONE warning an image
    naming its path and every user, however many materials (and the world) share it."""

    def __init__(self):
        self.images = {}  # (name, library path) -> [problem, [users]]

    def add(self, image, problem, user):
        key = (image.name, image.library.filepath if image.library else "")
        entry = self.images.setdefault(key, [problem, []])
        if user not in entry[1]:
            entry[1].append(user)

    def report(self, warn):
        for (name, _), (problem, users) in self.images.items():
            warn("image '%s': %s; rendered magenta, as Cycles does; used by %s"
                 % (name, problem, ", ".join(users)))


class ImageWriter:
    """Finds or writes the file glint reads for an image in a given use."""

    def __init__(self, out_dir, mtl_dir, missing=None):
        self.dir = os.path.join(out_dir, "textures")
        self.mtl_dir = mtl_dir
        self.cache = {}
        self.used = set()
        self.missing = missing if missing is not None else MissingImages()

    def rel(self, path):
        p = os.path.abspath(path)
        d = os.path.abspath(self.mtl_dir)
        return os.path.relpath(p, d) if p.startswith(d + os.sep) else p

    def file_for(self, image, statement, issues, kind="color", scale=1.0):
        """kind: 'color' (RGB as is), 'gray' (the luminance, a height map), 'alpha' (the alpha
        channel as gray). scale multiplies the values (an emission strength). An image without
        pixels gives Cycles' magenta (recorded in self.missing for its one warning), and so
        does image None (a node without an image, which the caller warns about)."""
        if image is None:  # an Image Texture node without an image
            return self._write_missing(kind, scale)
        problem = image_problem(image)
        if problem is not None:
            self.missing.add(image, problem, "material '%s'" % issues.material)
            return self._write_missing(kind, scale)
        key = (image.name, image.library.filepath if image.library else "", statement, kind,
               scale)
        if key in self.cache:
            return self.cache[key]
        space = image.colorspace_settings.name
        if space not in SRGB_SPACES and space not in LINEAR_SPACES:
            issues.add("image '%s' has colour space %s, read as %s" %
                       (image.name, space, "Linear" if image.is_float else "sRGB"))
        if image.source not in ("FILE", "GENERATED"):
            issues.add("image '%s' is a %s; its first frame/tile is used" %
                       (image.name, image.source.lower()))
        path = image_path(image)
        ext = os.path.splitext(path)[1].lower()
        on_disk = (image.source == "FILE" and image.packed_file is None and not image.is_dirty
                   and os.path.isfile(path) and ext in READABLE_EXTS)
        cycles_linear = image.is_float or space in LINEAR_SPACES
        if ext in FLOAT_EXTS:
            agrees = True  # glint reads float files as stored, Blender too
        elif GLINT_DECODE[statement] == "srgb":
            agrees = not cycles_linear
        else:
            agrees = space in LINEAR_SPACES
        if on_disk and agrees and kind == "color" and scale == 1.0:
            result = path
        else:
            result = self._write(image, kind, scale, issues)
        self.cache[key] = result
        return result

    def _write_missing(self, kind, scale):
        """A 1 x 1 float image of what Cycles reads from a missing image in this use."""
        key = ("<missing>", kind, scale)
        if key not in self.cache:
            r, g, b, a = MISSING_RGBA
            if kind == "gray":
                r = g = b = luminance((r, g, b))
            elif kind == "alpha":
                r = g = b = a
            rgb = [r * scale, g * scale, b * scale]
            self.cache[key] = self._write_pfm("missing_" + kind + (
                "_x%g" % scale if scale != 1.0 else ""), 1, 1, rgb)
        return self.cache[key]

    def _write_pfm(self, base, w, h, rgb):
        os.makedirs(self.dir, exist_ok=True)
        name, k = base, 1
        while name in self.used:
            k += 1
            name = "%s_%d" % (base, k)
        self.used.add(name)
        out = os.path.join(self.dir, name + ".pfm")
        write_pfm(out, w, h, rgb)
        return out

    def _write(self, image, kind, scale, issues):
        import numpy as np
        w, h = image.size[:2]
        n = image.channels
        if w <= 0 or h <= 0 or n <= 0:  # image_problem() said it has pixels: a Blender quirk
            self.missing.add(image, "Blender gives it no pixels",
                             "material '%s'" % issues.material)
            return self._write_missing(kind, scale)
        px = np.empty(w * h * n, dtype=np.float32)
        image.pixels.foreach_get(px)
        px = px.reshape(h * w, n).astype(np.float64)
        rgb = px[:, :3] if n >= 3 else np.repeat(px[:, :1], 3, axis=1)
        alpha = px[:, 3] if n == 4 else (px[:, 1] if n == 2 else np.ones(h * w))
        if not image.is_float and image.colorspace_settings.name not in LINEAR_SPACES:
            # Byte buffers hold the file's values; Cycles decodes them as sRGB.
            rgb = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
        if kind == "gray":
            g = rgb @ np.array([0.2126, 0.7152, 0.0722])
            rgb = np.repeat(g[:, None], 3, axis=1)
        elif kind == "alpha":
            rgb = np.repeat(alpha[:, None], 3, axis=1)
        rgb = rgb * scale
        base = re.sub(r"[^A-Za-z0-9._-]", "_", os.path.splitext(image.name)[0]) or "image"
        if kind != "color":
            base += "_" + kind
        if scale != 1.0:
            base += "_x%g" % scale
        return self._write_pfm(base, w, h, rgb.astype(np.float32).ravel())
