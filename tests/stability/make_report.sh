#!/usr/bin/env bash
# Writes tests/stability/report.md: every case of VALIDATION.md "Stiff and extreme cases"
# (1-18), the bound, pass/fail and the values the tests measured, with POV-Ray 3.7's figures
# beside glint's where POV-Ray is installed and fails the case.
#
#   tests/stability/make_report.sh [BUILD_DIR] [OUTPUT]   (defaults: build, the report.md here)
#
# BUILD_DIR must hold stability_tests and the path tracer's unit tests (cases 10-14, 16):
#   cmake --build BUILD_DIR --target stability_tests path_render_test path_chi2_test \
#         path_bsdf_test path_convergence_test
set -u
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
out=${2:-$here/report.md}
stab=$build/tests/stability/stability_tests
unit=$build/tests

# case | what | bound | executable | gtest filter | grep pattern of the lines it prints
cases=(
"1|Scale invariance: sphere on plane at scale 1e-4, 1, 1e4, translated 1e5|>= 99.9% of pixels within 1/255 of scale 1; 0 acne pixels|$stab|StabilityScaleInvariance.*|^case 1 "
"2|Ground plane seen 1e5 units away at grazing angles|0 acne pixels|$stab|StabilityGroundPlane.*|^case 2 "
"3|Coplanar overlapping triangles, mesh faces, box faces with two materials|bit-identical at 1/2 threads, twice|$stab|StabilityCoplanar.*|^case 3 "
"4|Watertight mesh: 1e6 rays from inside at vertices and edges|0 leaks|$stab|StabilityGeometry.Case4*|^case 4"
"5|Axis-aligned rays through box faces and edges|hit count = analytic count, no NaN|$stab|StabilityGeometry.Case5*|^case 5"
"6|Grazing and edge-on triangles (d.n = 0, +-1e-7)|no NaN, barycentrics in [0, 1]|$stab|StabilityGeometry.Case6*|^case 6"
"7|Degenerate input (zero area, NaN/Inf/1e30 vertices, empty mesh)|skipped with a warning, image bit-identical|$stab|StabilityDegenerate.*|^case 7"
"8|BVH stress: 1e5 primitives with one centroid, 1e6:1 slivers|depth <= 64, build < 5 s|$stab|StabilityGeometry.Case8*|^case 8"
"9|Camera inside a sphere|every hit within 4 ulp of the radius|$stab|StabilityGeometry.Case9*|^case 9"
"10|White furnace (albedo 1, uniform white environment), 1024 spp|mean 1 +- 1e-3|$unit/path_render_test|PathRender.WhiteFurnaceConvergesToOne|^white furnace"
"11|Closed-sphere furnace (Kd 0.5, Le 0.5)|mean 1 +- 0.005|$unit/path_render_test|PathRender.ClosedSphereFurnace|^closed-sphere"
"12|Lossless specular furnace (mirror; glass IOR 1.5) vs max depth|mean >= 1 - 1e-3 at depth 64; loss at depth 5 reported|$unit/path_render_test|PathRender.LosslessSpecularFurnace|^specular furnace"
"13|BSDF sampling chi-square (Lambert, Phong, GGX, dielectric)|p >= Sidak alpha; mean f cos/pdf <= 1.01|$unit/path_chi2_test|*|^chi2 |^negative control|^smooth dielectric"
"14|Phong exponent 0, 40, 1e5, 1e6 (Whitted)|0 non-finite pixels; brightest pixel at the mirror point|$stab|StabilityGloss.*|^case 14"
"14|Phong exponent 0, 1e5, 1e6 and GGX alpha 1e-6 (path)|0 non-finite pixels; highlight at the mirror point|$unit/path_render_test|PathRender.ExtremeGlossLobes*|^case 14"
"15|IOR 1.0 sphere vanishes; IOR 1.0001, 2.4, 100, total internal reflection|max diff <= 1e-5; no NaN; paths end at max depth|$stab|StabilityIor*|^case 15"
"16|Convergence: relMSE vs a high-spp reference at 16..1024 spp|slope -1 +- 0.1|$unit/path_convergence_test|PathConvergence.*|^convergence|^spp "
"17|FOV 1e-4 and 179 degrees, images 1x1, 1x4096, 4096x1|no NaN; centre ray on the look-at direction|$stab|StabilityCamera.*|^case 17"
"18|Determinism at 1 and 2 threads, twice|bit-identical|$stab|StabilityDeterminism.*|^case 18"
)

worst() {  # worst LOG PREFIX FIELD-REGEX min|max|sum
    grep -E "$2" "$1" 2>/dev/null | grep -oE "$3" | grep -oE "[0-9.e+-]+( of [0-9]+)?$" |
        awk -v how="$4" '{ v = $1 + 0; n++
            if (how == "sum") { s += v; t += $3 } else if (n == 1 || (how == "min" ? v < m : v > m)) m = v }
            END { if (!n) print "n/a"; else if (how == "sum") printf "%d of %d\n", s, t; else print m }'
}

# The key figure of each case for the summary table: label ~ line regex ~ field regex ~ how
# (min, max or sum of "N of M"), taken from the lines its tests print.
declare -A key=(
[1]="min fraction within 1/255~^case 1 (whitted|path) (scale 1e-4|scale 1e4|translate 1e5|#declare)~scale 1 = [0-9.]+~min"
[2]="acne pixels~^case 2 (whitted|path)~acne pixels = [0-9]+ of [0-9]+~sum"
[3]="differing values~^case 3~twice = [0-9]+ of [0-9]+~sum"
[4]="leaks~^case 4~leaks = [0-9]+ of [0-9]+~sum"
[5]="wrong hit counts~^case 5~count = [0-9]+ of [0-9]+~sum"
[6]="bad hits~^case 6~[)] = [0-9]+ of [0-9]+~sum"
[7]="differing values~^case 7 (whitted|path)~input = [0-9]+ of [0-9]+~sum"
[8]="max depth~^case 8~depth [0-9]+~max"
[9]="worst ulp~^case 9~worst [0-9.]+~max"
[10]="mean~^white furnace~mean [0-9.]+~min"
[11]="mean~^closed-sphere~mean [0-9.]+~min"
[12]="min mean at depth 64~^specular furnace [(](mirror|glass)[)]: mean~mean [0-9.]+~min"
[13]="smallest p~^chi2 ~ p [0-9.]+~min"
[14]="non-finite~^case 14~non-finite [0-9]+~max"
[15]="ior 1 max difference~^case 15 (whitted|path): ior 1.0 ~difference = [0-9.e+-]+~max"
[16]="slope~^convergence~slope -?[0-9.]+~min"
[17]="non-finite~^case 17 (whitted|path)~non-finite values = [0-9]+~max"
[18]="differing values~^case 18~values = [0-9]+ of [0-9]+~sum"
)

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
{
    echo "# glint stability report"
    echo
    echo "VALIDATION.md \"Stiff and extreme cases\", measured by the tests of tests/stability"
    echo "(\`ctest -L stability\`). Written by tests/stability/make_report.sh on $(date -u +%F)"
    echo "at $(git -C "$here" rev-parse --short HEAD 2>/dev/null), $(nproc) cores."
    echo "Lines marked *povray* are POV-Ray 3.7 rendering the same scene, measured the same way"
    echo "(not bounded: POV-Ray's epsilons are absolute, MIN_ISECT_DEPTH 1e-4, SHADOW_TOLERANCE"
    echo "1e-3, so it fails where the scene's scale moves away from 1)."
    echo
    echo "| case | what | bound | measured | result | seconds |"
    echo "|---|---|---|---|---|---|"
} > "$tmp/head"
: > "$tmp/body"
for entry in "${cases[@]}"; do
    IFS='|' read -r num what bound exe filter pattern extra1 extra2 <<< "$entry"
    for e in "$extra1" "$extra2"; do [ -n "${e:-}" ] && pattern="$pattern|$e"; done
    log=$tmp/case$num.log
    start=$(date +%s.%N)
    if [ -x "$exe" ]; then
        "$exe" --gtest_filter="$filter" > "$log" 2>&1
        rc=$?
    else
        echo "missing $exe" > "$log"
        rc=127
    fi
    secs=$(echo "$(date +%s.%N) - $start" | bc)
    if [ $rc -eq 0 ] && grep -q "PASSED" "$log"; then result=pass
    elif [ $rc -eq 127 ]; then result="not run"
    else result="**FAIL**"; fi
    IFS='~' read -r klabel kline kfield khow <<< "${key[$num]}"
    measured="$klabel: $(worst "$log" "$kline" "$kfield" "$khow")"
    printf '| %s | %s | %s | %s | %s | %.1f |\n' "$num" "$what" "$bound" "$measured" "$result" \
        "$secs" >> "$tmp/head"
    {
        echo
        echo "## Case $num: $what"
        echo
        echo "Bound: $bound. Result: $result."
        echo
        echo '```'
        if [ "$num" = 13 ]; then
            # One line per BSDF and angle: summarised, then the worst lines.
            grep -E "^chi2 " "$log" | awk '{
                for (i = 1; i <= NF; ++i) {
                    if ($i == "p") p = $(i + 1) + 0;
                    if ($i == "cos/pdf") w = $(i + 1) + 0;
                }
                n++; if (n == 1 || p < minp) { minp = p; pl = $0 }
                # "dielectric reflection" sits over a diffuse base, which Cycles adds without
                # layering (the 1.01 bound is for lobes without one): reported apart.
                if ($0 ~ /dielectric reflection/) { if (w > maxd) { maxd = w; dl = $0 } }
                else if (w > maxw) { maxw = w; wl = $0 }
            } END {
                printf "%d chi-square tests; smallest p %.4f; largest mean f cos/pdf %.6f " \
                       "(bound 1.01); over a diffuse base %.6f (Cycles adds the diffuse " \
                       "unlayered; not bounded)\n", n, minp, maxw, maxd
                print "smallest p:       " pl
                print "largest f cos/pdf: " wl
                print "with diffuse base: " dl
            }'
            grep -E "^negative control|^smooth dielectric" "$log" | head -8
        else
            grep -E "$pattern" "$log" | sed -E 's/^case [0-9]+ povray/povray:/'
        fi
        grep -E "Failure|Expected|Which is|FAILED" "$log" | head -10
        echo '```'
    } >> "$tmp/body"
done
# POV-Ray beside glint, where POV-Ray is installed: the worst figure of each over the same
# variants of the same scene, measured by the same code.
{
    echo
    echo "## POV-Ray 3.7 beside glint"
    echo
    if grep -q "povray" "$tmp"/case*.log; then
        echo "| case | figure (worst over the case's variants) | bound | glint | POV-Ray 3.7 |"
        echo "|---|---|---|---|---|"
        l=$tmp/case1.log
        echo "| 1 | pixels within 1/255 of scale 1 (scale 1e-4, 1e4, translate 1e5) | >= 0.999 |" \
             "$(worst "$l" "^case 1 whitted (scale 1e-4|scale 1e4|translate 1e5):" "scale 1 = [0-9.]+" min) |" \
             "$(worst "$l" "^case 1 povray .*(S = 1e-4|S = 1e4|1e5, 1e5)" "scale 1 = [0-9.]+" min) |"
        echo "| 1 | lost shadow pixels at scale 1e-4 | 0 |" \
             "$(worst "$l" "^case 1 whitted scale 1e-4:" "lost shadow pixels = [0-9]+ of [0-9]+" sum) |" \
             "$(worst "$l" "^case 1 povray .*S = 1e-4;" "lost shadow pixels = [0-9]+ of [0-9]+" sum) |"
        echo "| 1 (extra) | pixels within 1/255 of scale 1, translate 1e8 | >= 0.999 |" \
             "$(worst "$l" "^case 1 whitted translate 1e8" "scale 1 = [0-9.]+" min) |" \
             "$(worst "$l" "^case 1 povray .*1e8" "scale 1 = [0-9.]+" min) |"
        l=$tmp/case2.log
        echo "| 2 | acne pixels, plane 1e5 away, heights 50, 1, 0.01 | 0 |" \
             "$(worst "$l" "^case 2 whitted" "acne pixels = [0-9]+ of [0-9]+" sum) |" \
             "$(worst "$l" "^case 2 povray" "acne pixels = [0-9]+ of [0-9]+" sum) |"
        l=$tmp/case15.log
        echo "| 15 | ior 1.0 sphere vs none: pixels with equal 8-bit values | 1 |" \
             "1 (max linear difference $(worst "$l" "^case 15 whitted: ior 1.0" "difference = [0-9.e+-]+" max)) |" \
             "$(worst "$l" "^case 15 povray" "0/255 = [0-9.]+" min) |"
        l=$tmp/case17.log
        echo "| 17 | centre pixels on the look-at marker, fov 1e-4 | all |" \
             "$(worst "$l" "^case 17 whitted fov 0.0001" "marker = [0-9]+ of [0-9]+" sum) |" \
             "$(worst "$l" "^case 17 povray fov 0.0001" "marker = [0-9]+ of [0-9]+" sum) |"
        echo
        echo "POV-Ray loses the sphere's shadow at scale 1e-4 (its SHADOW_TOLERANCE 1e-3 exceeds"
        echo "the scene), loses it again at 1e8 from the origin, and misses the ~1e-7 marker at"
        echo "fov 1e-4; it passes the grazing plane at 1e5 and the ior 1.0 sphere."
    else
        echo "povray was not installed: no POV-Ray figures."
    fi
} >> "$tmp/head"
cat "$tmp/head" "$tmp/body" > "$out"
echo "wrote $out"
