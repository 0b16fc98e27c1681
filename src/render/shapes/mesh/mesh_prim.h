// Triangle meshes (scene::Mesh) as one primitive with its own BVH in object space: per-face
// materials, interpolated normals and uvs; inside by ray parity along inside_vector.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/log.h"
#include "core/transform.h"
#include "render/shapes/mesh/mesh_kernels.h"
#include "render/shapes/primitive.h"
#include "scene/mesh.h"

namespace glint::render {

// nullptr (with warnings) when no face is usable; degenerate faces are skipped with a warning.
// With `baked`, the primitive lives in the parent space of that transform: rays are tested
// against the transformed vertices (no per-ray transform) and hits come out as
// transform_hit(baked) of the object-space hit. Only for transforms that bake_exact() accepts.
std::unique_ptr<Primitive> make_mesh(const scene::Mesh& mesh, Diagnostics& diag,
                                     const Transform* baked = nullptr);

// Consecutive meshes of one plain union (an OBJ's groups and objects) as one primitive: one BVH
// and one query for all, instead of a scene BVH leaf and a query each. Faces keep their order
// (part by part), so equal-t ties still go to the earlier part; a face without a material gets
// its part's. Each part's unusable faces are warned about at its own location.
struct MeshPart {
    const scene::Mesh* mesh;
    int material;
};
std::unique_ptr<Primitive> make_merged_mesh(const std::vector<MeshPart>& parts,
                                            Diagnostics& diag, const Transform* baked = nullptr);

// The BVH query of a primitive from make_mesh, below the primitive: the kernels' view of its
// triangles and the point their float corners are offsets from (a ray's origin goes into that
// frame by subtracting it). For bench/traversal_bench, which times the query alone against
// Embree's (which, like it, leaves the hit point and the unit normal to its caller). Null for
// any other primitive and for a baked mesh (whose rays are mirrored too).
struct MeshQuery {
    const MeshView* view;
    Vec3 origin;
};
std::optional<MeshQuery> mesh_query(const Primitive& prim);

// Whether a mesh behind `xf` can be baked with results identical bit for bit to transforming
// each ray: xf must be a pure mirror (a diagonal of +-1, no translation; obj_file's z-mirror is
// one). Then taking a ray into object space only flips signs, and the watertight triangle test
// computes the same t and barycentrics from either side.
bool bake_exact(const Transform& xf);

}  // namespace glint::render
