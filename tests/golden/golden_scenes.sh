# Sourced by the golden-suite scripts: lists "NAME PATH" for every golden scene (the POV-Ray
# examples in examples.txt, then every scenes/*.pov), PATH relative to the repository root.
# CMake reads the same two sources (tests/golden/CMakeLists.txt), so the lists cannot drift.
golden_scenes() {
    local root=$1 path
    grep -v '^#' "$root/tests/golden/examples.txt" | while read -r path; do
        [ -n "$path" ] && echo "pov_$(basename "$path" .pov) $path"
    done
    for path in "$root"/scenes/*.pov; do
        echo "$(basename "$path" .pov) scenes/$(basename "$path")"
    done
}
