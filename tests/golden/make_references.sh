#!/bin/bash
# Regenerates the POV-Ray 3.7 reference images of the golden suite into tests/golden/ref/.
#
#   tests/golden/make_references.sh [NAME...]     (default: every golden scene)
#
# Each scene is rendered from a temporary copy of its folder (scenes include local .inc files
# and images; POV-Ray may only write under its working directory and /tmp) with the command of
# VALIDATION.md: no anti-aliasing (one ray through each pixel centre), one thread, 320x240.
# A reference whose pixels did not change is left alone, so that a re-run does not rewrite
# files only because POV-Ray stamps the render date into them; new files are stored without
# that metadata.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$here/golden_scenes.sh"
include=/usr/share/povray-3.7/include
if ! command -v povray >/dev/null; then
    echo "povray is not installed (apt-get install povray)" >&2
    exit 1
fi
mkdir -p "$here/ref"

wanted=" $* "
status=0
while read -r name path; do
    if [ $# -gt 0 ] && [[ "$wanted" != *" $name "* ]]; then continue; fi
    work=$(mktemp -d /tmp/glint-ref.XXXXXX)
    cp -r "$(dirname "$root/$path")"/. "$work"/
    if ! (cd "$work" && povray +I"$(basename "$path")" +Oref.png +W320 +H240 -D -A +WT1 \
            +L"$include" >povray.log 2>&1); then
        echo "FAILED $name ($path):" >&2
        tail -n 15 "$work/povray.log" >&2
        status=1
        rm -rf "$work"
        continue
    fi
    ref="$here/ref/$name.png"
    if [ -f "$ref" ] && idiff -q -fail 0 -warn 0 "$ref" "$work/ref.png" >/dev/null 2>&1; then
        echo "unchanged $name"
    else
        oiiotool --nosoftwareattrib "$work/ref.png" --eraseattrib ".*" -o "$ref"
        echo "wrote     $name -> tests/golden/ref/$name.png"
    fi
    rm -rf "$work"
done < <(golden_scenes "$root")
exit $status
