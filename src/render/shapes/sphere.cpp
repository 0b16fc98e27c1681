// Sphere (POV-Ray 3.7 manual 2.4.1.11): |p - center| = radius.
// Roots by the numerically careful quadratic of Ray Tracing Gems, ch. 7 ("Precision
// Improvements for Ray/Sphere Intersection"): the discriminant from the distance of the centre
// to the ray line, the near root from Vieta's formula. Hit points are reprojected onto the
// sphere (pbrt-v4, 6.8.5), so their error is a few ulps of the radius at any scale.
#include <cmath>

#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

class SpherePrim final : public Primitive {
public:
    explicit SpherePrim(const scene::Sphere& s) : c_(s.center), r_(std::fabs(s.radius)) {}

    Bounds3 bounds() const override {
        Bounds3 b;
        b.extend(c_ - Vec3(r_));
        b.extend(c_ + Vec3(r_));
        Vec3 e = rounding_error(c_, 2) + Vec3(r_ * gamma(2));
        b.lo -= e;
        b.hi += e;
        return b;
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        if (!reachable(ray, tmax)) return false;
        double t[2];
        int n = roots(ray, t);
        for (int i = 0; i < n; ++i)
            if (t[i] < tmax) {
                fill(ray, t[i], hit);
                return true;
            }
        return false;
    }

    bool occludes(const Ray& ray, double tmax) const override {
        if (!reachable(ray, tmax)) return false;
        double t[2];
        int n = roots(ray, t);
        return (n > 0 && t[0] < tmax) || (n > 1 && t[1] < tmax);
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        if (!reachable(ray, tmax)) return;
        double t[2];
        int n = roots(ray, t);
        for (int i = 0; i < n; ++i)
            if (t[i] < tmax) fill(ray, t[i], &hits->emplace_back());
    }

    bool inside(const Vec3& p) const override { return length_squared(p - c_) < r_ * r_; }

private:
    // Whether the ray can reach the surface before tmax. Shadow rays and rays behind a nearer
    // hit mostly end short of it (a sky sphere around the scene is tested by every ray): the
    // surface is |fl - r| from the origin, the ray goes no farther than tmax |d|. The margin
    // covers the rounding of both sides many times over, so the roots still decide every ray
    // that could hit.
    bool reachable(const Ray& ray, double tmax) const {
        if (!std::isfinite(tmax)) return true;
        const double fl = length(ray.origin - c_), reach = tmax * length(ray.dir);
        return !(std::fabs(fl - r_) > reach + gamma(16) * (fl + r_ + reach));
    }

    // Roots with 0 < t, ascending. A root whose error interval reaches 0 is dropped: that is
    // the surface a (properly offset) secondary ray leaves from.
    int roots(const Ray& ray, double out[2]) const {
        const Vec3& d = ray.dir;
        Vec3 f = ray.origin - c_;
        double a = dot(d, d);
        if (!(a > 0)) return 0;
        double bh = dot(f, d);
        Vec3 l = f - d * (bh / a);
        double ll = length(l);
        double disc = (r_ - ll) * (r_ + ll);
        if (!(disc >= 0)) return 0;
        double sd = std::sqrt(a * disc);
        double q = -(bh + std::copysign(sd, bh));
        if (q == 0) return 0;
        double fl = length(f);
        double c = (fl - r_) * (fl + r_);
        double t_far = q / a, t_near = c / q;
        double e_far = gamma(8) * (fl * std::sqrt(a) + sd) / a;
        double e_near = (gamma(3) * fl * (fl + r_) + gamma(1) * std::fabs(c)) / std::fabs(q) +
                        gamma(3) * std::fabs(t_near);
        double t0 = t_near, t1 = t_far, e0 = e_near, e1 = e_far;
        if (t0 > t1) {
            std::swap(t0, t1);
            std::swap(e0, e1);
        }
        int n = 0;
        if (t0 > e0) out[n++] = t0;
        if (t1 > e1) out[n++] = t1;
        return n;
    }

    void fill(const Ray& ray, double t, LocalHit* h) const {
        Vec3 pl = ray.origin + ray.dir * t - c_;
        double len = length(pl);
        if (len > 0) pl = pl * (r_ / len);
        h->t = t;
        h->p = c_ + pl;
        h->p_error = rounding_error(pl, 5) + rounding_error(h->p, 1);
        h->ng = len > 0 ? pl / r_ : Vec3(0, 1, 0);
        h->n = h->ng;
        h->uv_source = this;
        h->uv_point = h->ng;
        h->has_uv = true;
    }

    // POV-Ray's sphere uv_mapping (spheres.cpp, Sphere::UVCoord): u is the angle around y
    // measured from +x towards +z, v the latitude, both in [0, 1]. `n`: the unit normal.
    Vec2 uv_at(const Vec3& n) const override {
        return {turn_about_y(n.x, n.z), 0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / kPi};
    }

    Vec3 c_;
    double r_;
};

}  // namespace

std::unique_ptr<Primitive> make_sphere(const scene::Sphere& s) {
    return std::make_unique<SpherePrim>(s);
}

}  // namespace glint::render
