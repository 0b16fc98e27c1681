// prism (POV-Ray 3.7 manual 2.4.1.8; prism.cpp): closed spline outlines in the xz-plane (points
// <x, z>) swept along y from height1 to height2. A linear sweep keeps the outline; a conic sweep
// scales it by y, so the sides are cones with their apex at the origin. Side hits solve the
// spline parameter w in [0, 1] for the plane through the ray (linear: the vertical plane; conic:
// the plane through the origin); caps test the outline's crossing count at the cap point.
// Normals are oriented out of the solid by probing which side of each segment is inside.
#include <cmath>
#include <vector>

#include "render/shapes/shapes.h"
#include "render/shapes/sweeps/spline2d.h"

namespace glint::render {
namespace {

class PrismPrim final : public Primitive {
public:
    PrismPrim(std::vector<SplineSegment> segs, bool conic, double h1, double h2, bool open)
        : segs_(std::move(segs)), conic_(conic), h1_(h1), h2_(h2), closed_(!open) {
        lo_ = segs_[0].lo;
        hi_ = segs_[0].hi;
        for (const auto& s : segs_) {
            lo_ = {std::min(lo_.x, s.lo.x), std::min(lo_.y, s.lo.y)};
            hi_ = {std::max(hi_.x, s.hi.x), std::max(hi_.y, s.hi.y)};
        }
        double ext = std::max({std::fabs(lo_.x), std::fabs(lo_.y), std::fabs(hi_.x),
                               std::fabs(hi_.y)});
        scale_ = std::max({ext, std::fabs(h1_), std::fabs(h2_), 1e-300});
        if (conic_) scale_ = std::max(scale_, ext * std::max(std::fabs(h1_), std::fabs(h2_)));
        // Outward side of each segment: probe a little to the right of its middle.
        double step = 1e-6 * std::max(ext, 1e-300);
        for (const auto& s : segs_) {
            Vec2 m = s.at(0.5), t = s.tangent(0.5);
            double tl = std::hypot(t.x, t.y);
            int sign = 1;
            if (tl > 0) {
                Vec2 probe{m.x + step * t.y / tl, m.y - step * t.x / tl};
                if (curve_contains(segs_, probe.x, probe.y)) sign = -1;
            }
            outward_.push_back(sign);
        }
    }

    Bounds3 bounds() const override {
        Bounds3 b;
        if (!conic_) {
            b = {Vec3(lo_.x, h1_, lo_.y), Vec3(hi_.x, h2_, hi_.y)};
        } else {
            for (double h : {h1_, h2_}) {
                b.extend(Vec3(lo_.x * h, h, lo_.y * h));
                b.extend(Vec3(hi_.x * h, h, hi_.y * h));
            }
        }
        Vec3 pad = rounding_error(abs(b.lo) + abs(b.hi), 4) + Vec3(1e-9 * scale_);
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
        double kmax = tmax * len;
        double kmin = 1e-9 * scale_;
        auto add = [&](double k, const Vec3& n) {
            if (!(k > kmin) || !(k < kmax)) return;
            LocalHit& h = hits->emplace_back();
            h.t = k / len;
            h.p = P + D * k;
            h.p_error = rounding_error(h.p, 8) + Vec3(1e-9 * scale_);
            h.ng = n;
            h.n = n;
        };
        const double kEps = 1e-10;
        if (std::fabs(D.y) < kEps) {
            if (P.y < h1_ || P.y > h2_) return;
        } else if (closed_) {
            for (int cap = 0; cap < 2; ++cap) {
                double h = cap ? h2_ : h1_;
                if (conic_ && std::fabs(h) <= kEps) continue;
                double k = (h - P.y) / D.y;
                double u = P.x + k * D.x, v = P.z + k * D.z;
                if (conic_) {
                    u /= h;
                    v /= h;
                }
                if (curve_contains(segs_, u, v))
                    add(k, Vec3(0, cap ? 1.0 : -1.0, 0));
            }
        }
        if (std::fabs(D.x) <= kEps && std::fabs(D.z) <= kEps) return;
        // Conic: the plane through the origin and the ray, normal P x D (up to sign).
        double k1 = P.z * D.y - P.y * D.z, k2 = P.y * D.x - P.x * D.y,
               k3 = P.x * D.z - P.z * D.x;
        for (size_t j = 0; j < segs_.size(); ++j) {
            const SplineSegment& s = segs_[j];
            if (!conic_ && ((D.x >= 0 && P.x > s.hi.x) || (D.x <= 0 && P.x < s.lo.x) ||
                            (D.z >= 0 && P.z > s.hi.y) || (D.z <= 0 && P.z < s.lo.y)))
                continue;
            double c[4];
            if (!conic_) {
                c[3] = s.a.x * D.z - s.a.y * D.x;
                c[2] = s.b.x * D.z - s.b.y * D.x;
                c[1] = s.c.x * D.z - s.c.y * D.x;
                c[0] = D.z * (s.d.x - P.x) - D.x * (s.d.y - P.z);
            } else {
                c[3] = s.a.x * k1 + s.a.y * k2;
                c[2] = s.b.x * k1 + s.b.y * k2;
                c[1] = s.c.x * k1 + s.c.y * k2;
                c[0] = s.d.x * k1 + s.d.y * k2 + k3;
            }
            double w[3];
            int n = solve_in_interval(c, 3, 0, 1, w);
            for (int r = 0; r < n; ++r) {
                Vec2 q = s.at(w[r]);
                double k;
                if (!conic_) {
                    k = std::fabs(D.x) >= std::fabs(D.z) ? (q.x - P.x) / D.x : (q.y - P.z) / D.z;
                } else {
                    double hx = D.x - q.x * D.y, hz = D.z - q.y * D.y;
                    if (std::fabs(hx) >= std::fabs(hz)) {
                        if (!(std::fabs(hx) > kEps)) continue;
                        k = (q.x * P.y - P.x) / hx;
                    } else {
                        if (!(std::fabs(hz) > kEps)) continue;
                        k = (q.y * P.y - P.z) / hz;
                    }
                }
                double y = P.y + k * D.y;
                if (!(y >= h1_ && y <= h2_)) continue;
                Vec2 t = s.tangent(w[r]);
                Vec3 nrm(t.y, 0, -t.x);
                if (conic_) {
                    if (std::fabs(y) <= kEps) {
                        nrm = Vec3(0, 1, 0);
                    } else {
                        Vec3 p = P + D * k;
                        nrm.y = -(p.x * nrm.x + p.z * nrm.z) / p.y;
                    }
                }
                double nl = length(nrm);
                nrm = nl > 0 ? nrm * (outward_[j] / nl) : Vec3(0, 1, 0);
                if (conic_ && y < 0) nrm = -nrm;
                add(k, nrm);
            }
        }
    }

    bool inside(const Vec3& p) const override {
        if (!(p.y >= h1_ && p.y < h2_)) return false;
        double u = p.x, v = p.z;
        if (conic_) {
            if (std::fabs(p.y) <= 1e-10) return false;
            u /= p.y;
            v /= p.y;
        }
        return curve_contains(segs_, u, v);
    }

private:
    std::vector<SplineSegment> segs_;
    std::vector<int> outward_;
    bool conic_;
    double h1_, h2_;
    bool closed_;
    Vec2 lo_, hi_;
    double scale_;
};

}  // namespace

std::unique_ptr<Primitive> make_prism(const scene::Prism& s, const char** why) {
    using scene::SplineType;
    const auto& P = s.points;
    const int n = static_cast<int>(P.size());
    const double kEps = 1e-10;
    auto same = [&](const Vec2& a, const Vec2& b) {
        return std::fabs(a.x - b.x) < kEps && std::fabs(a.y - b.y) < kEps;
    };
    // Closed? (Parse_Prism): every sub-outline must end on its first point.
    bool closed = false;
    if (s.spline == SplineType::Bezier) {
        closed = n >= 4 && n % 4 == 0;
        int loop = 0;
        for (int i = 4; closed && i < n; i += 4) {
            if (!same(P[i], P[i - 1])) {
                if (!same(P[i - 1], P[loop])) closed = false;
                loop = i;
            }
        }
        if (closed && !same(P[n - 1], P[loop])) closed = false;
    } else {
        int i = s.spline == SplineType::Linear ? 1 : 2;
        int skip = s.spline == SplineType::Linear ? 1 : s.spline == SplineType::Quadratic ? 2 : 3;
        if (n > i - 1) {
            Vec2 first = P[i - 1];
            for (; i < n; ++i) {
                closed = false;
                if (same(first, P[i])) {
                    i += skip;
                    if (i < n) first = P[i];
                    closed = true;
                }
            }
        }
    }
    if (!closed) {
        *why = "prism whose outline is not closed (POV-Ray ignores it too)";
        return nullptr;
    }
    // Segments (Compute_Prism): the spline restarts after each closed sub-outline.
    std::vector<SplineSegment> segs;
    int span = segment_points(s.spline);
    Vec2 first = s.spline == SplineType::Linear ? P[0] : P[1];
    for (int i = 0; i < n - 1; ++i) {
        if (i + span - 1 >= n) break;
        segs.push_back(make_segment(s.spline, &P[i]));
        switch (s.spline) {
            case SplineType::Linear:
                if (same(P[i + 1], first)) {
                    ++i;
                    if (i + 1 < n) first = P[i + 1];
                }
                break;
            case SplineType::Quadratic:
                if (same(P[i + 2], first)) {
                    i += 2;
                    if (i + 2 < n) first = P[i + 2];
                }
                break;
            case SplineType::Cubic:
                if (same(P[i + 2], first)) {
                    i += 3;
                    if (i + 2 < n) first = P[i + 2];
                }
                break;
            case SplineType::Bezier:
                i += 3;
                break;
        }
    }
    if (segs.empty()) {
        *why = "prism without segments";
        return nullptr;
    }
    return std::make_unique<PrismPrim>(std::move(segs), s.conic, std::min(s.height1, s.height2),
                                       std::max(s.height1, s.height2), s.open);
}

}  // namespace glint::render
