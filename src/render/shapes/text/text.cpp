// text (POV-Ray 3.7 manual 2.4.2.7; truetype.cpp): each character a solid between z = 0 and
// z = thickness whose cross-section is the glyph outline (quadratic TrueType contours, even-odd
// filled). A ray meets the caps where the crossing point lies inside the outline and the side
// walls where its projection onto the xy-plane meets a contour segment (a line or a
// quadratic: a ruled surface swept along z). Tolerances and tests follow POV-Ray's
// GlyphIntersect and Inside_Glyph so that the same rays hit.
#include "render/shapes/text/text.h"

#include <cmath>

#include "core/error.h"
#include "render/shapes/text/font.h"

namespace glint::render {
namespace {

constexpr double kTtfTolerance = 1.0e-6;  // truetype.cpp TTF_Tolerance
constexpr double kCoeffLimit = 1.0e-20;   // truetype.cpp COEFF_LIMIT

// solve_quad: roots of x0 s^2 - x1 s + x2... in POV-Ray's sign convention (c[0] s^2 + c[1] s +
// c[2] = 0) that lie in [lo, hi]; the larger-root branch first.
int solve_quad(const double c[3], double roots[2], double lo, double hi) {
    double a = c[0], b = -c[1], cc = c[2];
    if (std::fabs(a) < kCoeffLimit) {
        if (std::fabs(b) < kCoeffLimit) return 0;
        double q = cc / b;
        if (q >= lo && q <= hi) {
            roots[0] = q;
            return 1;
        }
        return 0;
    }
    double d = b * b - 4.0 * a * cc;
    if (d < kPovEpsilon) return 0;
    d = std::sqrt(d);
    double t = 2.0 * a;
    double q = (b + d) / t;
    if (q >= lo && q <= hi) {
        roots[0] = q;
        q = (b - d) / t;
        if (q >= lo && q <= hi) {
            roots[1] = q;
            return 2;
        }
        return 1;
    }
    q = (b - d) / t;
    if (q >= lo && q <= hi) {
        roots[0] = q;
        return 1;
    }
    return 0;
}

// Walks a contour's segments as POV-Ray does: an on-curve point ends a line from the current
// point; an off-curve point is the control of a quadratic ending at the next on-curve point or
// at the midpoint to the next off-curve one.
template <typename Line, typename Quad>
void for_each_segment(const GlyphContour& c, Line line, Quad quad) {
    const size_t n = c.p.size() - 1;  // the last point repeats the first
    Vec2 p0 = c.p[0];
    for (size_t j = 1; j <= n; ++j) {
        Vec2 p1 = c.p[j];
        if (c.on_curve[j]) {
            line(p0, p1);
            p0 = p1;
        } else {
            Vec2 p2;
            if (j == n) {
                p2 = c.p[0];
            } else {
                p2 = c.p[j + 1];
                if (!c.on_curve[j + 1]) p2 = (p1 + p2) * 0.5;
            }
            quad(p0, p1, p2);
            p0 = p2;
        }
    }
}

// Inside_Glyph: even-odd crossings of the ray from (x, y) towards +x.
bool inside_glyph(double x, double y, const Glyph& g) {
    if (x < g.lo.x || x > g.hi.x || y < g.lo.y || y > g.hi.y) return false;
    int crossings = 0;
    for (const GlyphContour& c : g.contours) {
        for_each_segment(
            c,
            [&](Vec2 a, Vec2 b) {
                if (a.y == b.y) return;
                bool qi = a.y < y, qj = b.y < y;
                if (qi == qj) return;
                bool ri = a.x > x, rj = b.x > x;
                if (ri && rj) {
                    ++crossings;
                    return;
                }
                if (!ri && !rj) return;
                double m = (b.y - a.y) / (b.x - a.x);
                double bb = (b.y - y) - m * (b.x - x);
                if (bb / m < kPovEpsilon) ++crossings;
            },
            [&](Vec2 a, Vec2 b, Vec2 e) {
                if ((a.y < y && b.y < y && e.y < y) || (a.y > y && b.y > y && e.y > y)) return;
                double yt[3] = {a.y - 2.0 * b.y + e.y, 2.0 * (b.y - a.y), a.y - y};
                double roots[2];
                int k = solve_quad(yt, roots, 0.0, 1.0);
                // Discard end-point roots where y is not really within the segment's range.
                for (int ri = 0; ri < k;) {
                    bool drop = false;
                    if (roots[ri] <= kPovEpsilon)
                        drop = (y <= a.y && y < b.y) || (y >= a.y && y > b.y);
                    else if (roots[ri] >= 1.0 - kPovEpsilon)
                        drop = (y < e.y && y < b.y) || (y > e.y && y > b.y);
                    if (drop) {
                        --k;
                        if (k > ri) roots[ri] = roots[ri + 1];
                        continue;
                    }
                    ++ri;
                }
                double xt[3] = {a.x - 2.0 * b.x + e.x, 2.0 * (b.x - a.x), a.x};
                for (int r = 0; r < k; ++r) {
                    double t = roots[r];
                    if ((xt[0] * t + xt[1]) * t + xt[2] > x) ++crossings;
                }
            });
    }
    return (crossings & 1) != 0;
}

class TextPrim final : public Primitive {
public:
    TextPrim(TextGlyphs glyphs, double depth) : glyphs_(std::move(glyphs.glyphs)), depth_(depth) {
        for (const Glyph& g : glyphs_) {
            if (g.contours.empty()) continue;
            Vec3 lo(g.lo.x + g.offset.x, g.lo.y + g.offset.y, std::min(0.0, depth_));
            Vec3 hi(g.hi.x + g.offset.x, g.hi.y + g.offset.y, std::max(0.0, depth_));
            Bounds3 b{lo - Vec3(kTtfTolerance), hi + Vec3(kTtfTolerance)};
            boxes_.push_back(b);
            bounds_.extend(b);
        }
    }

    Bounds3 bounds() const override { return bounds_; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        return nearest_of_all(ray, tmax, hit);
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        size_t box = 0;
        for (const Glyph& g : glyphs_) {
            if (g.contours.empty()) continue;
            if (crosses(boxes_[box++], ray, tmax)) glyph_hits(g, ray, tmax, hits);
        }
    }

    bool inside(const Vec3& p) const override {
        if (!(p.z >= 0.0 && p.z <= depth_)) return false;
        for (const Glyph& g : glyphs_)
            if (!g.contours.empty() && inside_glyph(p.x - g.offset.x, p.y - g.offset.y, g))
                return true;
        return false;
    }

private:
    static bool crosses(const Bounds3& b, const Ray& ray, double tmax) {
        double t0 = 0, t1 = tmax;
        for (int i = 0; i < 3; ++i) {
            double o = ray.origin[i], d = ray.dir[i];
            if (d == 0) {
                if (o < b.lo[i] || o > b.hi[i]) return false;
                continue;
            }
            double ta = (b.lo[i] - o) / d, tb = (b.hi[i] - o) / d;
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb * (1 + gamma(4)));
            if (t0 > t1) return false;
        }
        return true;
    }

    void add(const Ray& ray, double t, double tmax, const Vec3& n, HitList* hits) const {
        if (!(t > kTtfTolerance) || !(t < tmax)) return;
        LocalHit& h = hits->emplace_back();
        h.t = t;
        h.p = ray.origin + ray.dir * t;
        h.p_error = rounding_error(h.p, 16) + Vec3(1e-12);
        h.ng = normalize(n);
        h.n = h.ng;
        h.has_uv = false;
    }

    // GlyphIntersect, in the glyph's space (the ray moved by -offset).
    void glyph_hits(const Glyph& g, const Ray& ray, double tmax, HitList* hits) const {
        const Vec3 P(ray.origin.x - g.offset.x, ray.origin.y - g.offset.y, ray.origin.z);
        const Vec3& D = ray.dir;
        // Caps at z = 0 and z = depth.
        if (std::fabs(D.z) >= kPovEpsilon) {
            double t = -P.z / D.z;
            if (inside_glyph(P.x + t * D.x, P.y + t * D.y, g))
                add(ray, t, tmax, Vec3(0, 0, -1), hits);
            t += depth_ / D.z;
            if (inside_glyph(P.x + t * D.x, P.y + t * D.y, g))
                add(ray, t, tmax, Vec3(0, 0, 1), hits);
        }
        bool use_x;
        if (std::fabs(D.x) < kPovEpsilon) {
            if (std::fabs(D.y) < kPovEpsilon) return;  // parallel to the walls
            use_x = false;
        } else {
            use_x = true;
        }
        const double a = D.y, b = -D.x, c = P.y * D.x - P.x * D.y;
        const double w = g.winding;
        auto wall = [&](double t, double nx, double ny) {
            double z = P.z + t * D.z;
            // POV-Ray's normal (dy, -dx) points into a clockwise outline; ours points out.
            if (z >= 0 && z <= depth_) add(ray, t, tmax, Vec3(-w * nx, -w * ny, 0), hits);
        };
        for (const GlyphContour& ct : g.contours) {
            for_each_segment(
                ct,
                [&](Vec2 p0, Vec2 p1) {
                    double d0 = p1.x - p0.x, d1 = p1.y - p0.y;
                    double den = d1 * D.x - d0 * D.y;
                    if (std::fabs(den) < kPovEpsilon) return;
                    double s = (D.x * (P.y - p0.y) - D.y * (P.x - p0.x)) / den;
                    if (s < 0.0 || s > 1.0) return;
                    double t = use_x ? ((p0.x + s * d0) - P.x) / D.x
                                     : ((p0.y + s * d1) - P.y) / D.y;
                    wall(t, d1, -d0);
                },
                [&](Vec2 p0, Vec2 p1, Vec2 p2) {
                    double xt2 = p0.x - 2.0 * p1.x + p2.x, xt1 = 2.0 * (p1.x - p0.x), xt0 = p0.x;
                    double yt2 = p0.y - 2.0 * p1.y + p2.y, yt1 = 2.0 * (p1.y - p0.y), yt0 = p0.y;
                    double C[3] = {a * xt2 + b * yt2, a * xt1 + b * yt1, a * xt0 + b * yt0 + c};
                    double S[2];
                    int k = solve_quad(C, S, 0.0, 1.0);
                    for (int l = 0; l < k; ++l) {
                        double s = S[l];
                        double t = use_x ? ((s * s * xt2 + s * xt1 + xt0) - P.x) / D.x
                                         : ((s * s * yt2 + s * yt1 + yt0) - P.y) / D.y;
                        wall(t, 2.0 * yt2 * s + yt1, -2.0 * xt2 * s - xt1);
                    }
                });
        }
    }

    std::vector<Glyph> glyphs_;
    std::vector<Bounds3> boxes_;  // of the glyphs with contours, in the text's space
    double depth_;
    Bounds3 bounds_;
};

}  // namespace

std::unique_ptr<Primitive> make_text(const scene::Text& s, const FileLoc& loc, const char** why) {
    if (!std::isfinite(s.thickness) || !is_finite(s.offset)) {
        *why = "text with a non-finite thickness or offset";
        return nullptr;
    }
    TextGlyphs glyphs;
    try {
        glyphs = layout_text(s.font, s.text, s.offset);
    } catch (const Error& e) {
        throw Error(e.kind(), loc, e.what());
    }
    auto prim = std::make_unique<TextPrim>(std::move(glyphs), s.thickness);
    if (prim->bounds().empty()) {
        *why = "text without visible characters";
        return nullptr;
    }
    return prim;
}

}  // namespace glint::render
