// sor, surface of revolution (POV-Ray 3.7 manual 2.4.1.9; sor.cpp): for each segment between
// points i+1 and i+2, radius^2 is the cubic r2(y) = A y^3 + B y^2 + C y + D through both points
// with the slopes given by the neighbouring points (Hermite conditions on x^2). The ray
// P + k D (D unit) meets it where r2(Py + k Dy) = |P_xz + k D_xz|^2, a cubic in k, solved on
// the stretch of the ray inside the segment's height band. Caps close the ends unless `open`.
#include <cmath>
#include <vector>

#include "render/shapes/polynomial/poly_solve.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

struct SorSegment {
    double a, b, c, d;  // r2(y)
    double y1, y2;      // height band
    double rmax;        // largest radius in the band
    double r2(double y) const { return ((a * y + b) * y + c) * y + d; }
    double dr2(double y) const { return (3 * a * y + 2 * b) * y + c; }
};

class SorPrim final : public Primitive {
public:
    SorPrim(std::vector<SorSegment> segs, bool open) : segs_(std::move(segs)), closed_(!open) {
        ymin_ = segs_.front().y1;
        ymax_ = segs_.back().y2;
        rmax_ = 0;
        for (const auto& s : segs_) rmax_ = std::max(rmax_, s.rmax);
        base2_ = std::max(0.0, segs_.front().r2(ymin_));
        cap2_ = std::max(0.0, segs_.back().r2(ymax_));
        scale_ = std::max({rmax_, std::fabs(ymin_), std::fabs(ymax_), 1e-300});
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
        double kmax = tmax * len, kmin = 1e-9 * scale_;
        // Sor::UVCoord: u the turn about y; v runs 0..1 up the curve, segment by segment,
        // from -1 to 0 across the base and from 1 to 2 across the cap (centre outwards).
        auto add = [&](double k, const Vec3& n, int part) {
            if (!(k > kmin) || !(k < kmax)) return;
            LocalHit& h = hits->emplace_back();
            h.t = k / len;
            h.p = P + D * k;
            h.p_error = rounding_error(h.p, 8) + Vec3(1e-9 * scale_);
            h.ng = n;
            h.n = n;
            const double rad = std::sqrt(h.p.x * h.p.x + h.p.z * h.p.z);
            double v;
            if (part == kBase) {
                v = rad / std::sqrt(base2_) - 1;
            } else if (part == kCap) {
                v = 2 - rad / std::sqrt(cap2_);
            } else {
                const SorSegment& s = segs_[static_cast<size_t>(part)];
                v = ((h.p.y - s.y1) / (s.y2 - s.y1) + part) / static_cast<double>(segs_.size());
            }
            h.uv_source = this;
            h.uv_point = Vec3(h.p.x, v, h.p.z);
            h.has_uv = true;
        };
        const double kEps = 1e-10;
        if (closed_ && std::fabs(D.y) > kEps) {
            for (int cap = 0; cap < 2; ++cap) {
                double rr = cap ? cap2_ : base2_;
                if (rr <= 1e-4) continue;  // POV-Ray skips caps this small
                double k = ((cap ? ymax_ : ymin_) - P.y) / D.y;
                double u = P.x + k * D.x, v = P.z + k * D.z;
                if (u * u + v * v <= rr) add(k, Vec3(0, cap ? 1.0 : -1.0, 0), cap ? kCap : kBase);
            }
        }
        // The ray's stretch inside the bounding cylinder bounds the search.
        double ka = 0, kb = kmax;
        if (r > 0) {
            double bh = m_of(P, D);
            double c = P.x * P.x + P.z * P.z - rmax_ * rmax_ * (1 + 1e-6);
            double disc = bh * bh - r * c;
            if (disc < 0) return;
            double sq = std::sqrt(disc);
            ka = std::max(ka, (-bh - sq) / r);
            kb = std::min(kb, (-bh + sq) / r);
        }
        for (size_t j = 0; j < segs_.size(); ++j) {
            const SorSegment& s = segs_[j];
            double k0 = ka, k1 = kb;
            if (std::fabs(D.y) > kEps) {
                double ya = (s.y1 - P.y) / D.y, yb = (s.y2 - P.y) / D.y;
                if (ya > yb) std::swap(ya, yb);
                k0 = std::max(k0, ya);
                k1 = std::min(k1, yb);
            } else if (P.y < s.y1 || P.y > s.y2) {
                continue;
            }
            if (!(k1 > k0) && !(k1 == k0)) continue;
            double pad = 1e-9 * scale_;
            k0 -= pad;
            k1 += pad;
            // In u = k - k0: y = Y0 + u Dy, with Y0 = Py + k0 Dy.
            Vec3 Q = P + D * k0;
            double y0 = Q.y, dy = D.y;
            double c[4];
            c[3] = s.a * dy * dy * dy;
            c[2] = dy * dy * (3 * s.a * y0 + s.b) - r;
            c[1] = dy * (y0 * (3 * s.a * y0 + 2 * s.b) + s.c) - 2 * (Q.x * D.x + Q.z * D.z);
            c[0] = s.r2(y0) - Q.x * Q.x - Q.z * Q.z;
            double u[3];
            int n = solve_in_interval(c, 3, 0, k1 - k0, u);
            for (int i = 0; i < n; ++i) {
                double k = k0 + u[i];
                Vec3 p = P + D * k;
                if (!(p.y >= s.y1 && p.y <= s.y2)) continue;
                Vec3 nrm(p.x, -0.5 * s.dr2(p.y), p.z);
                double nl = length(nrm);
                add(k, nl > 0 ? nrm / nl : Vec3(0, 1, 0), static_cast<int>(j));
            }
        }
    }

    bool inside(const Vec3& p) const override {
        if (!(p.y >= ymin_ && p.y <= ymax_)) return false;
        double r0 = p.x * p.x + p.z * p.z;
        if (r0 > rmax_ * rmax_) return false;
        for (const SorSegment& s : segs_)
            if (p.y >= s.y1 && p.y <= s.y2) return r0 <= s.r2(p.y);
        return false;
    }

    Vec2 uv_at(const Vec3& q) const override { return {turn_about_y(q.x, q.z), q.y}; }

private:
    static constexpr int kBase = -1, kCap = -2;  // parts of the surface besides the segments
    static double m_of(const Vec3& P, const Vec3& D) { return P.x * D.x + P.z * D.z; }

    std::vector<SorSegment> segs_;
    bool closed_;
    double ymin_, ymax_, rmax_, base2_, cap2_, scale_;
};

// Solves the 4x4 system M x = rhs by Gaussian elimination with partial pivoting.
bool solve4(double m[4][4], double rhs[4], double x[4]) {
    for (int col = 0; col < 4; ++col) {
        int piv = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::fabs(m[r][col]) > std::fabs(m[piv][col])) piv = r;
        if (m[piv][col] == 0) return false;
        std::swap(m[piv], m[col]);
        std::swap(rhs[piv], rhs[col]);
        for (int r = col + 1; r < 4; ++r) {
            double f = m[r][col] / m[col][col];
            for (int k = col; k < 4; ++k) m[r][k] -= f * m[col][k];
            rhs[r] -= f * rhs[col];
        }
    }
    for (int r = 3; r >= 0; --r) {
        double v = rhs[r];
        for (int k = r + 1; k < 4; ++k) v -= m[r][k] * x[k];
        x[r] = v / m[r][r];
    }
    return true;
}

}  // namespace

std::unique_ptr<Primitive> make_sor(const scene::Sor& s, const char** why) {
    const auto& P = s.points;
    const int n = static_cast<int>(P.size());
    if (n < 4) {
        *why = "sor with fewer than 4 points";
        return nullptr;
    }
    const double kEps = 1e-10;
    std::vector<SorSegment> segs;
    for (int i = 0; i + 3 < n; ++i) {
        if (std::fabs(P[i + 2].y - P[i].y) < kEps || std::fabs(P[i + 3].y - P[i + 1].y) < kEps) {
            *why = "sor with an incorrect point (equal heights)";
            return nullptr;
        }
        double k0 = P[i + 1].x * P[i + 1].x, k1 = P[i + 2].x * P[i + 2].x;
        double k2 = 2 * P[i + 1].x * (P[i + 2].x - P[i].x) / (P[i + 2].y - P[i].y);
        double k3 = 2 * P[i + 2].x * (P[i + 3].x - P[i + 1].x) / (P[i + 3].y - P[i + 1].y);
        double y1 = P[i + 1].y, y2 = P[i + 2].y;
        double m[4][4] = {{y1 * y1 * y1, y1 * y1, y1, 1},
                          {y2 * y2 * y2, y2 * y2, y2, 1},
                          {3 * y1 * y1, 2 * y1, 1, 0},
                          {3 * y2 * y2, 2 * y2, 1, 0}};
        double rhs[4] = {k0, k1, k2, k3}, x[4];
        if (!solve4(m, rhs, x)) {
            *why = "sor with an incorrect point";
            return nullptr;
        }
        SorSegment seg;
        seg.a = std::fabs(x[0]) < kEps ? 0 : x[0];
        seg.b = std::fabs(x[1]) < kEps ? 0 : x[1];
        seg.c = std::fabs(x[2]) < kEps ? 0 : x[2];
        seg.d = std::fabs(x[3]) < kEps ? 0 : x[3];
        seg.y1 = y1;
        seg.y2 = y2;
        double rm = std::max(std::fabs(P[i + 1].x), std::fabs(P[i + 2].x));
        double cr[3] = {seg.c, 2 * seg.b, 3 * seg.a}, r[2];
        int nr = solve_in_interval(cr, 2, y1, y2, r);
        for (int k = 0; k < nr; ++k) rm = std::max(rm, std::sqrt(std::max(0.0, seg.r2(r[k]))));
        seg.rmax = rm;
        segs.push_back(seg);
    }
    return std::make_unique<SorPrim>(std::move(segs), s.open);
}

}  // namespace glint::render
