// disc (POV-Ray 3.7 manual 2.4.2.1): a flat ring in the plane through `center` with `normal`,
// between hole_radius and radius. Solved in a frame where the disc lies in z = 0. Inside is
// POV-Ray's (discs.cpp, Disc::Inside): the half-space behind the normal.
#include <cmath>

#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

class DiscPrim final : public Primitive {
public:
    DiscPrim(double r, double hole) : r2_(r * r), h2_(hole * hole), r_(r) {}

    Bounds3 bounds() const override {
        double r = r_ * (1 + gamma(2));
        return {Vec3(-r, -r, 0), Vec3(r, r, 0)};
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        const Vec3 &o = ray.origin, &d = ray.dir;
        if (d.z == 0) return false;
        double t = -o.z / d.z;
        if (!(t > 0) || !(t < tmax)) return false;
        Vec3 p(o.x + t * d.x, o.y + t * d.y, 0);
        double w2 = p.x * p.x + p.y * p.y;
        if (w2 > r2_ || w2 < h2_) return false;
        hit->t = t;
        hit->p = p;
        hit->p_error = rounding_error(p, 2);
        hit->ng = Vec3(0, 0, 1);
        hit->n = hit->ng;
        hit->has_uv = false;
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        LocalHit h;
        if (intersect(ray, tmax, &h)) hits->push_back(h);
    }

    bool inside(const Vec3& p) const override { return p.z < 0; }

private:
    double r2_, h2_, r_;
};

}  // namespace

std::unique_ptr<Primitive> make_disc(const scene::Disc& s, Transform* frame, const char** why) {
    if (!is_finite(s.center) || !is_finite(s.normal) || !(length_squared(s.normal) > 0) ||
        !std::isfinite(s.radius) || !std::isfinite(s.hole_radius) || !(s.radius != 0)) {
        *why = "disc with zero normal or radius";
        return nullptr;
    }
    *frame = axis_frame(s.center, normalize(s.normal));
    return std::make_unique<DiscPrim>(std::fabs(s.radius), std::fabs(s.hole_radius));
}

}  // namespace glint::render
