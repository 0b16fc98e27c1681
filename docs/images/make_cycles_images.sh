#!/bin/bash
# Regenerates docs/path-tracer.md's pictures: for each Cycles cross-check scene
# (tests/cycles), glint's path tracer | Blender 3.4 Cycles | difference x4, side by side at
# twice the 128x96 render size, written to docs/images/cycles_<name>.png. glint renders at
# 1024 spp; the Cycles half is the committed reference (16 seeds x 256 spp). Both are linear
# EXRs shown through the sRGB curve (no view transform), the difference is |glint - Cycles| in
# linear values, amplified 4x.
#
#   docs/images/make_cycles_images.sh [path/to/glint] [NAME...]   (default: build/glint, all three)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
glint=${1:-$root/build/glint}
shift || true
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(cornell spheres hdr)

work=$(mktemp -d /tmp/glint-cyclesimages.XXXXXX)
trap 'rm -rf "$work"' EXIT
for name in "${names[@]}"; do
    ref="$root/tests/cycles/ref/${name}_mean.exr"
    "$glint" render "$root/tests/cycles/scenes/$name.pov" -o "$work/$name.exr" \
        --width 128 --height 96 --integrator path --spp 1024 --max-depth 8
    oiiotool "$work/$name.exr" "$ref" --absdiff --mulc 4 -o "$work/$name.diff.exr"
    oiiotool --nosoftwareattrib "$work/$name.exr" --ch R,G,B "$ref" --ch R,G,B \
        "$work/$name.diff.exr" --ch R,G,B --mosaic:pad=2 3x1 \
        --resample:interp=0 776x192 --colorconvert linear sRGB -d uint8 --eraseattrib ".*" \
        -o "$here/cycles_${name}.png"
    echo "wrote docs/images/cycles_${name}.png   ($("$glint" compare "$work/$name.exr" "$ref" || true))"
done
