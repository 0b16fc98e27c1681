"""Installs the glint add-on into Blender's user add-ons, enables it and saves the preferences:

    blender -b --python /path/to/glint/plugin/blender/install.py -- --binary /path/to/glint

Run it from any folder: the add-on is the glint_blender folder beside this script, and
--binary (relative paths are taken from the current folder) is stored as an absolute path in
the add-on's **glint binary** preference; left out, the preference stays empty and the add-on
uses $GLINT_BINARY, then `glint` on PATH. The copy replaces an earlier one (a symlink there is
removed, never what it points to). The binary is checked by running `glint --version`.
Exits non-zero with a message when something fails. Run it without --factory-startup, so that
the preferences it saves are the user's.
"""

import argparse
import os
import shutil
import subprocess
import sys

import addon_utils
import bpy

MODULE = "glint_blender"
HERE = os.path.dirname(os.path.abspath(__file__))


def fail(msg):
    print("glint install: error: " + msg, file=sys.stderr, flush=True)
    sys.exit(1)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    ap = argparse.ArgumentParser(prog="install.py")
    ap.add_argument("--binary", default="", help="the glint executable (build/glint)")
    args = ap.parse_args(argv)

    binary = ""
    if args.binary:
        binary = os.path.abspath(os.path.expanduser(args.binary))
        if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
            fail("%s is not an executable file (build glint first: see README.md)" % binary)
        try:
            version = subprocess.run([binary, "--version"], capture_output=True, text=True,
                                     timeout=30).stdout.strip()
        except (OSError, subprocess.SubprocessError) as e:
            fail("cannot run %s: %s" % (binary, e))
        if not version.startswith("glint"):
            fail("%s --version printed %r: is it glint?" % (binary, version))

    src = os.path.join(HERE, MODULE)
    if not os.path.isfile(os.path.join(src, "__init__.py")):
        fail("the add-on folder %s is not there" % src)
    addons = bpy.utils.user_resource('SCRIPTS', path="addons", create=True)
    dest = os.path.join(addons, MODULE)
    if MODULE in bpy.context.preferences.addons:
        addon_utils.disable(MODULE, default_set=True)
    if os.path.islink(dest) or os.path.isfile(dest):
        os.unlink(dest)
    elif os.path.isdir(dest):
        shutil.rmtree(dest)
    shutil.copytree(src, dest, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    bpy.utils.refresh_script_paths()  # a user add-ons folder made just now joins sys.path
    if addons not in sys.path:
        sys.path.append(addons)
    addon_utils.modules_refresh()
    if addon_utils.enable(MODULE, default_set=True, handle_error=None) is None:
        fail("Blender could not enable the add-on copied to %s" % dest)
    prefs = bpy.context.preferences.addons[MODULE].preferences
    prefs.binary = binary
    bpy.ops.wm.save_userpref()
    print("glint install: add-on installed in %s and enabled; glint binary: %s" %
          (dest, binary or "(empty: $GLINT_BINARY, then glint on PATH)"), flush=True)


main()
