// quadric (POV-Ray 3.7 manual 2.4.3.5; quadrics.cpp): Q(p) = p^T A p + b.p + J with A holding
// the square terms on its diagonal and half the mixed terms off it. Inside where Q <= 0.
// Roots by the stable quadratic (the far root from Vieta's formula); hits whose distance is
// within the rounding of Q at the ray origin are not trusted to be in front of it. Bounds are
// finite for ellipsoids (A positive definite), infinite otherwise, as POV-Ray's quadrics are
// unbounded unless clipped.
#include <algorithm>
#include <cmath>

#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

class QuadricPrim final : public Primitive {
public:
    explicit QuadricPrim(const scene::Quadric& q)
        : a_(q.square.x), e_(q.square.y), h_(q.square.z), b_(q.mixed.x), c_(q.mixed.y),
          f_(q.mixed.z), d_(q.linear.x), g_(q.linear.y), i_(q.linear.z), j_(q.constant) {
        bounds_ = Bounds3{Vec3(-kInfinity), Vec3(kInfinity)};
        ellipsoid_bounds();
    }

    bool empty() const { return empty_; }
    Bounds3 bounds() const override { return bounds_; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        double t[2];
        int n = roots(ray, t);
        for (int k = 0; k < n; ++k)
            if (t[k] < tmax) {
                fill(ray, t[k], hit);
                return true;
            }
        return false;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        double t[2];
        int n = roots(ray, t);
        for (int k = 0; k < n; ++k)
            if (t[k] < tmax) fill(ray, t[k], &hits->emplace_back());
    }

    bool inside(const Vec3& p) const override { return value(p) <= 0; }

    // Without mixed terms Q is a sum of one-axis terms q_k(x) = A_k x^2 + L_k x plus J, so
    // the inside within `box` reaches along axis k only where q_k(x) <= -(J + the least the
    // other terms can be in the box). POV-Ray bounds its quadrics between planes likewise.
    Bounds3 bounds_within(const Bounds3& box) const override {
        Bounds3 r{max(bounds_.lo, box.lo), min(bounds_.hi, box.hi)};
        if (b_ != 0 || c_ != 0 || f_ != 0 || empty_) return r;
        const double sq[3] = {a_, e_, h_}, ln[3] = {d_, g_, i_};
        // The least of q_k over [lo, hi] (-infinity where it is unbounded below).
        auto least = [&](int k) {
            const double A = sq[k], L = ln[k], lo = r.lo[k], hi = r.hi[k];
            auto q = [&](double x) {
                return std::isinf(x) ? (A > 0   ? kInfinity
                                        : A < 0 ? -kInfinity
                                                : L * x)
                                     : x * (A * x + L);
            };
            if (A > 0) {
                const double v = std::clamp(-L / (2 * A), lo, hi);
                return v * (A * v + L);
            }
            if (A == 0 && L == 0) return 0.0;
            return std::min(q(lo), q(hi));
        };
        for (int pass = 0; pass < 2 && !r.empty(); ++pass) {
            for (int k = 0; k < 3; ++k) {
                double rest = j_;
                for (int j = 0; j < 3; ++j)
                    if (j != k) rest += least(j);
                if (!(rest > -kInfinity) || std::isnan(rest)) continue;
                const double A = sq[k], L = ln[k];
                double lo = -kInfinity, hi = kInfinity;
                if (A > 0) {
                    const double disc = L * L - 4 * A * rest;
                    if (disc < 0) return Bounds3{};  // nothing inside within the box
                    const double sd = std::sqrt(disc);
                    lo = (-L - sd) / (2 * A);
                    hi = (-L + sd) / (2 * A);
                } else if (A == 0 && L > 0) {
                    hi = -rest / L;
                } else if (A == 0 && L < 0) {
                    lo = -rest / L;
                } else {
                    continue;
                }
                // Widened well past the rounding of the roots.
                if (std::isfinite(lo)) lo -= 1e-7 * (1 + std::fabs(lo));
                if (std::isfinite(hi)) hi += 1e-7 * (1 + std::fabs(hi));
                r.lo[k] = std::max(r.lo[k], lo);
                r.hi[k] = std::min(r.hi[k], hi);
                if (r.empty()) return r;
            }
        }
        return r;
    }

  private:
    double value(const Vec3& p) const {
        return p.x * (a_ * p.x + b_ * p.y + c_ * p.z + d_) + p.y * (e_ * p.y + f_ * p.z + g_) +
               p.z * (h_ * p.z + i_) + j_;
    }
    // Sum of the magnitudes of Q's terms: bounds the rounding of value().
    double magnitude(const Vec3& p) const {
        Vec3 q = abs(p);
        return q.x * (std::fabs(a_) * q.x + std::fabs(b_) * q.y + std::fabs(c_) * q.z +
                      std::fabs(d_)) +
               q.y * (std::fabs(e_) * q.y + std::fabs(f_) * q.z + std::fabs(g_)) +
               q.z * (std::fabs(h_) * q.z + std::fabs(i_)) + std::fabs(j_);
    }
    Vec3 gradient(const Vec3& p) const {
        return {2 * a_ * p.x + b_ * p.y + c_ * p.z + d_, b_ * p.x + 2 * e_ * p.y + f_ * p.z + g_,
                c_ * p.x + f_ * p.y + 2 * h_ * p.z + i_};
    }

    // Roots with t > 0 ascending: a t^2 + 2 bh t + c = 0.
    int roots(const Ray& ray, double out[2]) const {
        const Vec3 &o = ray.origin, &d = ray.dir;
        double a = d.x * (a_ * d.x + b_ * d.y + c_ * d.z) + d.y * (e_ * d.y + f_ * d.z) +
                   d.z * h_ * d.z;
        double bh = d.x * (a_ * o.x + 0.5 * (b_ * o.y + c_ * o.z + d_)) +
                    d.y * (e_ * o.y + 0.5 * (b_ * o.x + f_ * o.z + g_)) +
                    d.z * (h_ * o.z + 0.5 * (c_ * o.x + f_ * o.y + i_));
        double c = value(o);
        double c_err = gamma(8) * magnitude(o);
        double t[2];
        int n = 0;
        Vec3 ad = abs(d);
        double amag = ad.x * (std::fabs(a_) * ad.x + std::fabs(b_) * ad.y + std::fabs(c_) * ad.z) +
                      ad.y * (std::fabs(e_) * ad.y + std::fabs(f_) * ad.z) +
                      ad.z * std::fabs(h_) * ad.z;
        if (std::fabs(a) > gamma(8) * amag) {
            double disc = bh * bh - a * c;
            if (!(disc > 0)) return 0;
            double q = -(bh + std::copysign(std::sqrt(disc), bh));
            if (q == 0) return 0;
            t[n++] = q / a;
            t[n++] = c / q;
        } else {
            if (bh == 0) return 0;
            t[n++] = -0.5 * c / bh;
        }
        if (n == 2 && t[0] > t[1]) std::swap(t[0], t[1]);
        int m = 0;
        for (int k = 0; k < n; ++k) {
            if (!(t[k] > 0) || !std::isfinite(t[k])) continue;
            // The root's uncertainty from the rounding of c: c_err / |dQ/dt|.
            double slope = std::fabs(2 * (a * t[k] + bh));
            if (t[k] * slope <= c_err) continue;
            out[m++] = t[k];
        }
        return m;
    }

    void fill(const Ray& ray, double t, LocalHit* h) const {
        Vec3 p = ray.origin + ray.dir * t;
        // Newton steps onto the surface: the point computed from t carries t's rounding times
        // the ray length, far more than the surface's own uncertainty.
        for (int it = 0; it < 2; ++it) {
            Vec3 g = gradient(p);
            double g2 = length_squared(g);
            if (!(g2 > 0)) break;
            Vec3 step = g * (value(p) / g2);
            if (!is_finite(step)) break;
            p -= step;
        }
        Vec3 g = gradient(p);
        double gl = length(g);
        h->t = t;
        h->p = p;
        double e = gl > 0 ? gamma(10) * magnitude(p) / gl : 0;
        h->p_error = rounding_error(p, 4) + Vec3(e);
        h->ng = gl > 0 ? g / gl : Vec3(1, 0, 0);
        h->n = h->ng;
    }

    // An ellipsoid (A positive definite) is bounded: centre m = -A^-1 b / 2, and
    // Q(p) = (p - m)^T A (p - m) - k with k = m^T A m - J; half-widths sqrt(k (A^-1)_ii).
    void ellipsoid_bounds() {
        double m00 = a_, m11 = e_, m22 = h_, m01 = 0.5 * b_, m02 = 0.5 * c_, m12 = 0.5 * f_;
        double det2 = m00 * m11 - m01 * m01;
        double det = m00 * (m11 * m22 - m12 * m12) - m01 * (m01 * m22 - m12 * m02) +
                     m02 * (m01 * m12 - m11 * m02);
        if (!(m00 > 0 && det2 > 0 && det > 0)) return;
        // Inverse by cofactors (symmetric).
        double i00 = (m11 * m22 - m12 * m12) / det, i11 = (m00 * m22 - m02 * m02) / det,
               i22 = det2 / det, i01 = (m02 * m12 - m01 * m22) / det,
               i02 = (m01 * m12 - m02 * m11) / det, i12 = (m01 * m02 - m00 * m12) / det;
        Vec3 bv(d_, g_, i_);
        Vec3 m(-0.5 * (i00 * bv.x + i01 * bv.y + i02 * bv.z),
               -0.5 * (i01 * bv.x + i11 * bv.y + i12 * bv.z),
               -0.5 * (i02 * bv.x + i12 * bv.y + i22 * bv.z));
        double k = -value(m);
        if (!(k > 0)) {
            empty_ = true;
            return;
        }
        Vec3 half(std::sqrt(k * i00), std::sqrt(k * i11), std::sqrt(k * i22));
        half = half * (1 + 1e-6) + Vec3(1e-9 * (length(m) + length(half)));
        if (!is_finite(half) || !is_finite(m)) return;
        bounds_ = Bounds3{m - half, m + half};
    }

    double a_, e_, h_, b_, c_, f_, d_, g_, i_, j_;
    Bounds3 bounds_;
    bool empty_ = false;
};

}  // namespace

std::unique_ptr<Primitive> make_quadric(const scene::Quadric& s, const char** why) {
    auto q = std::make_unique<QuadricPrim>(s);
    if (q->empty()) {
        *why = "quadric with no real points (an imaginary ellipsoid)";
        return nullptr;
    }
    return q;
}

}  // namespace glint::render
