// Plane (POV-Ray 3.7 manual 2.4.1.13, IR convention): points with dot(p, normal) = distance;
// the inside is dot(p, normal) < distance. Infinite, no uv mapping.
// The hit point is projected back onto the plane, so its error is the rounding of the residual
// (pbrt-v4's reprojection idea applied to a plane), not the error of t.
#include <cmath>

#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

class PlanePrim final : public Primitive {
public:
    explicit PlanePrim(const scene::Plane& s)
        : n_(s.normal), d_(s.distance), nn_(dot(s.normal, s.normal)),
          unit_(normalize(s.normal)) {}

    // An axis-aligned plane bounds its inside on one side (POV-Ray's Plane::Compute_BBox),
    // which a CSG intersection with finite or slab-bounded partners turns into a finite box.
    Bounds3 bounds() const override {
        Bounds3 b{Vec3(-kInfinity), Vec3(kInfinity)};
        int axis = -1;
        for (int k = 0; k < 3; ++k) {
            if (n_[k] == 0) continue;
            if (axis >= 0) return b;
            axis = k;
        }
        if (axis < 0) return b;
        const double at = d_ / n_[axis];
        const double pad = 1e-9 * (1 + std::fabs(at));
        if (n_[axis] > 0) b.hi[axis] = at + pad;  // inside: coordinate below `at`
        else b.lo[axis] = at - pad;
        return b;
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        double denom = dot(ray.dir, n_);
        if (denom == 0 || !std::isfinite(denom)) return false;
        double num = d_ - dot(ray.origin, n_);
        // Origins within the rounding of the residual are on the plane: no hit (the surface a
        // secondary ray leaves from).
        double num_err = gamma(3) * (dot(abs(ray.origin), abs(n_)) + std::fabs(d_));
        if (std::fabs(num) <= num_err) return false;
        double t = num / denom;
        if (!(t > 0 && t < tmax)) return false;
        Vec3 p = ray.origin + ray.dir * t;
        double residual = dot(p, n_) - d_;
        p -= n_ * (residual / nn_);
        hit->t = t;
        hit->p = p;
        double e = gamma(5) * (dot(abs(p), abs(n_)) + std::fabs(d_)) / std::sqrt(nn_);
        hit->p_error = Vec3(e) + rounding_error(p, 2);
        hit->ng = unit_;
        hit->n = unit_;
        hit->has_uv = false;
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        LocalHit h;
        if (intersect(ray, tmax, &h)) hits->push_back(h);
    }

    bool inside(const Vec3& p) const override { return dot(p, n_) < d_; }

private:
    Vec3 n_;
    double d_;
    double nn_;
    Vec3 unit_;
};

}  // namespace

std::unique_ptr<Primitive> make_plane(const scene::Plane& s) {
    return std::make_unique<PlanePrim>(s);
}

}  // namespace glint::render
