// sphere_sweep (reference manual 3.4.5.1.13; sphsweep.cpp): a sphere whose centre C(u) and radius
// r(u) follow a polynomial in u in [0, 1] per piece (degree 1 for linear_spline, 3 for b_spline
// and cubic_spline). The ray O + t D (D unit) meets the sphere of parameter u where
//   F(t, u) = t^2 + B(u) t + G(u) = 0,  B = 2 D.(O - C(u)),  G = |O - C(u)|^2 - r(u)^2,
// and touches the swept surface (the envelope) where also dF/du = B'(u) t + G'(u) = 0. Putting
// t = -G'/B' into F gives one polynomial in u, G'^2 - B B' G' + B'^2 G, of degree 2 or 10.
// POV-Ray then takes, for each of its roots, the ray's hits with that sphere (a straight piece
// uses t = -G'/B' directly unless the ray is nearly square to it), adds the hits with the
// spheres between pieces and with the discs that close each piece, and merges them all by
// counting entries and exits along the whole line. This file builds the same hits, in the same
// way, so that POV-Ray's surface and its quirks (the inside test among them) come out alike.
#include <algorithm>
#include <cmath>
#include <vector>

#include "render/shapes/polynomial/poly_solve.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

// POV-Ray's constants as sphsweep.cpp uses them: EPSILON for grazing and parallel tests,
// MAX_DISTANCE for hits worth keeping, and the slope below which a straight piece's hit is
// taken from the sphere rather than from t = -G'/B'.
constexpr double kEpsilon = 1e-10;
constexpr double kMaxDistance = 1e7;
constexpr double kSquareToPiece = 1e-4;

constexpr int kMaxDegree = 10;

// Ascending coefficients; `n` the degree (entries past it are zero).
struct Poly {
    double c[kMaxDegree + 1] = {};
    int n = 0;
};

Poly mul(const Poly& a, const Poly& b) {
    Poly r;
    r.n = a.n + b.n;
    for (int i = 0; i <= a.n; ++i)
        for (int k = 0; k <= b.n; ++k) r.c[i + k] += a.c[i] * b.c[k];
    return r;
}
Poly add(const Poly& a, const Poly& b, double sb) {
    Poly r;
    r.n = std::max(a.n, b.n);
    for (int i = 0; i <= r.n; ++i) r.c[i] = a.c[i] + sb * b.c[i];
    return r;
}
Poly derivative(const Poly& a) {
    Poly r;
    r.n = std::max(a.n - 1, 0);
    for (int i = 1; i <= a.n; ++i) r.c[i - 1] = i * a.c[i];
    return r;
}

// POV-Ray's quick rejection before a root search on [0, 1]: the polynomial written in the
// Bernstein basis of its degree has coefficients that bound it there, so when none of them
// change sign (zeros allowed) it reports no root at all, not even one at 0 or 1.
bool may_have_root(const Poly& p) {
    bool pos = false, neg = false;
    for (int k = 0; k <= p.n; ++k) {
        // b_k = sum_{j <= k} C(k, j) / C(n, j) a_j
        double b = 0, ckj = 1, cnj = 1;
        for (int j = 0; j <= k; ++j) {
            b += ckj / cnj * p.c[j];
            ckj = ckj * (k - j) / (j + 1);
            cnj = cnj * (p.n - j) / (j + 1);
        }
        pos |= b > 0;
        neg |= b < 0;
        if (pos && neg) return true;
    }
    return false;
}

// Real roots in [0, 1], ascending: for a cubic piece only past POV-Ray's rejection test.
int roots01(const Poly& p, bool cubic, double* roots) {
    if (cubic && !may_have_root(p)) return 0;
    int n = p.n;
    while (n > 0 && p.c[n] == 0) --n;
    if (n == 0) return 0;
    return solve_in_interval(p.c, n, 0, 1, roots);
}

struct Ball {
    Vec3 center;
    double radius = 0;
};

struct LineHit {
    double t;
    Vec3 p, n;
};

// The line's two crossings of a ball, as POV-Ray's sweep takes them: none when the origin lies
// outside and the centre is not ahead, or the line only grazes it; the normal is (p - c) / r.
void ball_hits(const Vec3& O, const Vec3& D, const Ball& b, std::vector<LineHit>* out) {
    const double r2 = b.radius * b.radius;
    const Vec3 oc = b.center - O;
    const double oc2 = dot(oc, oc), tca = dot(oc, D);
    if (oc2 >= r2 && tca < kEpsilon) return;
    const double h2 = r2 - oc2 + tca * tca;
    if (!(h2 > kEpsilon)) return;
    const double h = std::sqrt(h2);
    for (double t : {tca - h, tca + h}) {
        Vec3 p = O + D * t;
        out->push_back({t, p, (p - b.center) / b.radius});
    }
}

struct Piece {
    bool cubic = false;
    Vec3 c[4];      // C(u) = sum c[k] u^k
    double r[4] = {0, 0, 0, 0};
    Ball end[2];    // the spheres at u = 0 and u = 1
    Vec3 dc[2];     // C'(0), C'(1)
    double dr[2] = {0, 0};
    Bounds3 box;    // everything the piece's spheres cover

    int degree() const { return cubic ? 3 : 1; }
    Vec3 center(double u) const {
        return c[0] + (c[1] + (c[2] + c[3] * u) * u) * u;
    }
    double radius(double u) const { return r[0] + (r[1] + (r[2] + r[3] * u) * u) * u; }

    // G(u) = |V - sum_{k>=1} c[k] u^k|^2 - r(u)^2 with V = point - c[0], and, when D is given,
    // B(u) = 2 D.(V - sum_{k>=1} c[k] u^k).
    void polys(const Vec3& V, const Vec3* D, Poly* G, Poly* B) const {
        const int m = degree();
        Poly w[3], rr;
        for (int a = 0; a < 3; ++a) {
            w[a].n = m;
            w[a].c[0] = V[a];
            for (int k = 1; k <= m; ++k) w[a].c[k] = -c[k][a];
        }
        rr.n = m;
        for (int k = 0; k <= m; ++k) rr.c[k] = r[k];
        *G = add(add(add(mul(w[0], w[0]), mul(w[1], w[1]), 1), mul(w[2], w[2]), 1),
                 mul(rr, rr), -1);
        if (D) {
            B->n = m;
            for (int k = 0; k <= m; ++k)
                B->c[k] = 2 * (D->x * w[0].c[k] + D->y * w[1].c[k] + D->z * w[2].c[k]);
        }
    }
};

// The range of x(u) - |r(u)| .. x(u) + |r(u)| over u in [0, 1] for one axis of a piece: the
// ends and the turning points of x +- r.
void extend_axis(const Piece& s, int a, double* lo, double* hi) {
    for (int sign : {1, -1}) {
        // f(u) = x(u) + sign r(u), cubic; its turning points solve a quadratic.
        double f[4];
        for (int k = 0; k < 4; ++k) f[k] = s.c[k][a] + sign * s.r[k];
        auto eval = [&](double u) { return f[0] + (f[1] + (f[2] + f[3] * u) * u) * u; };
        std::vector<double> us = {0, 1};
        double q[3] = {f[1], 2 * f[2], 3 * f[3]};
        int qn = q[2] != 0 ? 2 : (q[1] != 0 ? 1 : 0);
        double roots[2];
        if (qn > 0) {
            int nr = solve_in_interval(q, qn, 0, 1, roots);
            us.insert(us.end(), roots, roots + nr);
        }
        for (double u : us) {
            double v = eval(u);
            *lo = std::min(*lo, v);
            *hi = std::max(*hi, v);
        }
    }
}

// Whether the whole line O + t D (any t) passes through the box.
bool line_meets(const Bounds3& b, const Vec3& O, const Vec3& D) {
    double t0 = -kInfinity, t1 = kInfinity;
    for (int a = 0; a < 3; ++a) {
        if (D[a] == 0) {
            if (O[a] < b.lo[a] || O[a] > b.hi[a]) return false;
            continue;
        }
        double ta = (b.lo[a] - O[a]) / D[a], tb = (b.hi[a] - O[a]) / D[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

class SphereSweepPrim final : public Primitive {
public:
    SphereSweepPrim(std::vector<Piece> pieces, std::vector<Ball> joints, Bounds3 box,
                    double tolerance)
        : pieces_(std::move(pieces)), joints_(std::move(joints)), box_(box),
          tolerance_(tolerance) {
        scale_ = std::max({max_component(abs(box_.lo)), max_component(abs(box_.hi)), 1e-300});
    }

    Bounds3 bounds() const override {
        Bounds3 b = box_;
        Vec3 pad = Vec3(1e-9 * scale_) + rounding_error(abs(b.lo) + abs(b.hi), 4);
        b.lo -= pad;
        b.hi += pad;
        return b;
    }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        return nearest_of_all(ray, tmax, hit);
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        const double len = length(ray.dir);
        if (!(len > 0)) return;
        // A unit direction is used as it is, as POV-Ray does when it has no transform to undo.
        const Vec3 O = ray.origin, D = len == 1 ? ray.dir : ray.dir / len;
        std::vector<LineHit> line;
        for (const Ball& b : joints_) ball_hits(O, D, b, &line);
        for (const Piece& s : pieces_)
            if (line_meets(s.box, O, D)) piece_hits(s, O, D, &line);
        if (line.empty()) return;
        // Stable, as the C library's qsort that POV-Ray calls sorts (a merge sort): crossings
        // at the same depth, such as the two discs where consecutive pieces meet, keep the
        // order they were found in, which decides what the merge below keeps.
        std::stable_sort(line.begin(), line.end(),
                         [](const LineHit& a, const LineHit& b) { return a.t < b.t; });
        // POV-Ray's merge: the first and last crossings of the line always stay; between them
        // a crossing into a part stays only when the line was in no part, one out of a part
        // only when it was in just that one. The count starts as if the first crossing had
        // entered.
        const size_t n = line.size();
        const double kmax = tmax * len;
        int depth = 1;
        for (size_t i = 0; i < n; ++i) {
            bool keep = true;
            if (i > 0 && i + 1 < n) {
                if (dot(line[i].n, D) < 0) {
                    keep = depth == 0;
                    ++depth;
                } else {
                    keep = depth == 1;
                    --depth;
                }
            }
            const LineHit& l = line[i];
            if (!keep || !(l.t > tolerance_) || !(l.t < kmax)) continue;
            double nl = length(l.n);
            if (!(nl > 0) || !std::isfinite(nl)) continue;
            LocalHit& h = hits->emplace_back();
            h.t = l.t / len;
            h.p = l.p;
            h.p_error = rounding_error(h.p, 16) + Vec3(1e-9 * scale_);
            h.ng = h.n = l.n / nl;
        }
    }

    // POV-Ray's test: inside when, for some piece, the point lies on the sphere of some u in
    // [0, 1], i.e. |p - C(u)|^2 - r(u)^2 has a root there. (So a point that every sphere of a
    // piece holds is inside only through another piece, as in POV-Ray.)
    bool inside(const Vec3& p) const override {
        for (const Piece& s : pieces_) {
            if (p.x < s.box.lo.x || p.y < s.box.lo.y || p.z < s.box.lo.z || p.x > s.box.hi.x ||
                p.y > s.box.hi.y || p.z > s.box.hi.z)
                continue;
            Poly G, B;
            s.polys(p - s.c[0], nullptr, &G, &B);
            double roots[kMaxDegree];
            if (roots01(G, s.cubic, roots) > 0) return true;
        }
        return false;
    }

private:
    // The line's crossings with one piece: the discs closing it at u = 0 and u = 1 (where the
    // piece's surface leaves its end spheres), then its side.
    static void piece_hits(const Piece& s, const Vec3& O, const Vec3& D,
                           std::vector<LineHit>* out) {
        for (int e = 0; e < 2; ++e) {
            const double dd = dot(D, s.dc[e]);
            if (!(std::fabs(dd) > kEpsilon)) continue;
            const double t = -(dot(O - s.end[e].center, s.dc[e]) + s.end[e].radius * s.dr[e]) / dd;
            if (!(t > -kMaxDistance && t < kMaxDistance)) continue;
            const Vec3 p = O + D * t;
            const Vec3 q = p - s.end[e].center;
            if (!(dot(q, q) < s.end[e].radius * s.end[e].radius)) continue;
            const Vec3 axis = normalize(s.dc[e]);
            out->push_back({t, p, e == 0 ? -axis : axis});
        }
        Poly G, B;
        s.polys(O - s.c[0], &D, &G, &B);
        const Poly dG = derivative(G), dB = derivative(B);
        // G'^2 - B B' G' + B'^2 G: zero where the line touches the sphere of u tangentially.
        const Poly E = add(add(mul(dG, dG), mul(mul(B, dB), dG), -1), mul(mul(dB, dB), G), 1);
        double us[kMaxDegree];
        const int nu = roots01(E, s.cubic, us);
        for (int i = 0; i < nu; ++i) {
            const double u = us[i];
            const Ball b{s.center(u), s.radius(u)};
            if (!s.cubic) {
                const double slope = eval_polynomial(dB.c, dB.n, u);
                if (std::fabs(slope) > kSquareToPiece) {
                    const double t = -eval_polynomial(dG.c, dG.n, u) / slope;
                    if (!(t > -kMaxDistance && t < kMaxDistance)) continue;
                    const Vec3 p = O + D * t;
                    out->push_back({t, p, normalize(p - b.center)});
                    continue;
                }
            }
            ball_hits(O, D, b, out);
        }
    }

    std::vector<Piece> pieces_;
    std::vector<Ball> joints_;  // the spheres where pieces meet, and the two ends
    Bounds3 box_;
    double tolerance_;
    double scale_;
};

// The spline's weights of four consecutive spheres for u^0 .. u^3 (rows), each sphere a
// column: the uniform B-spline, and POV-Ray's Catmull-Rom (through the inner two spheres).
constexpr double kBSpline[4][4] = {{1 / 6.0, 4 / 6.0, 1 / 6.0, 0},
                                   {-3 / 6.0, 0, 3 / 6.0, 0},
                                   {3 / 6.0, -6 / 6.0, 3 / 6.0, 0},
                                   {-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0}};
constexpr double kCatmullRom[4][4] = {{0, 1, 0, 0},
                                      {-0.5, 0, 0.5, 0},
                                      {1, -2.5, 2, -0.5},
                                      {-0.5, 1.5, -1.5, 0.5}};

}  // namespace

std::unique_ptr<Primitive> make_sphere_sweep(const scene::SphereSweep& s, const char** why) {
    using scene::SweepSpline;
    const auto& sp = s.spheres;
    const int n = static_cast<int>(sp.size());
    const bool cubic = s.spline != SweepSpline::Linear;
    if (n < (cubic ? 4 : 2)) {
        *why = "sphere_sweep with too few spheres";
        return nullptr;
    }
    for (const scene::Sphere& b : sp)
        if (!is_finite(b.center) || !std::isfinite(b.radius)) {
            *why = "sphere_sweep with non-finite spheres";
            return nullptr;
        }
    std::vector<Piece> pieces;
    for (int i = 0; i + (cubic ? 3 : 1) < n; ++i) {
        Piece p;
        p.cubic = cubic;
        if (!cubic) {
            p.c[0] = sp[i].center;
            p.c[1] = sp[i + 1].center - sp[i].center;
            p.r[0] = sp[i].radius;
            p.r[1] = sp[i + 1].radius - sp[i].radius;
        } else {
            const auto& m = s.spline == SweepSpline::BSpline ? kBSpline : kCatmullRom;
            for (int k = 0; k < 4; ++k)
                for (int j = 0; j < 4; ++j) {
                    p.c[k] += sp[i + j].center * m[k][j];
                    p.r[k] += sp[i + j].radius * m[k][j];
                }
        }
        p.end[0] = {p.center(0), p.radius(0)};
        p.end[1] = {p.c[0] + p.c[1] + p.c[2] + p.c[3], p.r[0] + p.r[1] + p.r[2] + p.r[3]};
        p.dc[0] = p.c[1];
        p.dr[0] = p.r[1];
        p.dc[1] = p.c[1] + p.c[2] * 2 + p.c[3] * 3;
        p.dr[1] = p.r[1] + 2 * p.r[2] + 3 * p.r[3];
        for (int a = 0; a < 3; ++a) {
            double lo = kInfinity, hi = -kInfinity;
            extend_axis(p, a, &lo, &hi);
            // Rounding in the line test must not drop a piece that the line grazes.
            double pad = 1e-9 * std::max({std::fabs(lo), std::fabs(hi), 1.0});
            p.box.lo[a] = lo - pad;
            p.box.hi[a] = hi + pad;
        }
        pieces.push_back(p);
    }
    std::vector<Ball> joints;
    for (const Piece& p : pieces) joints.push_back(p.end[0]);
    joints.push_back(pieces.back().end[1]);
    // POV-Ray's bounding box, which also clips what lies outside it: the modelling spheres,
    // with twice their radii for cubic_spline (whose pieces may swing past them).
    Bounds3 box;
    const double grow = s.spline == SweepSpline::Cubic ? 2 : 1;
    for (const scene::Sphere& b : sp) {
        box.extend(b.center - Vec3(grow * b.radius));
        box.extend(b.center + Vec3(grow * b.radius));
    }
    return std::make_unique<SphereSweepPrim>(std::move(pieces), std::move(joints), box,
                                             s.tolerance);
}

}  // namespace glint::render
