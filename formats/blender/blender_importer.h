// The Blender add-on's native exchange (FORMAT.md here): a JSON scene and its binary buffers
// into the IR. Coordinates stay Blender's (right-handed, Z up); meshes are held once however
// many objects instance them; materials, the world and lights keep their node graphs.
#pragma once

#include <string>

#include "core/log.h"
#include "scene/scene.h"

namespace glint::blender {

struct ImportLimits {
    long long triangles = 50'000'000;
    long long objects = 10'000'000;
};

// Whether `path` looks like the exchange's JSON (its extension is .json).
bool is_blender_exchange(const std::string& path);

// Throws Error(MissingFile) when the JSON or its buffers cannot be read, Error(Scene) naming
// the file (with line:col for JSON syntax) and the JSON path of what is wrong.
scene::Scene import_blender(const std::string& path, const ImportLimits& limits,
                            Diagnostics& diag);

}  // namespace glint::blender
