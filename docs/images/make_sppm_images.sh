#!/bin/bash
# Regenerates docs/images/sppm_caustic.png (README.md, docs/path-tracer.md): the glass ball of
# scenes/caustic_point.pov (a point light) and scenes/caustic.pov (a small emitting ball), each
# by the path tracer and by the photon integrator at about the same time, 240x180.
#
#   docs/images/make_sppm_images.sh [path/to/glint]   (default: build/glint)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
glint=${1:-$root/build/glint}
work=$(mktemp -d /tmp/glint-sppmimages.XXXXXX)
trap 'rm -rf "$work"' EXIT
for scene in caustic_point caustic; do
    "$glint" render "$root/scenes/$scene.pov" -o "$work/$scene-path.png" --width 240 \
        --height 180 --integrator path --spp 400
    "$glint" render "$root/scenes/$scene.pov" -o "$work/$scene-sppm.png" --width 240 \
        --height 180 --integrator sppm --spp 256
done
oiiotool --nosoftwareattrib "$work/caustic_point-path.png" "$work/caustic_point-sppm.png" \
    "$work/caustic-path.png" "$work/caustic-sppm.png" --mosaic:pad=4 2x2 --eraseattrib ".*" \
    -o "$here/sppm_caustic.png"
echo "wrote docs/images/sppm_caustic.png"
