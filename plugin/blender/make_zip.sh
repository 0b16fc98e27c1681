#!/bin/sh
# Writes glint_blender.zip (the add-on folder at the top of the archive, as Blender's
# Preferences > Add-ons > Install... expects) next to this script, or to the path given.
#   plugin/blender/make_zip.sh [OUT.zip]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-"$here/glint_blender.zip"}
case "$out" in /*) ;; *) out="$(pwd)/$out" ;; esac
rm -f "$out"
cd "$here"
if command -v zip >/dev/null 2>&1; then
    zip -q -r "$out" glint_blender -x '*/__pycache__/*' '*.pyc'
else
    python3 - "$out" <<'PY'
import os, sys, zipfile
with zipfile.ZipFile(sys.argv[1], "w", zipfile.ZIP_DEFLATED) as z:
    for root, dirs, files in os.walk("glint_blender"):
        dirs[:] = sorted(d for d in dirs if d != "__pycache__")
        for f in sorted(files):
            if not f.endswith(".pyc"):
                z.write(os.path.join(root, f))
PY
fi
echo "wrote $out"
