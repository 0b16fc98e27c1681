"""Run by `blender -b SCENE.blend --python enable_addon.py -E GLINT ...` (tests/plugin): enables
the glint add-on headless from the working tree and points it at the glint under test.

BLENDER_USER_SCRIPTS must hold addons/glint_blender (run_scene.py links it to
plugin/blender/glint_blender). Environment:
    GLINT_TEST_BINARY   the glint executable (preferences.binary)
    GLINT_TEST_THREADS  scene.glint.threads (default 0: all)
The render settings are set here too (samples 256, max depth 8: the Cycles references' 256 spp
per seed image and 7 bounces), so the test does not depend on how the .blend stored them.
keep_temp is on: the test re-renders the exported folder from its command.txt.
"""

import os
import sys

import addon_utils
import bpy

mod = addon_utils.enable("glint_blender", default_set=True, handle_error=None)
if mod is None:
    print("enable_addon.py: could not enable glint_blender (BLENDER_USER_SCRIPTS=%s)"
          % os.environ.get("BLENDER_USER_SCRIPTS"), file=sys.stderr)
    sys.exit(1)
prefs = bpy.context.preferences.addons["glint_blender"].preferences
prefs.binary = os.environ["GLINT_TEST_BINARY"]
prefs.keep_temp = True
for scene in bpy.data.scenes:
    g = scene.glint
    g.integrator = "PATH"
    g.samples = 256
    g.max_depth = 8
    g.time_limit = 0.0
    g.seed = 0
    g.threads = int(os.environ.get("GLINT_TEST_THREADS", "0"))
print("enable_addon.py: glint_blender enabled, binary %s" % prefs.binary)
