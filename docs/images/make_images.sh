#!/bin/bash
# Regenerates the comparison pictures (docs/compatibility.md, README.md): for each scene, glint | POV-Ray 3.7 | difference
# side by side (320x240 each, no anti-aliasing, the golden-test setting), written to
# docs/images/<name>_compare.png. The difference is |glint - POV-Ray| per channel, amplified
# 8x so that a 2/255 error is visible. The POV-Ray half is the committed golden reference.
#
#   docs/images/make_images.sh [path/to/glint] [NAME...]   (default: build/glint, the scenes below)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
glint=${1:-$root/build/glint}
shift || true
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(demo refraction_tir csg image_maps pov_chars media_interior media_density_file radiosity
    photons)
source "$root/tests/golden/golden_scenes.sh"

work=$(mktemp -d /tmp/glint-docimages.XXXXXX)
trap 'rm -rf "$work"' EXIT
while read -r name path; do
    [[ " ${names[*]} " == *" $name "* ]] || continue
    ref="$root/tests/golden/ref/$name.png"
    "$glint" render "$root/$path" -o "$work/$name.png" --width 320 --height 240 --aa none
    oiiotool "$work/$name.png" "$ref" --absdiff --mulc 8 -o "$work/$name.diff.png"
    oiiotool --nosoftwareattrib "$work/$name.png" "$ref" "$work/$name.diff.png" \
        --mosaic:pad=4 3x1 --eraseattrib ".*" -o "$here/${name}_compare.png"
    echo "wrote docs/images/${name}_compare.png   ($("$glint" compare "$work/$name.png" "$ref" \
        --tolerance 2 --min-fraction 0.99 || true))"
done < <(golden_scenes "$root")

# The demo scene as the picture that opens docs/compatibility.md: glint at 480x360 with adaptive anti-aliasing.
if [[ " ${names[*]} " == *" demo "* ]]; then
    "$glint" render "$root/scenes/demo.pov" -o "$work/demo_480.png" --width 480 --height 360 \
        --aa adaptive:0.3
    oiiotool --nosoftwareattrib "$work/demo_480.png" --eraseattrib ".*" -o "$here/demo.png"
    echo "wrote docs/images/demo.png"
fi
