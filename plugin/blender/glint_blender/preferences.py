"""Add-on preferences: where the glint executable is, and whether to keep the temp folders."""

import os
import shutil

import bpy


class GlintPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    binary: bpy.props.StringProperty(
        name="glint binary",
        description="Path of the glint executable. Empty: the GLINT_BINARY environment "
                    "variable, then `glint` on PATH",
        subtype='FILE_PATH',
        default="",
    )
    keep_temp: bpy.props.BoolProperty(
        name="Keep temporary files",
        description="Keep each render's folder (scene.pov, scene.obj/mtl, textures, out.exr, "
                    "command.txt, glint.log) for debugging; its path is printed",
        default=False,
    )

    def draw(self, context):
        layout = self.layout
        layout.prop(self, "binary")
        found = find_binary(self.binary)
        layout.label(text="Using: " + found if found else
                     "glint not found: set the path above, GLINT_BINARY or PATH",
                     icon='CHECKMARK' if found else 'ERROR')
        layout.prop(self, "keep_temp")


def get(context=None):
    """The add-on's preferences, or None when the add-on is not enabled by name (tests)."""
    context = context or bpy.context
    addon = context.preferences.addons.get(__package__)
    return addon.preferences if addon else None


def find_binary(configured):
    """The glint executable to run: the preference, else $GLINT_BINARY, else `glint` on PATH.
    Returns an absolute path or None."""
    for candidate in (configured, os.environ.get("GLINT_BINARY", "")):
        if candidate:
            path = bpy.path.abspath(candidate)
            return path if os.path.isfile(path) and os.access(path, os.X_OK) else None
    return shutil.which("glint")


def register():
    bpy.utils.register_class(GlintPreferences)


def unregister():
    bpy.utils.unregister_class(GlintPreferences)
