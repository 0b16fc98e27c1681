// poly, cubic, quartic (POV-Ray 3.7 manual 2.4.3.4; poly.cpp): the implicit surface
// sum c_ijk x^i y^j z^k = 0 of total degree `order`, terms in POV-Ray's order (x power
// descending, then y, then z). Inside where the sum is below 1e-4 (INSIDE_TOLERANCE). Along the
// ray (unit direction in object space) the sum is a polynomial of degree `order` in the
// distance; its roots come from the interval solver over the stretch that can hold a hit.
// Unbounded like POV-Ray's (clip or bound it).
#include <cmath>
#include <vector>

#include "render/shapes/polynomial/poly_solve.h"
#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

struct Term {
    int i, j, k;
    double c;
};

constexpr double kMaxDistance = 1e7;  // POV-Ray's MAX_DISTANCE
constexpr double kMinDepth = 1e-4;    // DEPTH_TOLERANCE

class PolyPrim final : public Primitive {
public:
    PolyPrim(int order, std::vector<Term> terms) : order_(order), terms_(std::move(terms)) {}

    Bounds3 bounds() const override { return {Vec3(-kInfinity), Vec3(kInfinity)}; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        return nearest_of_all(ray, tmax, hit);
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        double len = length(ray.dir);
        if (!(len > 0)) return;
        Vec3 P = ray.origin, D = ray.dir / len;
        // Powers of (P + k D) per axis as polynomials in k.
        const int n = order_;
        std::vector<double> pw[3];
        for (int a = 0; a < 3; ++a) {
            pw[a].assign(static_cast<size_t>(n + 1) * (n + 1), 0.0);
            pw[a][0] = 1;
            for (int e = 1; e <= n; ++e)
                for (int d = 0; d < e; ++d) {
                    double prev = pw[a][static_cast<size_t>(e - 1) * (n + 1) + d];
                    pw[a][static_cast<size_t>(e) * (n + 1) + d] += prev * P[a];
                    pw[a][static_cast<size_t>(e) * (n + 1) + d + 1] += prev * D[a];
                }
        }
        double c[kMaxSolveDegree + 1] = {};
        double tmp[kMaxSolveDegree + 1];
        for (const Term& t : terms_) {
            const double* px = &pw[0][static_cast<size_t>(t.i) * (n + 1)];
            const double* py = &pw[1][static_cast<size_t>(t.j) * (n + 1)];
            const double* pz = &pw[2][static_cast<size_t>(t.k) * (n + 1)];
            std::fill(tmp, tmp + n + 1, 0.0);
            for (int a = 0; a <= t.i; ++a)
                for (int b = 0; b <= t.j; ++b) {
                    double ab = px[a] * py[b];
                    if (ab == 0) continue;
                    for (int d = 0; d <= t.k; ++d) tmp[a + b + d] += ab * pz[d];
                }
            for (int d = 0; d <= n; ++d) c[d] += t.c * tmp[d];
        }
        double hi = std::min(tmax * len, kMaxDistance);
        double roots[kMaxSolveDegree];
        int m = solve_in_interval(c, n, kMinDepth, hi, roots);
        for (int r = 0; r < m; ++r) {
            double k = roots[r];
            LocalHit& h = hits->emplace_back();
            h.t = k / len;
            h.p = P + D * k;
            for (int it = 0; it < 2; ++it) {  // onto the surface (see quadric.cpp)
                Vec3 g = gradient(h.p);
                double g2 = length_squared(g);
                if (!(g2 > 0)) break;
                Vec3 step = g * (value(h.p) / g2);
                if (!is_finite(step) || length(step) > 1e-3 * (1 + length(h.p))) break;
                h.p -= step;
            }
            Vec3 g = gradient(h.p);
            double gl = length(g);
            h.p_error = rounding_error(h.p, 8) +
                        Vec3(gl > 0 ? gamma(2 * n + 4) * magnitude(h.p) / gl : 1e-9);
            h.ng = gl > 0 && std::isfinite(gl) ? g / gl : Vec3(0, 1, 0);
            h.n = h.ng;
        }
    }

    bool inside(const Vec3& p) const override { return value(p) < 1e-4; }

private:
    static double ipow(double x, int e) {
        double r = 1;
        for (int i = 0; i < e; ++i) r *= x;
        return r;
    }
    double value(const Vec3& p) const {
        double s = 0;
        for (const Term& t : terms_) s += t.c * ipow(p.x, t.i) * ipow(p.y, t.j) * ipow(p.z, t.k);
        return s;
    }
    double magnitude(const Vec3& p) const {
        Vec3 a = abs(p);
        double s = 0;
        for (const Term& t : terms_)
            s += std::fabs(t.c) * ipow(a.x, t.i) * ipow(a.y, t.j) * ipow(a.z, t.k);
        return s;
    }
    Vec3 gradient(const Vec3& p) const {
        Vec3 g(0);
        for (const Term& t : terms_) {
            if (t.i > 0) g.x += t.c * t.i * ipow(p.x, t.i - 1) * ipow(p.y, t.j) * ipow(p.z, t.k);
            if (t.j > 0) g.y += t.c * t.j * ipow(p.x, t.i) * ipow(p.y, t.j - 1) * ipow(p.z, t.k);
            if (t.k > 0) g.z += t.c * t.k * ipow(p.x, t.i) * ipow(p.y, t.j) * ipow(p.z, t.k - 1);
        }
        return g;
    }

    int order_;
    std::vector<Term> terms_;
};

}  // namespace

std::unique_ptr<Primitive> make_poly(const scene::Poly& s, const char** why) {
    const int n = s.order;
    if (n < 2 || n > kMaxSolveDegree - 1 ||
        static_cast<int>(s.coefficients.size()) != (n + 1) * (n + 2) * (n + 3) / 6) {
        *why = "poly of an unsupported order (2 to 15)";
        return nullptr;
    }
    std::vector<Term> terms;
    size_t idx = 0;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j)
            for (int k = n - i - j; k >= 0; --k) {
                double c = s.coefficients[idx++];
                if (c != 0) terms.push_back({i, j, k, c});
            }
    if (terms.empty()) {
        *why = "poly with all coefficients zero";
        return nullptr;
    }
    return std::make_unique<PolyPrim>(n, std::move(terms));
}

}  // namespace glint::render
