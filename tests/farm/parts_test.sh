#!/usr/bin/env bash
# Renders in parts without a scheduler (docs/farm.md): every AA mode and the path tracer
# rendered as regions (cut through the driver's 32-pixel blocks) and joined with glint merge
# give the single-process render bit for bit; merge refuses overlaps, gaps, parts of another
# job, missing parts and a format change, writing nothing; --skip-existing skips a complete
# part and renders a corrupt one again; farm submit --dry-run lists one task per tile, and
# --no-submit writes a task list that, run by hand, makes the image.
# Usage: parts_test.sh GLINT SCENE WORK_DIR
set -euo pipefail
glint=$1 scene=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
size=(--width 150 --height 100)
# Identical pixels: glint compare at tolerance 0 finds no 8-bit difference and no linear one.
same() {
    local out
    out=$("$glint" compare "$1" "$2" --tolerance 0 --min-fraction 1) || fail "$1 and $2 differ: $out"
    [[ $out == *"max=0@"* && $out == *"rmse_linear=0"* ]] || fail "$1 and $2 differ: $out"
}
regions=(0,0,47,61 47,0,150,61 0,61,99,100 99,61,150,100)

for mode in "--aa none" "--aa adaptive" "--aa grid:3" "--integrator path --spp 8 --seed 3"; do
    ext=png
    [[ $mode == *path* ]] && ext=exr
    # shellcheck disable=SC2086
    "$glint" render "$scene" -o full.$ext "${size[@]}" $mode
    parts=()
    for r in "${regions[@]}"; do
        # shellcheck disable=SC2086
        "$glint" render "$scene" -o "part_$r.$ext" "${size[@]}" $mode --region "$r"
        parts+=("part_$r.$ext")
    done
    "$glint" merge "${parts[@]}" -o merged.$ext > /dev/null
    same full.$ext merged.$ext
    echo "ok: $mode: ${#parts[@]} regions merged = the whole render"
done

# Refusals: exit code, message, and no output file.
refuse() {
    local code=$1 want=$2
    shift 2
    rm -f refused.png
    local err rc=0
    err=$("$glint" merge "$@" -o refused.png 2>&1) || rc=$?
    [[ $rc == "$code" ]] || fail "merge $*: exit $rc, want $code ($err)"
    [[ $err == *"$want"* ]] || fail "merge $*: '$err' does not say '$want'"
    [[ ! -e refused.png ]] || fail "merge $* wrote refused.png"
    ls refused.png.tmp* > /dev/null 2>&1 && fail "merge $* left a temporary file"
    echo "ok: refused ($want)"
}
"$glint" render "$scene" -o p1.png "${size[@]}" --region 0,0,150,50
"$glint" render "$scene" -o p2.png "${size[@]}" --region 0,50,150,100
"$glint" render "$scene" -o p2_overlap.png "${size[@]}" --region 0,40,150,100
"$glint" render "$scene" -o p2_other_job.png "${size[@]}" --region 0,50,150,100 --aa grid:2
"$glint" render "$scene" -o p2_other_size.png --width 150 --height 101 --region 0,50,150,100
"$glint" merge p1.png p2.png -o whole.png > /dev/null
refuse 1 "overlap in 0,40,150,50" p1.png p2_overlap.png
refuse 1 "pixel 0,50 is in none of them" p1.png
refuse 1 "parts of different jobs" p1.png p2_other_job.png
refuse 1 "different image sizes" p1.png p2_other_size.png
refuse 3 "part missing.png is missing" p1.png missing.png
refuse 1 "is a whole image, not a region" whole.png
rm -f refused.exr
rc=0
"$glint" merge p1.png p2.png -o refused.exr > /dev/null 2>&1 || rc=$?
[[ $rc == 1 && ! -e refused.exr ]] || fail "merge of PNG parts into .exr: exit $rc"

# --skip-existing: a complete part is left alone (same bytes, same time), a corrupt one redone.
cp p1.png p1_before.png
touch -d '2000-01-01' p1.png
msg=$("$glint" render "$scene" -o p1.png "${size[@]}" --region 0,0,150,50 --skip-existing 2>&1)
[[ $msg == *"already complete"* ]] || fail "--skip-existing rendered a complete part: $msg"
[[ $(stat -c %Y p1.png) == $(date -d '2000-01-01' +%s) ]] || fail "--skip-existing touched p1.png"
head -c 200 p1_before.png > p1.png
msg=$("$glint" render "$scene" -o p1.png "${size[@]}" --region 0,0,150,50 --skip-existing 2>&1)
[[ $msg != *"already complete"* ]] || fail "--skip-existing took a truncated part for complete"
same p1.png p1_before.png
msg=$("$glint" render "$scene" -o p1.png "${size[@]}" --region 0,0,150,40 --skip-existing 2>&1)
[[ $msg != *"already complete"* ]] || fail "--skip-existing took another region for this one"
echo "ok: --skip-existing keeps complete parts and redoes the rest"

# The job a farm would submit: one render per tile, each with its region, and one merge.
dry=$("$glint" farm submit "$scene" -o "$work/farm.png" --tiles 6 "${size[@]}" --aa adaptive --dry-run)
[[ $(grep -c -- "--region" <<< "$dry") == 6 ]] || fail "dry run: not 6 tasks: $dry"
grep -q -- "--skip-existing" <<< "$dry" || fail "dry run: tasks do not skip complete parts"
grep -q "#SBATCH --array=0-5" <<< "$dry" || fail "dry run: no 6-task array"
grep -q "#SBATCH --requeue" <<< "$dry" || fail "dry run: tasks not requeued"
grep -q "dependency=afterany" <<< "$dry" || fail "dry run: no dependent finishing job"
[[ ! -e $work/farm.farm ]] || fail "dry run wrote the job folder"
# The same job written for another scheduler: its task list run by hand makes the image.
"$glint" farm submit "$scene" -o "$work/farm.png" --tiles 6 "${size[@]}" --aa adaptive --no-submit > /dev/null
[[ $(wc -l < farm.farm/tasks.txt) == 6 ]] || fail "tasks.txt has not 6 lines"
while read -r line; do eval "$line"; done < farm.farm/tasks.txt
eval "$(cat farm.farm/finish.txt)" > /dev/null
"$glint" render "$scene" -o direct.png "${size[@]}" --aa adaptive
same direct.png farm.png
echo "ok: the job's task list, run by hand, makes the image"
