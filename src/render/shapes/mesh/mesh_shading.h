// What a hit on a mesh triangle carries besides its point, shared by the still meshes
// (mesh_prim.cpp) and the deforming ones (motion_mesh.cpp): the interpolated shading normal,
// the uv with its tangents, and the named attributes' lookup.
#pragma once

#include <cmath>
#include <string_view>

#include "render/ray.h"
#include "render/shapes/primitive.h"
#include "scene/mesh.h"

namespace glint::render {

// The shading normal from the corners' normals at barycentrics b, turned to ng's side; ng
// where they cancel out or are not finite.
inline Vec3 interpolated_normal(const Vec3& n0, const Vec3& n1, const Vec3& n2, const double b[3],
                                const Vec3& ng) {
    Vec3 n = n0 * b[0] + n1 * b[1] + n2 * b[2];
    const double len = length(n);
    if (!(len > 0) || !std::isfinite(len)) return ng;
    n = n / len;
    return dot(n, ng) < 0 ? -n : n;
}

// h->uv at barycentrics b and the triangle's uv tangents: p - p2 = dpdu (u - u2) + dpdv (v - v2)
// solved over its two edges; zero tangents when the uvs are degenerate (no tangent frame).
inline void interpolate_uv(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec2& t0,
                           const Vec2& t1, const Vec2& t2, const double b[3], LocalHit* h) {
    h->uv = t0 * b[0] + t1 * b[1] + t2 * b[2];
    const Vec2 d02 = t0 - t2, d12 = t1 - t2;
    const double det = d02.x * d12.y - d02.y * d12.x;
    if (std::fabs(det) > 1e-12) {
        const Vec3 e02 = p0 - p2, e12 = p1 - p2;
        const double inv = 1 / det;
        h->dpdu = (e02 * d12.y - e12 * d02.y) * inv;
        h->dpdv = (e12 * d02.x - e02 * d12.x) * inv;
    }
}

// AttributeSource::attribute over a scene mesh's named attributes (Mesh::attributes, read
// through Mesh::corners) at scene face `face`.
bool mesh_attribute(const scene::Mesh& mesh, std::string_view name, AttributeSource::Want want,
                    int face, double b1, double b2, Vec3* value, double* alpha);
// AttributeSource::corner_normal over a scene mesh's normals (of its frame, for a deforming
// one).
bool mesh_corner_normal(const scene::Mesh& mesh, int face, double b1, double b2, Vec3* n);

}  // namespace glint::render
