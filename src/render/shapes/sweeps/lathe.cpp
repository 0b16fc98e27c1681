// lathe (POV-Ray 3.7 manual 2.4.1.6; lathe.cpp): a spline of <radius, height> points revolved
// around the y axis. For a segment (x(w), y(w)) the ray P + k D (D unit) meets the surface where
// its height is y(w) and its squared distance to the axis is x(w)^2; eliminating k gives
//   r Y^2 + 2 Dy m Y + Dy^2 (Px^2 + Pz^2 - x^2) = 0,  Y = y(w) - Py, r = Dx^2 + Dz^2,
//   m = Dx Px + Dz Pz,
// of degree 2, 4 or 6 in w. Nearly horizontal rays take the other route (y(w) = Py, then the
// circle), and every hit is polished by Newton steps on the two equations in (w, k).
#include <cmath>
#include <vector>

#include "render/shapes/shapes.h"
#include "render/shapes/sweeps/spline2d.h"

namespace glint::render {
namespace {

// Ascending coefficients of a cubic component: d + c w + b w^2 + a w^3.
void cubic(double a, double b, double c, double d, double out[4]) {
    out[0] = d, out[1] = c, out[2] = b, out[3] = a;
}

class LathePrim final : public Primitive {
public:
    explicit LathePrim(std::vector<SplineSegment> segs) : segs_(std::move(segs)) {
        rmax_ = 0;
        ymin_ = segs_[0].lo.y;
        ymax_ = segs_[0].hi.y;
        for (const auto& s : segs_) {
            rmax_ = std::max({rmax_, std::fabs(s.lo.x), std::fabs(s.hi.x)});
            ymin_ = std::min(ymin_, s.lo.y);
            ymax_ = std::max(ymax_, s.hi.y);
        }
        scale_ = std::max({rmax_, std::fabs(ymin_), std::fabs(ymax_), 1e-300});
        double step = 1e-6 * scale_;
        for (const auto& s : segs_) {
            Vec2 m = s.at(0.5), t = s.tangent(0.5);
            double tl = std::hypot(t.x, t.y);
            int sign = 1;
            if (tl > 0) {
                Vec2 probe{m.x + step * t.y / tl, m.y - step * t.x / tl};
                if (contains2d(probe.x, probe.y)) sign = -1;
            }
            outward_.push_back(sign);
        }
    }

    Bounds3 bounds() const override {
        Bounds3 b{Vec3(-rmax_, ymin_, -rmax_), Vec3(rmax_, ymax_, rmax_)};
        Vec3 pad = Vec3(1e-9 * scale_) + rounding_error(abs(b.lo) + abs(b.hi), 4);
        b.lo -= pad;
        b.hi += pad;
        return b;
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        return nearest_of_all(ray, tmax, hit);
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        double len = length(ray.dir);
        if (!(len > 0)) return;
        Vec3 P = ray.origin, D = ray.dir / len;
        if ((D.y >= 0 && P.y > ymax_) || (D.y <= 0 && P.y < ymin_) ||
            (D.x >= 0 && P.x > rmax_) || (D.x <= 0 && P.x < -rmax_))
            return;
        double r = D.x * D.x + D.z * D.z;
        double r0 = std::fabs(P.x * D.z - P.z * D.x);
        if (r > 0) r0 /= std::sqrt(r);
        if (r0 > rmax_ * (1 + 1e-9)) return;
        double m = D.x * P.x + D.z * P.z;
        double rho2 = P.x * P.x + P.z * P.z;
        double kmax = tmax * len, kmin = 1e-9 * scale_;
        const bool horizontal = std::fabs(D.y) < 1e-5;
        for (size_t j = 0; j < segs_.size(); ++j) {
            const SplineSegment& s = segs_[j];
            // The ray's height range against the segment's.
            if ((D.y >= 0 && P.y > s.hi.y) || (D.y <= 0 && P.y < s.lo.y)) continue;
            double X[4], Y[4];
            cubic(s.a.x, s.b.x, s.c.x, s.d.x, X);
            cubic(s.a.y, s.b.y, s.c.y, s.d.y - P.y, Y);
            double w[6];
            int n;
            if (!horizontal) {
                double c[7] = {0, 0, 0, 0, 0, 0, 0};
                for (int i = 0; i < 4; ++i)
                    for (int k = 0; k < 4; ++k) c[i + k] += r * Y[i] * Y[k] - D.y * D.y * X[i] * X[k];
                for (int i = 0; i < 4; ++i) c[i] += 2 * D.y * m * Y[i];
                c[0] += D.y * D.y * rho2;
                n = solve_in_interval(c, 6, 0, 1, w);
                for (int i = 0; i < n; ++i) {
                    double k = eval_polynomial(Y, 3, w[i]) / D.y;
                    emit(j, P, D, len, w[i], k, kmin, kmax, hits);
                }
            } else {
                n = solve_in_interval(Y, 3, 0, 1, w);
                for (int i = 0; i < n; ++i) {
                    double x = eval_polynomial(X, 3, w[i]);
                    // r k^2 + 2 m k + rho2 - x^2 = 0
                    double disc = m * m - r * (rho2 - x * x);
                    if (!(disc >= 0) || !(r > 0)) continue;
                    double q = -(m + std::copysign(std::sqrt(disc), m));
                    if (q != 0) {
                        emit(j, P, D, len, w[i], q / r, kmin, kmax, hits);
                        emit(j, P, D, len, w[i], (rho2 - x * x) / q, kmin, kmax, hits);
                    }
                }
            }
        }
    }

    bool inside(const Vec3& p) const override {
        if (!(p.y >= ymin_ && p.y <= ymax_)) return false;
        return contains2d(std::sqrt(p.x * p.x + p.z * p.z), p.y);
    }

private:
    // POV-Ray's Lathe::Inside in the (radius, height) plane: crossings towards +radius.
    bool contains2d(double rad, double y) const {
        int crossings = 0;
        const double kEps = 1e-10;
        for (const SplineSegment& s : segs_) {
            if (y < s.lo.y - kEps || y > s.hi.y + kEps) continue;
            double c[4] = {s.d.y - y, s.c.y, s.b.y, s.a.y};
            double w[3];
            int n = solve_in_interval(c, 3, 0, 1, w);
            for (int k = 0; k < n; ++k)
                if (s.at(w[k]).x >= rad) ++crossings;
        }
        return crossings & 1;
    }

    // Polishes (w, k) with Newton steps on F1 = y(w) - Py - k Dy, F2 = x(w)^2 - rho(k)^2 and
    // records the hit when it stays valid.
    void emit(size_t j, const Vec3& P, const Vec3& D, double len, double w, double k,
              double kmin, double kmax, HitList* hits) const {
        const SplineSegment& s = segs_[j];
        for (int it = 0; it < 3; ++it) {
            Vec2 q = s.at(w), t = s.tangent(w);
            double px = P.x + k * D.x, pz = P.z + k * D.z;
            double f1 = q.y - P.y - k * D.y;
            double f2 = q.x * q.x - (px * px + pz * pz);
            double a11 = t.y, a12 = -D.y;
            double a21 = 2 * q.x * t.x, a22 = -2 * (px * D.x + pz * D.z);
            double det = a11 * a22 - a12 * a21;
            if (!(std::fabs(det) > 1e-12 * (std::fabs(a11 * a22) + std::fabs(a12 * a21))))
                break;
            double dw = (f1 * a22 - f2 * a12) / det;
            double dk = (a11 * f2 - a21 * f1) / det;
            if (!(std::fabs(dw) < 1e-3) || !(std::fabs(dk) < 1e-3 * scale_)) break;
            w -= dw;
            k -= dk;
        }
        if (!(w >= -1e-9 && w <= 1 + 1e-9)) return;
        if (!(k > kmin) || !(k < kmax)) return;
        LocalHit& h = hits->emplace_back();
        h.t = k / len;
        h.p = P + D * k;
        h.p_error = rounding_error(h.p, 8) + Vec3(1e-9 * scale_);
        double rad = std::sqrt(h.p.x * h.p.x + h.p.z * h.p.z);
        Vec3 n(0, 1, 0);
        if (rad > 1e-10) {
            Vec2 t = s.tangent(std::clamp(w, 0.0, 1.0));
            n = Vec3(t.y * h.p.x / rad, -t.x, t.y * h.p.z / rad);
            double nl = length(n);
            n = nl > 0 ? n * (outward_[j] / nl) : Vec3(0, 1, 0);
        }
        h.ng = n;
        h.n = n;
        // Lathe::UVCoord: u the turn about y, v the spline parameter over all segments.
        h.uv_source = this;
        h.uv_point = Vec3(h.p.x, std::min(1.0, (w + static_cast<double>(j)) /
                                                   static_cast<double>(segs_.size())),
                          h.p.z);
        h.has_uv = true;
    }

    Vec2 uv_at(const Vec3& q) const override { return {turn_about_y(q.x, q.z), q.y}; }

    std::vector<SplineSegment> segs_;
    std::vector<int> outward_;
    double rmax_, ymin_, ymax_, scale_;
};

}  // namespace

std::unique_ptr<Primitive> make_lathe(const scene::Lathe& s, const char** why) {
    using scene::SplineType;
    const auto& P = s.points;
    const int n = static_cast<int>(P.size());
    int count = 0, step = 1;
    switch (s.spline) {
        case SplineType::Linear: count = n - 1; break;
        case SplineType::Quadratic: count = n - 2; break;
        case SplineType::Cubic: count = n - 3; break;
        case SplineType::Bezier: count = n / 4, step = 4; break;
    }
    if (count <= 0) {
        *why = "lathe with too few points";
        return nullptr;
    }
    std::vector<SplineSegment> segs;
    for (int i = 0, k = 0; k < count; ++k, i += step) segs.push_back(make_segment(s.spline, &P[i]));
    return std::make_unique<LathePrim>(std::move(segs));
}

}  // namespace glint::render
