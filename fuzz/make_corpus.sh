#!/usr/bin/env bash
# Gathers the seed corpora for the fuzz targets from the repository into OUT (default
# build-fuzz/corpus): OUT/pov, OUT/expr, OUT/obj, OUT/mtl. Seeds are copied, never committed.
# Usage: fuzz/make_corpus.sh [OUT]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/build-fuzz/corpus}
mkdir -p "$out"/{pov,expr,obj,mtl}

# Whole scenes (and include files, which are scene text too), under 256 KiB each.
n=0
while IFS= read -r -d '' f; do
  cp "$f" "$out/pov/$(echo "${f#$root/}" | tr '/' '_')"
  n=$((n + 1))
done < <(find "$root/scenes" "$root/tests" \( -name '*.pov' -o -name '*.inc' \) -size -256k -print0)

# Expressions: the right-hand side of every one-line #declare/#local in those scenes.
m=0
while IFS= read -r line; do
  m=$((m + 1))
  printf '%s' "$line" > "$out/expr/decl_$m"
done < <(cat "$out"/pov/* | grep -ohE '#(declare|local) +[A-Za-z_][A-Za-z0-9_]* *= *[^;]+;' |
           sed -E 's/^#(declare|local) +[A-Za-z_][A-Za-z0-9_]* *= *//; s/;$//' | sort -u | head -2000)
# A few forms the scenes may not spell on one line.
printf '%s' '<1,2,3>.x*vlength(<3,4,0>)+mod(7,3)' > "$out/expr/vec"
printf '%s' 'rgbft <1,0.5,0,0.2,0.1>' > "$out/expr/color"
printf '%s' 'concat("a", str(pi, 0, 3), chr(65), substr("hello", 2, 3))' > "$out/expr/string"
printf '%s' 'function(x, y, z) { sqrt(x*x + y*y) - select(z, 1, 2) }' > "$out/expr/function"
printf '%s' 'array[2][2] { {1, 2}, {3, 4} }' > "$out/expr/array"
printf '%s' '(1 < 2 ? 3 : 4) & !(0 | 1)' > "$out/expr/logic"
printf '%s' 'transform { rotate 30*y scale <1,2,3> translate -x }' > "$out/expr/transform"

# OBJ and MTL files, plus small hand-written ones for forms the test data does not use.
for f in $(find "$root/scenes" "$root/tests" -name '*.obj' -size -2M); do
  cp "$f" "$out/obj/$(echo "${f#$root/}" | tr '/' '_')"
done
for f in $(find "$root/scenes" "$root/tests" -name '*.mtl'); do
  cp "$f" "$out/mtl/$(echo "${f#$root/}" | tr '/' '_')"
done
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n' > "$out/obj/quad_negative"
printf 'o a\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nvt 0 0\nvn 0 0 1\ng b c\ns 1\nf 1/1/1 2//1 3/1\nl 1 2\np 3\n' > "$out/obj/mixed"
printf 'v 0 0 0\nv 2 0 0\nv 2 2 0\nv 1 3 0\nv 0 2 0\nf 1 2 3 4 5\nf 1 2 9\n' > "$out/obj/ngon_badindex"
printf 'mtllib a.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$out/obj/mtllib_missing"
printf 'newmtl Material\nKd 0.8 0.2 0.1\nKs 1 1 1\nNs 250\nNi 1.5\nd 0.5\nillum 7\nKe 1 1 1\nTf 0.5 0.5 0.5\nmap_Kd -s 2 2 1 -o 0.5 0 0 -clamp on tex.png\nbump -bm 0.3 n.png\n' > "$out/mtl/classic"
printf '# Blender MTL File\nnewmtl Material.001\nPr 0.3\nPm 1\nPs 0.2\nPc 0.1\nPcr 0.05\naniso 0.5\nanisor 0.2\nTr 0.1\nmap_Pr r.png\nnorm -bm 2 n.png\n' > "$out/mtl/pbr"

echo "pov: $n, expr: $((m + 7)), obj: $(ls "$out/obj" | wc -l), mtl: $(ls "$out/mtl" | wc -l) seeds in $out"
