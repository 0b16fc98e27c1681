// Triangle meshes (scene::Mesh) as one primitive with its own BVH in object space: per-face
// materials, interpolated normals and uvs; inside by ray parity along inside_vector.
#pragma once

#include <memory>

#include "core/log.h"
#include "render/shapes/primitive.h"
#include "scene/mesh.h"

namespace glint::render {

// nullptr (with warnings) when no face is usable; degenerate faces are skipped with a warning.
std::unique_ptr<Primitive> make_mesh(const scene::Mesh& mesh, Diagnostics& diag);

}  // namespace glint::render
