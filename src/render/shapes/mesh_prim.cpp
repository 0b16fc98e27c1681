// mesh / mesh2 (POV-Ray 3.7 manual 2.4.2.2-3) and OBJ meshes: the faces of a scene::Mesh
// behind their own BVH in object space.
#include "render/shapes/mesh_prim.h"

#include <cmath>
#include <optional>
#include <string>

#include "render/accel/bvh.h"
#include "render/shapes/object_node.h"
#include "render/shapes/triangle.h"

namespace glint::render {
namespace {

class MeshPrim final : public Primitive {
public:
    MeshPrim(const scene::Mesh& mesh, std::vector<int> faces, const Transform* baked)
        : mesh_(mesh), faces_(std::move(faces)) {
        if (baked) {
            baked_ = true;
            xf_ = *baked;
        }
        std::vector<Bounds3> boxes(faces_.size());
        for (size_t i = 0; i < faces_.size(); ++i)
            for (int k = 0; k < 3; ++k) boxes[i].extend(vertex(faces_[i], k));
        // Baked: the object-space tree, mirrored, so rays meet the faces in the same order.
        bvh_ = Bvh(boxes, 4);
        if (baked_) {
            const auto& m = xf_.matrix().m;
            const bool flip[3] = {m[0][0] < 0, m[1][1] < 0, m[2][2] < 0};
            bvh_.mirror(flip);
        }
        // Faces and their vertices in leaf order: a leaf's triangles sit side by side.
        std::vector<int> sorted(bvh_.order().size());
        tris_.resize(sorted.size());
        for (size_t i = 0; i < sorted.size(); ++i) {
            sorted[i] = faces_[bvh_.order()[i]];
            for (int k = 0; k < 3; ++k) tris_[i].p[k] = tested_vertex(sorted[i], k);
        }
        faces_ = std::move(sorted);
        bvh_.use_leaf_order();
        single_leaf_ = bvh_.nodes().size() == 1;
        if (mesh.has_inside_vector && length_squared(mesh.inside_vector) > 0)
            inside_dir_ = baked_ ? xf_.vector(mesh.inside_vector) : mesh.inside_vector;
    }

    Bounds3 bounds() const override { return bvh_.bounds(); }
    bool writes_whole_hit() const override { return true; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        RayShear shear(ray);
        TriangleHit best;
        int best_face = -1;
        double t = tmax;
        candidates(ray, t, [&](int i, double& tm) {
            TriangleHit th;
            int f = faces_[i];
            // Equal t: the lower face index wins, whatever the traversal order.
            double limit = best_face < 0 ? tm : next_up(tm);
            const Tri& tri = tris_[i];
            if (intersect_triangle(shear, tri.p[0], tri.p[1], tri.p[2], limit, &th) &&
                (best_face < 0 || th.t < best.t || f < best_face)) {
                best = th;
                best_face = f;
                tm = th.t;
            }
            return false;
        });
        if (best_face < 0) return false;
        fill(best_face, best, hit);
        return true;
    }

    bool occludes(const Ray& ray, double tmax) const override {
        RayShear shear(ray);
        double t = tmax;
        return candidates(ray, t, [&](int i, double&) {
            TriangleHit th;
            const Tri& tri = tris_[i];
            return intersect_triangle(shear, tri.p[0], tri.p[1], tri.p[2], tmax, &th);
        });
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        RayShear shear(ray);
        double t = tmax;
        candidates(ray, t, [&](int i, double&) {
            TriangleHit th;
            int f = faces_[i];
            const Tri& tri = tris_[i];
            if (intersect_triangle(shear, tri.p[0], tri.p[1], tri.p[2], tmax, &th))
                fill(f, th, &hits->emplace_back());
            return false;
        });
    }

    // POV-Ray (mesh.cpp, Mesh::Inside): a point is inside when a ray from it along
    // inside_vector crosses the surface an odd number of times. Without one, never inside.
    bool inside(const Vec3& p) const override {
        if (!inside_dir_) return false;
        Ray ray{p, *inside_dir_, kInfinity};
        RayShear shear(ray);
        int crossings = 0;
        double t = kInfinity;
        bvh_.traverse(ray, t, [&](int i, double&) {
            TriangleHit th;
            const Tri& tri = tris_[i];
            if (intersect_triangle(shear, tri.p[0], tri.p[1], tri.p[2], kInfinity, &th))
                ++crossings;
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
        for (int i = 0; i < static_cast<int>(tris_.size()); ++i)
            if (visit(i, tmax)) return true;
        return false;
    }

    const Vec3& vertex(int face, int k) const {
        return mesh_.positions[mesh_.faces[face].v[k]];
    }
    // The vertex as rays meet it: in the baked transform's parent space when baked.
    Vec3 tested_vertex(int face, int k) const {
        return baked_ ? xf_.point(vertex(face, k)) : vertex(face, k);
    }

    // Writes all of *h (writes_whole_hit).
    void fill(int f, const TriangleHit& th, LocalHit* h) const {
        *h = LocalHit();
        const scene::MeshFace& face = mesh_.faces[f];
        const Vec3 &p0 = vertex(f, 0), &p1 = vertex(f, 1), &p2 = vertex(f, 2);
        h->t = th.t;
        h->p = triangle_point(p0, p1, p2, th.b, &h->p_error);
        h->ng = normalize(cross(p1 - p0, p2 - p0));
        h->n = h->ng;
        if (face.n[0] >= 0 && face.n[1] >= 0 && face.n[2] >= 0) {
            Vec3 n = mesh_.normals[face.n[0]] * th.b[0] + mesh_.normals[face.n[1]] * th.b[1] +
                     mesh_.normals[face.n[2]] * th.b[2];
            double len = length(n);
            if (len > 0 && std::isfinite(len)) {
                n = n / len;
                h->n = dot(n, h->ng) < 0 ? -n : n;
            }
        }
        h->has_uv = face.uv[0] >= 0 && face.uv[1] >= 0 && face.uv[2] >= 0;
        if (h->has_uv) {
            const Vec2 &t0 = mesh_.uvs[face.uv[0]], &t1 = mesh_.uvs[face.uv[1]],
                       &t2 = mesh_.uvs[face.uv[2]];
            h->uv = t0 * th.b[0] + t1 * th.b[1] + t2 * th.b[2];
            // The triangle's uv tangents: p - p2 = dpdu (u - u2) + dpdv (v - v2) solved over
            // its two edges; zero when the uvs are degenerate (no tangent frame).
            const Vec2 d02 = t0 - t2, d12 = t1 - t2;
            const double det = d02.x * d12.y - d02.y * d12.x;
            if (std::fabs(det) > 1e-12) {
                const Vec3 e02 = p0 - p2, e12 = p1 - p2;
                const double inv = 1 / det;
                h->dpdu = (e02 * d12.y - e12 * d02.y) * inv;
                h->dpdv = (e12 * d02.x - e02 * d12.x) * inv;
            }
        }
        h->material = face.material;
        // Baked: the hit was computed in object space terms (bake_exact transforms give the
        // same t and barycentrics there), so carry it out exactly as ObjectNode would.
        if (baked_) transform_hit(xf_, h);
    }

    // A copy: the geometry must not depend on the scene outliving it.
    scene::Mesh mesh_;
    struct Tri {
        Vec3 p[3];
    };
    std::vector<int> faces_;  // usable faces of mesh_, in BVH leaf order
    std::vector<Tri> tris_;   // their vertices
    Bvh bvh_;
    std::optional<Vec3> inside_dir_;  // in the tested space
    bool baked_ = false;
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
    return std::make_unique<MeshPrim>(mesh, std::move(usable), baked);
}

}  // namespace glint::render
