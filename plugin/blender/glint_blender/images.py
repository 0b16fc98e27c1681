"""Images the export names: where a Blender image's file is, why glint could not read it, and
the one warning per missing image."""

import os


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
