// torus (POV-Ray 3.7 manual 2.4.3.6): major radius R around the y axis in the xz-plane, tube
// radius r: (x^2 + y^2 + z^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2).
// The quartic is set up in a well-scaled frame: unit direction, origin moved to where the ray
// enters the bounding sphere, so coefficients are O((R + r)^k) whatever the ray. Roots come from
// the derivative-splitting solver (poly_solve.h); hit points are reprojected onto the tube.
// `sturm` takes the same path: it is already the robust one.
#include <cmath>

#include "render/shapes/polynomial/poly_solve.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

class TorusPrim final : public Primitive {
public:
    TorusPrim(double major, double minor) : R_(major), r_(minor), rb_(major + minor) {}

    Bounds3 bounds() const override {
        double e = rb_ * (1 + gamma(2));
        double h = r_ * (1 + gamma(2));
        return {Vec3(-e, -h, -e), Vec3(e, h, e)};
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        double t[4];
        Frame f;
        int n = roots(ray, tmax, t, &f);
        if (n == 0) return false;
        fill(f, t[0], hit);
        return true;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        double t[4];
        Frame f;
        int n = roots(ray, tmax, t, &f);
        for (int i = 0; i < n; ++i) fill(f, t[i], &hits->emplace_back());
    }

    bool inside(const Vec3& p) const override {
        double w = std::sqrt(p.x * p.x + p.z * p.z) - R_;
        return w * w + p.y * p.y < r_ * r_;
    }

private:
    struct Frame {
        Vec3 o;         // ray origin moved to s0 along the unit direction
        Vec3 dn;        // unit direction
        double s0;      // where o sits, in unit-direction units from the ray origin
        double len;     // |ray.dir|
    };

    // Roots as ray parameters t, ascending, with 0 < t < tmax.
    int roots(const Ray& ray, double tmax, double out[4], Frame* f) const {
        f->len = length(ray.dir);
        if (!(f->len > 0) || !std::isfinite(f->len)) return 0;
        f->dn = ray.dir / f->len;
        // The bounding sphere |p| <= R + r, by the stable form (Ray Tracing Gems ch. 7).
        double b = dot(ray.origin, f->dn);
        Vec3 l = ray.origin - f->dn * b;
        double ll = length(l);
        double rb = rb_ * (1 + gamma(4));
        double disc = (rb - ll) * (rb + ll);
        if (!(disc >= 0)) return 0;
        // Widened a little: the torus touches its bounding sphere along the equator, and a root
        // there must not fall just outside the interval by rounding.
        double half = std::sqrt(disc) + 0.01 * rb_;
        double s_in = -b - half, s_out = -b + half;
        // The whole chord, not cut at tmax: the roots (and so the hits) must not depend on how
        // far the caller happens to look.
        double s_max = s_out;
        if (s_max <= 0 || std::max(s_in, 0.0) >= tmax * f->len) return 0;
        f->s0 = std::max(s_in, 0.0);
        f->o = ray.origin + f->dn * f->s0;
        const Vec3 &o = f->o, &d = f->dn;
        double R2 = R_ * R_, r2 = r_ * r_;
        // G(u) = |o + u d|^2 + R^2 - r^2 = u^2 + g1 u + g0
        double g1 = 2 * dot(o, d);
        double g0 = dot(o, o) + (R2 - r2);
        // (x^2 + z^2)(u) = a2 u^2 + a1 u + a0
        double a2 = d.x * d.x + d.z * d.z;
        double a1 = 2 * (o.x * d.x + o.z * d.z);
        double a0 = o.x * o.x + o.z * o.z;
        double k = 4 * R2;
        double c[5] = {g0 * g0 - k * a0, 2 * g1 * g0 - k * a1, g1 * g1 + 2 * g0 - k * a2, 2 * g1,
                       1};
        double u[4];
        int n = real_roots(c, 4, 0, s_max - f->s0, u);
        // Magnitude of the terms of the quartic near the torus: bounds the rounding of c0, so
        // roots this close to the start are not trusted to be in front of the origin.
        double scale = (dot(o, o) + R2 + r2);
        scale *= scale;
        int m = 0;
        for (int i = 0; i < n; ++i) {
            u[i] = polish(*f, u[i]);
            double s = f->s0 + u[i];
            double t = s / f->len;
            if (!(t > 0) || !(t < tmax)) continue;
            if (f->s0 == 0) {
                double slope = std::fabs(c[1] + u[i] * (2 * c[2] + u[i] * (3 * c[3] + 4 * u[i])));
                if (u[i] * slope <= gamma(12) * scale) continue;
            }
            out[m++] = t;
        }
        return m;
    }

    // Newton steps on the signed distance to the tube, which stays well conditioned where the
    // quartic is not (major radius much larger than minor): full precision for the root.
    double polish(const Frame& f, double u) const {
        for (int it = 0; it < 2; ++it) {
            Vec3 p = f.o + f.dn * u;
            double w = std::sqrt(p.x * p.x + p.z * p.z);
            if (!(w > 0)) break;
            Vec3 v(p.x - p.x * R_ / w, p.y, p.z - p.z * R_ / w);
            double lv = length(v);
            if (!(lv > 0)) break;
            double slope = dot(f.dn, v) / lv;
            // Near-grazing the step is unreliable; the quartic's root is kept.
            if (std::fabs(slope) < 0.05) break;
            double step = (lv - r_) / slope;
            if (!(std::fabs(step) < 1e-3 * rb_)) break;
            u -= step;
        }
        return u;
    }

    void fill(const Frame& f, double t, LocalHit* h) const {
        Vec3 p = f.o + f.dn * (t * f.len - f.s0);
        double w = std::sqrt(p.x * p.x + p.z * p.z);
        Vec3 center = w > 0 ? Vec3(p.x * R_ / w, 0, p.z * R_ / w) : Vec3(R_, 0, 0);
        Vec3 v = p - center;
        double lv = length(v);
        if (lv > 0) {
            v = v * (r_ / lv);
            p = center + v;
        }
        h->t = t;
        h->p = p;
        h->p_error = rounding_error(p, 6) + Vec3(gamma(6) * rb_);
        h->ng = lv > 0 ? v / r_ : Vec3(0, 1, 0);
        h->n = h->ng;
        h->uv_source = this;
        h->uv_point = p;
        h->has_uv = true;
    }

    // POV-Ray's torus uv_mapping (torus.cpp, Torus::CalcUV).
    Vec2 uv_at(const Vec3& p) const override {
        double w = std::sqrt(p.x * p.x + p.z * p.z);
        return {1.0 - (std::atan2(p.z, p.x) + kPi) / (2 * kPi),
                (std::atan2(p.y, w - R_) + kPi) / (2 * kPi)};
    }

    double R_, r_, rb_;
};

}  // namespace

std::unique_ptr<Primitive> make_torus(const scene::Torus& s) {
    return std::make_unique<TorusPrim>(s.major, s.minor);
}

}  // namespace glint::render
