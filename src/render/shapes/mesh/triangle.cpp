// triangle and smooth_triangle (POV-Ray 3.7 manual 2.4.2.5 and 2.4.2.4), and the watertight
// test they share with meshes.
#include "render/shapes/mesh/triangle.h"

#include <cmath>

#include "render/shapes/shapes.h"

namespace glint::render {

namespace {

class TrianglePrim final : public Primitive {
public:
    TrianglePrim(const Vec3 p[3], const Vec3* n) : p_{p[0], p[1], p[2]}, smooth_(n != nullptr) {
        ng_ = normalize(cross(p[1] - p[0], p[2] - p[0]));
        for (int i = 0; i < 3; ++i) n_[i] = smooth_ ? n[i] : ng_;
    }

    Bounds3 bounds() const override {
        Bounds3 b;
        for (const Vec3& p : p_) b.extend(p);
        return b;
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        TriangleHit th;
        if (!intersect_triangle(RayShear(ray), p_[0], p_[1], p_[2], tmax, &th)) return false;
        hit->t = th.t;
        hit->p = triangle_point(p_[0], p_[1], p_[2], th.b, &hit->p_error);
        hit->ng = ng_;
        hit->n = ng_;
        if (smooth_) {
            Vec3 n = n_[0] * th.b[0] + n_[1] * th.b[1] + n_[2] * th.b[2];
            double len = length(n);
            if (len > 0 && std::isfinite(len)) {
                n = n / len;
                hit->n = dot(n, ng_) < 0 ? -n : n;
            }
        }
        hit->has_uv = false;
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        LocalHit h;
        if (intersect(ray, tmax, &h)) hits->push_back(h);
    }

    // POV-Ray: triangles have no inside.
    bool inside(const Vec3&) const override { return false; }

private:
    Vec3 p_[3];
    Vec3 n_[3];
    Vec3 ng_;
    bool smooth_;
};

}  // namespace

std::unique_ptr<Primitive> make_triangle(const Vec3 p[3], const Vec3* normals) {
    for (int i = 0; i < 3; ++i)
        if (!is_finite(p[i])) return nullptr;
    Vec3 c = cross(p[1] - p[0], p[2] - p[0]);
    if (!(length_squared(c) > 0) || !is_finite(c)) return nullptr;
    if (normals) {
        for (int i = 0; i < 3; ++i)
            if (!is_finite(normals[i])) {
                normals = nullptr;
                break;
            }
    }
    return std::make_unique<TrianglePrim>(p, normals);
}

}  // namespace glint::render
