// mesh / mesh2 (POV-Ray 3.7 manual 2.4.2.2-3) and OBJ meshes: the faces of a scene::Mesh
// behind their own BVH in object space.
#include "render/shapes/mesh_prim.h"

#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "render/accel/bvh.h"
#include "render/shapes/object_node.h"
#include "render/shapes/triangle.h"

namespace glint::render {
namespace {

// Memory per triangle (bench/traversal_bench.cpp measures it): the vertex positions (shared by
// about two triangles each), 12 bytes of vertex indices, 4 of face index and the BVH's
// share; normal, uv and material indices only for meshes that have them, and none where they
// repeat the vertex indices (mesh2 without normal_indices, OBJ written per vertex).
class MeshPrim final : public Primitive {
public:
    MeshPrim(const scene::Mesh& mesh, const std::vector<int>& faces, const Transform* baked)
        : pos_(mesh.positions) {
        if (baked) {
            baked_ = true;
            xf_ = *baked;
            const auto& m = xf_.matrix().m;
            for (int a = 0; a < 3; ++a) flip_[a] = m[a][a] < 0;
        }
        std::vector<Bounds3> boxes(faces.size());
        for (size_t i = 0; i < faces.size(); ++i)
            for (int k = 0; k < 3; ++k) boxes[i].extend(pos_[mesh.faces[faces[i]].v[k]]);
        bvh_ = Bvh(boxes, 4);
        // Faces in leaf order: a leaf's triangles sit side by side.
        const std::vector<int>& order = bvh_.order();
        const size_t n = order.size();
        bool has_normals = false, normals_like_v = true, has_uvs = false, uvs_like_v = true,
             has_material = false;
        for (int i : order) {
            const scene::MeshFace& f = mesh.faces[faces[i]];
            has_normals = has_normals || f.n[0] >= 0 || f.n[1] >= 0 || f.n[2] >= 0;
            normals_like_v = normals_like_v && f.n == f.v;
            has_uvs = has_uvs || f.uv[0] >= 0 || f.uv[1] >= 0 || f.uv[2] >= 0;
            uvs_like_v = uvs_like_v && f.uv == f.v;
            has_material = has_material || f.material >= 0;
        }
        tri_.resize(n);
        face_.resize(n);
        for (size_t i = 0; i < n; ++i) {
            face_[i] = faces[order[i]];
            tri_[i] = mesh.faces[face_[i]].v;
        }
        if (has_normals) {
            normals_ = mesh.normals;
            if (!normals_like_v) {
                nidx_.resize(n);
                for (size_t i = 0; i < n; ++i) nidx_[i] = mesh.faces[face_[i]].n;
            }
        }
        if (has_uvs) {
            uvs_ = mesh.uvs;
            if (!uvs_like_v) {
                uvidx_.resize(n);
                for (size_t i = 0; i < n; ++i) uvidx_[i] = mesh.faces[face_[i]].uv;
            }
        }
        if (has_material) {
            material_.resize(n);
            for (size_t i = 0; i < n; ++i) material_[i] = mesh.faces[face_[i]].material;
        }
        bvh_.use_leaf_order();
        single_leaf_ = bvh_.single_leaf();
        if (mesh.has_inside_vector && length_squared(mesh.inside_vector) > 0)
            inside_dir_ = mesh.inside_vector;
    }

    // Baked: the object-space box mirrored into the parent space (exact).
    Bounds3 bounds() const override {
        Bounds3 b = bvh_.bounds();
        for (int a = 0; a < 3; ++a)
            if (flip_[a]) {
                const double lo = b.lo[a];
                b.lo[a] = -b.hi[a];
                b.hi[a] = -lo;
            }
        return b;
    }
    bool writes_whole_hit() const override { return true; }

    bool intersect(const Ray& parent_ray, double tmax, LocalHit* hit) const override {
        const Ray ray = to_object(parent_ray);
        RayShear shear(ray);
        TriangleHit best;
        int best_i = -1;
        double t = tmax;
        candidates(ray, t, [&](int i, double& tm) {
            TriangleHit th;
            // Equal t: the lower face index wins, whatever the traversal order.
            double limit = best_i < 0 ? tm : next_up(tm);
            if (test(shear, i, limit, &th) &&
                (best_i < 0 || th.t < best.t || face_[i] < face_[best_i])) {
                best = th;
                best_i = i;
                tm = th.t;
            }
            return false;
        });
        if (best_i < 0) return false;
        fill(best_i, best, hit);
        return true;
    }

    bool occludes(const Ray& parent_ray, double tmax) const override {
        const Ray ray = to_object(parent_ray);
        RayShear shear(ray);
        double t = tmax;
        return candidates(ray, t, [&](int i, double&) {
            TriangleHit th;
            return test(shear, i, tmax, &th);
        });
    }

    void intersect_all(const Ray& parent_ray, double tmax, HitList* hits) const override {
        const Ray ray = to_object(parent_ray);
        RayShear shear(ray);
        double t = tmax;
        candidates(ray, t, [&](int i, double&) {
            TriangleHit th;
            if (test(shear, i, tmax, &th)) fill(i, th, &hits->emplace_back());
            return false;
        });
    }

    // POV-Ray (mesh.cpp, Mesh::Inside): a point is inside when a ray from it along
    // inside_vector crosses the surface an odd number of times. Without one, never inside.
    bool inside(const Vec3& parent_p) const override {
        if (!inside_dir_) return false;
        const Ray ray{mirrored(parent_p), *inside_dir_, kInfinity};
        RayShear shear(ray);
        int crossings = 0;
        double t = kInfinity;
        bvh_.traverse(ray, t, [&](int i, double&) {
            TriangleHit th;
            if (test(shear, i, kInfinity, &th)) ++crossings;
            return false;
        });
        return crossings % 2 == 1;
    }

private:
    // The triangles a ray may hit, as Bvh::traverse passes them. A mesh that is one BVH leaf
    // (a wall, a quad: many OBJ groups) skips the box test: its owner's bounds have already
    // been tested, and the triangle test alone decides, so the results are the same.
    template <class Visit>
    bool candidates(const Ray& ray, double& tmax, Visit&& visit) const {
        if (!single_leaf_) return bvh_.traverse(ray, tmax, visit);
        for (int i = 0; i < static_cast<int>(tri_.size()); ++i)
            if (visit(i, tmax)) return true;
        return false;
    }

    bool test(const RayShear& shear, int i, double tmax, TriangleHit* th) const {
        const auto& v = tri_[static_cast<size_t>(i)];
        return intersect_triangle(shear, pos_[v[0]], pos_[v[1]], pos_[v[2]], tmax, th);
    }

    // Baked (a pure mirror, bake_exact): the ray in object space is the parent-space ray with
    // the mirrored components negated, exactly what the transform's matrix computes.
    Vec3 mirrored(Vec3 v) const {
        for (int a = 0; a < 3; ++a)
            if (flip_[a]) v[a] = -v[a];
        return v;
    }
    Ray to_object(const Ray& r) const {
        if (!baked_) return r;
        return {mirrored(r.origin), mirrored(r.dir), r.tmax};
    }

    // Writes all of *h (writes_whole_hit), for the triangle at leaf position i.
    void fill(int i, const TriangleHit& th, LocalHit* h) const {
        *h = LocalHit();
        const size_t at = static_cast<size_t>(i);
        const auto& v = tri_[at];
        const Vec3 &p0 = pos_[v[0]], &p1 = pos_[v[1]], &p2 = pos_[v[2]];
        h->t = th.t;
        h->p = triangle_point(p0, p1, p2, th.b, &h->p_error);
        h->ng = normalize(cross(p1 - p0, p2 - p0));
        h->n = h->ng;
        if (!normals_.empty()) {
            const auto& ni = nidx_.empty() ? v : nidx_[at];
            if (ni[0] >= 0 && ni[1] >= 0 && ni[2] >= 0) {
                Vec3 n = normals_[ni[0]] * th.b[0] + normals_[ni[1]] * th.b[1] +
                         normals_[ni[2]] * th.b[2];
                double len = length(n);
                if (len > 0 && std::isfinite(len)) {
                    n = n / len;
                    h->n = dot(n, h->ng) < 0 ? -n : n;
                }
            }
        }
        if (!uvs_.empty()) {
            const auto& ui = uvidx_.empty() ? v : uvidx_[at];
            h->has_uv = ui[0] >= 0 && ui[1] >= 0 && ui[2] >= 0;
            if (h->has_uv) {
                const Vec2 &t0 = uvs_[ui[0]], &t1 = uvs_[ui[1]], &t2 = uvs_[ui[2]];
                h->uv = t0 * th.b[0] + t1 * th.b[1] + t2 * th.b[2];
                // The triangle's uv tangents: p - p2 = dpdu (u - u2) + dpdv (v - v2) solved
                // over its two edges; zero when the uvs are degenerate (no tangent frame).
                const Vec2 d02 = t0 - t2, d12 = t1 - t2;
                const double det = d02.x * d12.y - d02.y * d12.x;
                if (std::fabs(det) > 1e-12) {
                    const Vec3 e02 = p0 - p2, e12 = p1 - p2;
                    const double inv = 1 / det;
                    h->dpdu = (e02 * d12.y - e12 * d02.y) * inv;
                    h->dpdv = (e12 * d02.x - e02 * d12.x) * inv;
                }
            }
        }
        h->material = material_.empty() ? -1 : material_[at];
        // Baked: the hit was computed in object space, so carry it out exactly as ObjectNode
        // would.
        if (baked_) transform_hit(xf_, h);
    }

    using Index3 = std::array<int, 3>;
    std::vector<Vec3> pos_;      // object space; copies: the scene need not outlive the geometry
    std::vector<Index3> tri_;    // vertex indices, in BVH leaf order
    std::vector<int> face_;      // the scene mesh's face index, in leaf order (ties break by it)
    std::vector<Vec3> normals_;  // empty: flat
    std::vector<Index3> nidx_;   // empty: the vertex indices
    std::vector<Vec2> uvs_;      // empty: no uvs
    std::vector<Index3> uvidx_;  // empty: the vertex indices
    std::vector<int> material_;  // empty: every face -1
    Bvh bvh_;
    std::optional<Vec3> inside_dir_;  // object space
    bool baked_ = false;
    bool flip_[3] = {false, false, false};
    bool single_leaf_ = false;  // the whole mesh is one BVH leaf
    Transform xf_;  // the baked transform
};

}  // namespace

bool bake_exact(const Transform& xf) {
    if (xf.is_identity()) return false;
    const auto& m = xf.matrix().m;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double v = m[i][j];
            bool ok = i == j ? (v == 1 || (v == -1 && i < 3)) : v == 0;
            if (!ok) return false;
        }
    return xf.inverse_matrix() == xf.matrix();
}

std::unique_ptr<Primitive> make_mesh(const scene::Mesh& mesh, Diagnostics& diag,
                                     const Transform* baked) {
    std::vector<int> usable;
    int degenerate = 0, bad_index = 0;
    int np = static_cast<int>(mesh.positions.size());
    int nn = static_cast<int>(mesh.normals.size());
    int nuv = static_cast<int>(mesh.uvs.size());
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        const scene::MeshFace& face = mesh.faces[f];
        bool ok = true;
        for (int k = 0; k < 3; ++k) {
            ok = ok && face.v[k] >= 0 && face.v[k] < np && face.n[k] < nn && face.uv[k] < nuv;
        }
        if (!ok) {
            ++bad_index;
            continue;
        }
        const Vec3 &p0 = mesh.positions[face.v[0]], &p1 = mesh.positions[face.v[1]],
                   &p2 = mesh.positions[face.v[2]];
        Vec3 c = cross(p1 - p0, p2 - p0);
        // A vertex beyond 1e15 (VALIDATION.md case 7's 1e30) is corrupt input, not geometry:
        // there a double cannot resolve 1/8 of a unit, and the triangle would cut the scene
        // as a sliver of unbounded size.
        constexpr double kMaxCoordinate = 1e15;
        auto sane = [&](const Vec3& p) {
            return std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate &&
                   std::fabs(p.z) <= kMaxCoordinate;
        };
        if (!sane(p0) || !sane(p1) || !sane(p2) || !is_finite(c) ||
            !(length_squared(c) > 0)) {
            ++degenerate;
            continue;
        }
        usable.push_back(static_cast<int>(f));
    }
    if (degenerate > 0)
        diag.warning(mesh.loc, std::to_string(degenerate) +
                                   " degenerate mesh triangle(s) (zero area, or vertices not "
                                   "finite or beyond 1e15) skipped");
    if (bad_index > 0)
        diag.warning(mesh.loc,
                     std::to_string(bad_index) + " mesh triangle(s) with invalid indices skipped");
    if (usable.empty()) return nullptr;
    return std::make_unique<MeshPrim>(mesh, usable, baked);
}

}  // namespace glint::render
