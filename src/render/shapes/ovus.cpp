// ovus (POV-Ray 3.7 reference 3.4.5.1.11; ovus.cpp): an egg around the y axis. A bottom sphere of
// radius b at the origin and a top sphere of radius t centred at <0, b, 0> are joined by a band
// of a spindle torus whose meridian circle (radius twice the larger sphere's) is tangent to
// both; each piece holds only between the heights where it meets the next. The band's circle
// centre and the tangency heights are POV-Ray's (Parse_Ovus), the band is the quartic of a
// torus of major radius HP and minor radius CR, of whose two branches only the "lemon" one,
// (h + HP)^2 + (y - VP)^2 = CR^2, belongs to the egg (h = sqrt(x^2 + z^2)).
// Roots are found in a well-scaled frame (unit direction, origin moved to the bounding sphere)
// and hit points reprojected onto their piece; the pieces, normals, inside test and uv are
// POV-Ray's. A top radius of at least twice the bottom one is a sphere, which the importer
// substitutes as POV-Ray's parser does.
#include <algorithm>
#include <cmath>

#include "render/shapes/polynomial/poly_solve.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

constexpr double kEpsilon = 1e-10;       // POV-Ray's EPSILON
constexpr double kRootTolerance = 1e-4;  // ovus.cpp ROOT_TOLERANCE: the lemon-branch test

enum class Piece { Bottom, Top, Band };

struct Candidate {
    double t;
    Piece piece;
};

class OvusPrim final : public Primitive {
public:
    explicit OvusPrim(const scene::Ovus& s) : b_(s.bottom_radius), t_(s.top_radius) {
        // Parse_Ovus's derived values; the caller guarantees 0 <= t < 2 b.
        if (b_ > t_) {
            cr_ = 2.0 * b_;
            vp_ = 2.0 * t_ - b_ - t_ * t_ / (2.0 * b_);
            hp_ = std::sqrt(std::max(0.0, b_ * b_ - vp_ * vp_));
            bv_ = -vp_;
            tv_ = (b_ - vp_) * t_ / (cr_ - t_) + b_;
        } else {
            cr_ = 2.0 * t_;
            vp_ = -2.0 * t_ + b_ + 1.5 * t_ * t_ / b_;
            hp_ = std::sqrt(std::max(0.0, t_ * t_ - (vp_ - b_) * (vp_ - b_)));
            tv_ = 2.0 * b_ - vp_;
            bv_ = -vp_ * b_ / (cr_ - b_);
        }
        biggest_ = std::max({cr_ - hp_, b_, t_});
        rb_ = std::hypot(biggest_, b_ + t_);
    }

    // Ovus::Compute_BBox: the vertical cylinder of the widest piece, from -b to b + t.
    Bounds3 bounds() const override {
        const double e = (biggest_ + b_ + t_) * gamma(4);
        return {Vec3(-biggest_ - e, -b_ - e, -biggest_ - e),
                Vec3(biggest_ + e, b_ + t_ + e, biggest_ + e)};
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        return nearest_of_all(ray, tmax, hit);
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        const double len = length(ray.dir);
        if (!(len > 0) || !std::isfinite(len)) return;
        const Vec3 d = ray.dir / len;
        Candidate found[6];
        int n = 0;
        sphere_hits(ray.origin, d, Vec3(0, 0, 0), b_, Piece::Bottom, found, &n);
        sphere_hits(ray.origin, d, Vec3(0, b_, 0), t_, Piece::Top, found, &n);
        band_hits(ray.origin, d, found, &n);
        for (int i = 0; i < n; ++i) {
            const double t = found[i].t / len;
            if (t > 0 && t < tmax) fill(ray.origin, d, found[i], len, &hits->emplace_back());
        }
    }

    // Ovus::Inside: in either sphere, or within the band's heights and its circle.
    bool inside(const Vec3& p) const override {
        if (length_squared(p) < b_ * b_) return true;
        if (length_squared(p - Vec3(0, b_, 0)) < t_ * t_) return true;
        if (p.y > bv_ && p.y < tv_) {
            const double h = std::sqrt(p.x * p.x + p.z * p.z);
            const double dy = p.y - vp_;
            if ((h + hp_) * (h + hp_) + dy * dy < cr_ * cr_) return true;
        }
        return false;
    }

    // Ovus::CalcUV: the sphere mapping about <0, t/2, 0>.
    Vec2 uv_at(const Vec3& p) const override {
        Vec3 q(p.x, p.y - t_ / 2.0, p.z);
        const double len = length(q);
        if (len == 0) return {0, 0};
        q = q / len;
        return {turn_about_y(q.x, q.z), 0.5 + std::asin(std::clamp(q.y, -1.0, 1.0)) / kPi};
    }

private:
    // The sphere's crossings (distances along the unit d) on its own piece of the egg: the
    // careful quadratic of sphere.cpp, with POV-Ray's rejection of grazing rays (a half chord
    // squared of at most EPSILON) and of spheres behind an outside origin. A crossing whose
    // error interval reaches 0 is the surface a secondary ray leaves from: dropped.
    void sphere_hits(const Vec3& o, const Vec3& d, const Vec3& c, double r, Piece piece,
                     Candidate* out, int* n) const {
        if (!(r > 0)) return;
        const Vec3 f = o - c;
        const double bh = dot(f, d), fl = length(f);
        if (!(fl < r) && -bh < kEpsilon) return;
        const Vec3 l = f - d * bh;
        const double ll = length(l);
        const double disc = (r - ll) * (r + ll);
        if (!(disc > kEpsilon)) return;
        const double sd = std::sqrt(disc);
        const double q = -(bh + std::copysign(sd, bh));
        if (q == 0) return;
        const double cc = (fl - r) * (fl + r);
        const double s_far = q, s_near = cc / q;
        const double e_far = gamma(8) * (fl + sd);
        const double e_near = (gamma(3) * fl * (fl + r) + gamma(1) * std::fabs(cc)) /
                                  std::fabs(q) + gamma(3) * std::fabs(s_near);
        const double s[2] = {s_near, s_far}, e[2] = {e_near, e_far};
        for (int i = 0; i < 2; ++i) {
            if (!(s[i] > e[i])) continue;
            const double y = o.y + d.y * s[i];
            if (piece == Piece::Bottom ? y < bv_ : y > tv_) out[(*n)++] = {s[i], piece};
        }
    }

    // Signed distance to the lemon branch's meridian circle and its gradient (the normal).
    double band_distance(const Vec3& p, Vec3* grad) const {
        const double h = std::sqrt(p.x * p.x + p.z * p.z);
        const Vec3 c = h > 0 ? Vec3(-hp_ * p.x / h, vp_, -hp_ * p.z / h) : Vec3(-hp_, vp_, 0);
        const Vec3 v = p - c;
        const double lv = length(v);
        *grad = lv > 0 ? v / lv : Vec3(0, 1, 0);
        return lv - cr_;
    }

    // The band: the spindle torus's quartic, roots kept where POV-Ray keeps them (between the
    // tangency heights, on the lemon branch to within ROOT_TOLERANCE), then polished onto the
    // lemon circle.
    void band_hits(const Vec3& o, const Vec3& d, Candidate* out, int* n) const {
        if (!(tv_ > bv_)) return;
        // The bounding sphere |p| <= rb, by the stable form; the quartic is set up where the
        // ray enters it so its coefficients stay O(rb^k).
        const double b = dot(o, d);
        const double ll = length(o - d * b);
        const double rb = rb_ * (1 + gamma(4));
        const double disc = (rb - ll) * (rb + ll);
        if (!(disc >= 0)) return;
        const double half = std::sqrt(disc) + 0.01 * rb_;
        const double s_in = -b - half, s_out = -b + half;
        if (s_out <= 0) return;
        const double s0 = std::max(s_in, 0.0);
        const Vec3 q = o + d * s0 - Vec3(0, vp_, 0);
        const double R2 = hp_ * hp_, r2 = cr_ * cr_;
        const double g1 = 2 * dot(q, d), g0 = dot(q, q) + (R2 - r2);
        const double a2 = d.x * d.x + d.z * d.z, a1 = 2 * (q.x * d.x + q.z * d.z),
                     a0 = q.x * q.x + q.z * q.z;
        const double k = 4 * R2;
        const double c[5] = {g0 * g0 - k * a0, 2 * g1 * g0 - k * a1, g1 * g1 + 2 * g0 - k * a2,
                             2 * g1, 1};
        double u[4];
        const int m = real_roots(c, 4, 0, s_out - s0, u);
        double scale = dot(q, q) + R2 + r2;
        scale *= scale;
        const Vec3 o0 = o + d * s0;
        for (int i = 0; i < m; ++i) {
            Vec3 p = o0 + d * u[i];
            if (!(p.y > bv_ && p.y < tv_)) continue;
            const double h = std::sqrt(p.x * p.x + p.z * p.z);
            const double oc2 = (h + hp_) * (h + hp_) + (p.y - vp_) * (p.y - vp_);
            if (!(std::fabs(oc2 - r2) < kRootTolerance)) continue;
            double ui = u[i];
            for (int it = 0; it < 2; ++it) {
                Vec3 g;
                const double dist = band_distance(o0 + d * ui, &g);
                const double slope = dot(d, g);
                if (std::fabs(slope) < 0.05) break;  // grazing: keep the quartic's root
                const double step = dist / slope;
                if (!(std::fabs(step) < 1e-3 * rb_)) break;
                ui -= step;
            }
            if (s0 == 0) {
                const double slope =
                    std::fabs(c[1] + ui * (2 * c[2] + ui * (3 * c[3] + 4 * ui)));
                if (ui * slope <= gamma(12) * scale) continue;
            }
            const double s = s0 + ui;
            if (s > 0) out[(*n)++] = {s, Piece::Band};
        }
    }

    void fill(const Vec3& o, const Vec3& d, const Candidate& c, double len, LocalHit* h) const {
        Vec3 p = o + d * c.t;
        Vec3 nrm;
        if (c.piece == Piece::Band) {
            const double dist = band_distance(p, &nrm);
            p = p - nrm * dist;
            h->p_error = rounding_error(p, 8) + Vec3(gamma(8) * rb_);
        } else {
            const Vec3 center = c.piece == Piece::Bottom ? Vec3(0, 0, 0) : Vec3(0, b_, 0);
            const double r = c.piece == Piece::Bottom ? b_ : t_;
            Vec3 v = p - center;
            const double lv = length(v);
            nrm = lv > 0 ? v / lv : Vec3(0, 1, 0);
            p = center + nrm * r;
            h->p_error = rounding_error(p, 6) + Vec3(gamma(6) * r);
        }
        h->t = c.t / len;
        h->p = p;
        h->ng = nrm;
        h->n = nrm;
        h->uv_source = this;
        h->uv_point = p;
        h->has_uv = true;
    }

    double b_, t_;
    double cr_ = 0, vp_ = 0, hp_ = 0, bv_ = 0, tv_ = 0;  // POV-Ray's ConnectingRadius, ...
    double biggest_ = 0, rb_ = 0;
};

}  // namespace

std::unique_ptr<Primitive> make_ovus(const scene::Ovus& s, const char** why) {
    if (!(s.bottom_radius > 0) || !(s.top_radius >= 0) || !(s.top_radius < 2 * s.bottom_radius) ||
        !std::isfinite(s.bottom_radius)) {
        *why = "ovus radii out of range (bottom > 0, 0 <= top < 2 bottom)";
        return nullptr;
    }
    return std::make_unique<OvusPrim>(s);
}

}  // namespace glint::render
