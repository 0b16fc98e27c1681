#!/bin/bash
# Regenerates docs/blender.md's add-on picture: for each scene of tests/plugin, the image
# Blender saved from the glint add-on's render (256 spp) | Blender 3.4 Cycles (the committed
# reference, 16 seeds x 256 spp) | |glint - Cycles| x4 in linear values, one row per scene at
# twice the 128x96 render size, shown through the sRGB curve, written to
# docs/images/plugin_scenes.png (and the volume scenes to volumes.png). Run the plugin tests first (`ctest -L plugin`): they leave
# Blender's images in <build>/tests/plugin/out/NAME/.
#
#   docs/images/make_plugin_images.sh [path/to/build]   (default: build)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-$root/build}
out="$build/tests/plugin/out"

work=$(mktemp -d /tmp/glint-pluginimages.XXXXXX)
trap 'rm -rf "$work"' EXIT
# picture OUT.png NAME:FRAME:REF...: one row per scene, written to docs/images/OUT.png.
picture() {
    local file=$1 rows=() spec name frame ref_name img ref
    shift
    for spec in "$@"; do
        IFS=: read -r name frame ref_name <<<"$spec"
        img="$out/$name/blender_$frame.exr"
        ref="$root/tests/plugin/ref/${ref_name}_mean.exr"
        [ -f "$img" ] || { echo "missing $img: run ctest -L plugin first" >&2; exit 1; }
        oiiotool "$img" --ch R,G,B "$ref" --ch R,G,B --absdiff --mulc 4 -o "$work/$name.diff.exr"
        oiiotool "$img" --ch R,G,B "$ref" --ch R,G,B "$work/$name.diff.exr" --mosaic:pad=2 3x1 \
            -o "$work/$name.row.exr"
        rows+=("$work/$name.row.exr")
        echo "$name: $("$build/glint" compare "$img" "$ref" || true)"
    done
    oiiotool --nosoftwareattrib "${rows[@]}" --mosaic:pad=2 1x${#rows[@]} \
        --resample:interp=0 776x$((194 * ${#rows[@]})) --colorconvert linear sRGB -d uint8 \
        --eraseattrib ".*" -o "$here/$file"
    echo "wrote docs/images/$file"
}
picture plugin_scenes.png cornell:0001:cornell principled:0001:principled \
    textured:0001:textured lamps:0001:lamps anim:0002:anim_f2
# The volumes (issue 31): docs/blender.md and README.md.
picture volumes.png volume:0001:volume volume_noise:0001:volume_noise \
    volume_world:0001:volume_world vdb_volume:0001:vdb_volume
picture subsurface.png subsurface:0001:subsurface
