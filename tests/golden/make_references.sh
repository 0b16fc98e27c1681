#!/bin/bash
# Regenerates the POV-Ray 3.7 reference images of the golden suite: tests/golden/ref/NAME.png
# without anti-aliasing and tests/golden/ref/aa/NAME.png with POV-Ray's adaptive method.
#
#   tests/golden/make_references.sh [NAME...]     (default: every golden scene)
#
# Each scene is rendered from a temporary copy of its folder (scenes include local .inc files
# and images; POV-Ray may only write under its working directory and /tmp) with the command of
# VALIDATION.md: one thread, 320x240, no anti-aliasing (-A: one ray through each pixel centre);
# and again with +A0.3 (sampling method 1, threshold 0.3, depth 3, POV-Ray's default jitter
# 1.0, which glint reproduces: it is a hash of the sub-sample's position).
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
mkdir -p "$here/ref/aa"

wanted=" $* "
status=0
while read -r name path; do
    if [ $# -gt 0 ] && [[ "$wanted" != *" $name "* ]]; then continue; fi
    for kind in plain aa; do
        if [ $kind = plain ]; then flags=(-A); ref="$here/ref/$name.png"
        else flags=(+A0.3); ref="$here/ref/aa/$name.png"; fi
        work=$(mktemp -d /tmp/glint-ref.XXXXXX)
        cp -r "$(dirname "$root/$path")"/. "$work"/
        if ! (cd "$work" && povray +I"$(basename "$path")" +Oref.png +W320 +H240 -D "${flags[@]}" \
                +WT1 +L"$include" >povray.log 2>&1); then
            echo "FAILED $name ($path, ${flags[*]}):" >&2
            tail -n 15 "$work/povray.log" >&2
            status=1
            rm -rf "$work"
            continue
        fi
        if [ -f "$ref" ] && idiff -q -fail 0 -warn 0 "$ref" "$work/ref.png" >/dev/null 2>&1; then
            echo "unchanged ${ref#$root/}"
        else
            oiiotool --nosoftwareattrib "$work/ref.png" --eraseattrib ".*" -o "$ref"
            echo "wrote     ${ref#$root/}"
        fi
        rm -rf "$work"
    done
done < <(golden_scenes "$root")
exit $status
