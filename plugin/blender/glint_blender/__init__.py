"""glint as a Blender render engine.

The add-on exports the scene (meshes through Blender's OBJ exporter; camera, lights, world and
render settings into a small POV-Ray scene file), runs the glint command-line renderer on it in a
per-render temporary folder and loads glint's linear EXR into Blender's render result. See
plugin/blender/README.md.
"""

bl_info = {
    "name": "glint",
    "author": "glint authors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "Render Properties > Render Engine > glint",
    "description": "Render with the glint path tracer (Cycles-matching) through its CLI",
    "category": "Render",
}

if "bpy" in locals():
    import importlib
    for _m in (preferences, properties, runner, render_dirs, images,  # noqa: F821
               node_graphs, exporter, native_export, engine, ui):
        importlib.reload(_m)
else:
    from . import (preferences, properties, runner, render_dirs, images, node_graphs,
                   exporter, native_export, engine, ui)

import bpy  # noqa: E402

_modules = (preferences, properties, engine, ui)


def register():
    for m in _modules:
        m.register()


def unregister():
    for m in reversed(_modules):
        m.unregister()
