#!/bin/bash
# Live check that the committed references are current: re-renders every golden scene with the
# installed POV-Ray (same command as make_references.sh) and requires pixel-identical output.
# A scene edited without re-running make_references.sh fails here.
#
#   check_references.sh GLINT WORKDIR
set -u
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
source "$here/golden_scenes.sh"
glint=$1 workdir=$2
mkdir -p "$workdir"
stale=0
while read -r name path; do
    work=$(mktemp -d /tmp/glint-live.XXXXXX)
    cp -r "$(dirname "$root/$path")"/. "$work"/
    if ! (cd "$work" && povray +I"$(basename "$path")" +Olive.png +W320 +H240 -D -A +WT1 \
            +L/usr/share/povray-3.7/include >povray.log 2>&1); then
        echo "$name: povray failed"; tail -n 5 "$work/povray.log"; stale=1
    else
        cp "$work/live.png" "$workdir/$name.png"
        printf '%-24s ' "$name"
        if ! "$glint" compare "$workdir/$name.png" "$here/ref/$name.png" --tolerance 0 \
                --min-fraction 1; then
            echo "$name: reference is stale (run tests/golden/make_references.sh $name)"
            stale=1
        fi
    fi
    rm -rf "$work"
done < <(golden_scenes "$root")
exit $stale
