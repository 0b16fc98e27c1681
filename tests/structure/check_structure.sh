#!/bin/bash
# The house rules of docs/architecture.md, checked on the source tree: which layer may include
# which, where the renderer's stages live, the POV-Ray token layer as a unit of its own, file
# sizes, and the README's front door. Prints every broken rule; exits 1 if there is any.
#
#   check_structure.sh REPO_ROOT
set -u
root=$1
cd "$root" || exit 2
broken=0
fail() { echo "structure: $*"; broken=1; }

# Layers: io sees images, never the renderer; importers never include the renderer; the
# application includes the renderer only through its facade and the film's public header.
for f in $(grep -l '#include "render/' src/io/* 2>/dev/null); do
    fail "$f includes the renderer (src/io must not)"
done
for f in $(grep -rl '#include "render/' formats 2>/dev/null); do
    fail "$f includes the renderer (importers must not)"
done
beyond=$(grep -Hn '#include "render/' src/app/* | grep -v '"render/render.h"\|"render/film/film.h"')
[ -z "$beyond" ] || fail "src/app includes the renderer beyond render.h and film/film.h:
$beyond"

# The renderer's stages, each in its room; the integrators alone in theirs.
for d in prepare lights film integrators sampling shader; do
    [ -d "src/render/$d" ] || fail "src/render/$d is missing"
done
# Shader graphs are evaluated without knowing who asks: render/shader includes no integrator,
# light or film header.
for f in $(grep -l '#include "render/\(integrators\|lights\|film\)/' src/render/shader/* 2>/dev/null); do
    fail "$f includes an integrator, light or film header (render/shader must not)"
done
n=$(ls src/render/integrators/*.cpp 2>/dev/null | wc -l)
[ "$n" -le 4 ] || fail "src/render/integrators holds $n .cpp files (at most 4: integrators only)"

# The POV-Ray token layer is a unit of its own: its files see the grammar only through the
# hooks token_stream.h declares, never through parser_impl.h.
for f in token_stream.cpp directives.cpp file_directives.cpp scanner.cpp literal_list.cpp \
         token_stream.h scanner.h literal_list.h; do
    [ -f "formats/pov/$f" ] || { fail "formats/pov/$f is missing"; continue; }
    grep -q '#include "formats/pov/parser_impl.h"' "formats/pov/$f" &&
        fail "formats/pov/$f (token layer) includes the grammar's parser_impl.h"
done

# No source file over 800 lines (reference tables a script generates, *_refs*.inc, are data).
while read -r count file; do
    [ "$file" = total ] && continue
    case "$file" in *_refs*.inc) continue ;; esac
    [ "$count" -le 800 ] || fail "$file has $count lines (over 800)"
done < <(find src formats tests bench fuzz plugin \( -name '*.cpp' -o -name '*.h' -o \
         -name '*.inc' -o -name '*.py' \) -print0 | xargs -0 wc -l)

# The front door: under 300 lines, a picture in the first 30.
lines=$(wc -l < README.md)
[ "$lines" -lt 300 ] || fail "README.md has $lines lines (under 300 wanted)"
head -30 README.md | grep -q '!\[\|<img' || fail "README.md shows no picture in its first 30 lines"

[ $broken -eq 0 ] && echo "structure: all rules hold"
exit $broken
