#!/usr/bin/env bash
# Runs `glint ir` on every POV-Ray example scene (or the scenes given) with a timeout and
# counts how many parse, fail with a scene error, crash or hang. The commonest first error
# lines are listed so the language work can go after the most frequent ones.
#
#   tests/pov_examples/parse_all.sh [--glint PATH] [--timeout S] [--out DIR] [SCENE.pov ...]
#
# Exit status: 0 when no scene crashed or hung (a scene error is a result, not a failure),
# 1 otherwise. --out keeps each scene's stderr in DIR/<scene>.err.
set -u
glint=build/glint
timeout_s=20
out=""
examples=/usr/share/doc/povray/examples
include=/usr/share/povray-3.7/include
scenes=()
while [ $# -gt 0 ]; do
    case "$1" in
        --glint) glint=$2; shift 2 ;;
        --timeout) timeout_s=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
        *) scenes+=("$1"); shift ;;
    esac
done
if [ ${#scenes[@]} -eq 0 ]; then
    [ -d "$examples" ] || { echo "no scenes given and $examples is missing"; exit 0; }
    mapfile -t scenes < <(find "$examples" -name '*.pov' | sort)
fi
[ -n "$out" ] && mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ok=0; scene_err=0; missing=0; crash=0; hang=0
: > "$tmp/first_errors"
for s in "${scenes[@]}"; do
    name=$(echo "${s#$examples/}" | tr '/' '_')
    err="$tmp/err"
    timeout "$timeout_s" "$glint" ir "$s" -I "$(dirname "$s")" -I "$include" > /dev/null 2> "$err"
    rc=$?
    [ -n "$out" ] && cp "$err" "$out/${name%.pov}.err"
    case $rc in
        0) ok=$((ok + 1)) ;;
        2) scene_err=$((scene_err + 1))
           grep -m1 ': error: ' "$err" | sed -E 's/^.*: error: //' >> "$tmp/first_errors"
           echo "error $s: $(grep -m1 ': error: ' "$err")" ;;
        3) missing=$((missing + 1)); echo "missing $s: $(grep -m1 'error' "$err")" ;;
        124) hang=$((hang + 1)); echo "HANG $s" ;;
        *) crash=$((crash + 1)); echo "CRASH($rc) $s: $(tail -1 "$err")" ;;
    esac
done
total=${#scenes[@]}
echo
echo "scenes: $total  parsed: $ok  scene errors: $scene_err  missing files: $missing  crashes: $crash  hangs: $hang"
if [ -s "$tmp/first_errors" ]; then
    echo "commonest errors (message with quoted names kept):"
    sort "$tmp/first_errors" | uniq -c | sort -rn | head -25
fi
[ $crash -eq 0 ] && [ $hang -eq 0 ]
