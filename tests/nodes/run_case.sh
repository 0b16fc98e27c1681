#!/bin/bash
# One node family against Cycles (tests/nodes/README.md):
#   run_case.sh GLINT CASE_DIR OUT_DIR TOLERANCE MIN_FRACTION
# unpacks CASE_DIR (scene.json.gz, scene.bin, textures/) into OUT_DIR/<family>/, renders it
# with 1 sample per pixel into OUT_DIR/<family>.exr and compares that with CASE_DIR/cycles.exr
# per pixel (glint compare: 8-bit sRGB values, TOLERANCE in 1/255, at least MIN_FRACTION of
# the pixels within). Exits with glint compare's status (0 agree, 6 differ), 1 when glint
# warned while rendering.
set -euo pipefail
glint=$1 case_dir=$2 out_dir=$3 tolerance=$4 fraction=$5
family=$(basename "$case_dir")
work=$out_dir/$family
rm -rf "$work"
mkdir -p "$work"
gzip -dc "$case_dir/scene.json.gz" > "$work/scene.json"
cp "$case_dir/scene.bin" "$work/"
if [ -d "$case_dir/textures" ]; then cp -r "$case_dir/textures" "$work/"; fi
"$glint" render "$work/scene.json" -o "$out_dir/$family.exr" --spp 1 --progress none \
    2> "$work/render.log"
# A warning (a node or setting glint lacks) means the scene is not rendered as Cycles does.
if grep -i "warning" "$work/render.log"; then
    echo "run_case.sh: glint warned while rendering $family" >&2
    exit 1
fi
exec "$glint" compare "$out_dir/$family.exr" "$case_dir/cycles.exr" \
    --tolerance "$tolerance" --min-fraction "$fraction"
