// superellipsoid { <e, n> } (POV-Ray 3.7 manual 2.4.1.10; super.cpp):
//   f(p) = g(g(|x|, |y|, 2/e), |z|, 2/n) - 1,  g(a, b, q) = (a^q + b^q)^(1/q),
// inside where f < 0, within the cube [-1, 1]^3. POV-Ray's root search: the ray's stretch
// inside the (slightly enlarged) cube is cut at the planes x = 0, y = 0, z = 0, x = +-y,
// x = +-z, y = +-z, between which f changes convexity at most once; each piece with a sign
// change is solved by secant/bisection, and pieces without one are probed for a hidden
// double crossing. The normal is f's gradient in POV-Ray's ratio form.
#include <algorithm>
#include <cmath>

#include "render/shapes/shapes.h"

namespace glint::render {
namespace {

constexpr double kZero = 1e-10;       // POV-Ray's ZERO_TOLERANCE
constexpr double kEpsilon = 1e-10;    // POV-Ray's EPSILON
constexpr double kBoxLimit = 1.01;    // MIN_VALUE / MAX_VALUE
constexpr int kMaxIterations = 20;
constexpr double kMinDepth = 1e-4;    // DEPTH_TOLERANCE (unit direction)

double power(double x, double e) {
    int i = static_cast<int>(e);
    if (e == static_cast<double>(i)) {
        switch (i) {
            case 0: return 1;
            case 1: return x;
            case 2: return x * x;
            case 3: return x * x * x;
            case 4: return (x * x) * (x * x);
            default: break;
        }
    }
    return std::pow(x, e);
}

double g(double x, double y, double e) {
    if (x > y) {
        double v = 1 + power(y / x, e);
        if (v != 1) v = power(v, 1 / e);
        return v * x;
    }
    if (y != 0) {
        double v = 1 + power(x / y, e);
        if (v != 1) v = power(v, 1 / e);
        return v * y;
    }
    return 0;
}

class SuperellipsoidPrim final : public Primitive {
public:
    SuperellipsoidPrim(double e, double n) : px_(2 / e), pz_(2 / n) {}

    Bounds3 bounds() const override { return {Vec3(-1.0001), Vec3(1.0001)}; }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        return nearest_of_all(ray, tmax, hit);
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        double len = length(ray.dir);
        if (!(len > 0)) return;
        Vec3 P = ray.origin, D = ray.dir / len;
        double t1, t2;
        if (!box(P, D, &t1, &t2)) return;
        if (t2 < kMinDepth) return;
        t1 = std::max(t1, kMinDepth);
        double dists[11];
        int cnt = 0;
        dists[cnt++] = t1;
        dists[cnt++] = t2;
        // Cutting planes through the origin (normals below), within the enlarged stretch.
        static const double kPlanes[9][3] = {{1, 1, 0}, {1, -1, 0}, {1, 0, 1}, {1, 0, -1},
                                             {0, 1, 1}, {0, 1, -1}, {1, 0, 0}, {0, 1, 0},
                                             {0, 0, 1}};
        double pad = kEpsilon * (t2 - t1);
        for (const auto& pl : kPlanes) {
            double d = D.x * pl[0] + D.y * pl[1] + D.z * pl[2];
            if (std::fabs(d) < kEpsilon) continue;
            double t = -(P.x * pl[0] + P.y * pl[1] + P.z * pl[2]) / d;
            if (t >= t1 - pad && t <= t2 + pad) dists[cnt++] = t;
        }
        for (int i = 1; i < cnt; ++i)  // insertion sort: at most 11 values
            for (int k = i; k > 0 && dists[k] < dists[k - 1]; --k) std::swap(dists[k], dists[k - 1]);
        double kmax = tmax * len;
        auto add = [&](double k) {
            if (!(k > kMinDepth) || !(k < kmax)) return;
            LocalHit& h = hits->emplace_back();
            h.t = k / len;
            h.p = P + D * k;
            h.p_error = rounding_error(h.p, 8) + Vec3(1e-9);
            h.ng = normal(h.p);
            h.n = h.ng;
        };
        double k0 = dists[0];
        double v0 = f(P + D * k0);
        if (std::fabs(v0) < kZero) add(k0);
        for (int i = 1; i < cnt; ++i) {
            double k1 = dists[i];
            double v1 = f(P + D * k1);
            if (std::fabs(v1) < kZero) {
                add(k1);
            } else if (v0 * v1 < 0) {
                add(solve(P, D, k0, v0, k1, v1));
            } else {
                double k;
                if (hidden_crossing(P, D, k0, v0, k1, &k)) add(k);
            }
            k0 = k1;
            v0 = v1;
        }
    }

    bool inside(const Vec3& p) const override { return f(p) < kEpsilon; }

private:
    double f(const Vec3& p) const {
        return g(g(std::fabs(p.x), std::fabs(p.y), px_), std::fabs(p.z), pz_) - 1;
    }

    Vec3 normal(Vec3 p) const {
        double r = 0, z2n = 0;
        if (p.z != 0) {
            z2n = power(std::fabs(p.z), pz_);
            p.z = z2n / p.z;
        }
        if (std::fabs(p.x) > std::fabs(p.y)) {
            r = power(std::fabs(p.y / p.x), px_);
            p.x = (1 - z2n) / p.x;
            p.y = p.y != 0 ? (1 - z2n) * r / p.y : 0;
        } else if (p.y != 0) {
            r = power(std::fabs(p.x / p.y), px_);
            p.x = p.x != 0 ? (1 - z2n) * r / p.x : 0;
            p.y = (1 - z2n) / p.y;
        }
        if (p.z != 0) p.z *= 1 + r;
        double l = length(p);
        return l > 0 && std::isfinite(l) ? p / l : Vec3(0, 0, 1);
    }

    // Slab test against [-1.01, 1.01]^3 (POV-Ray's intersect_box).
    static bool box(const Vec3& P, const Vec3& D, double* dmin, double* dmax) {
        double lo = -kInfinity, hi = kInfinity;
        for (int a = 0; a < 3; ++a) {
            double p = P[a], d = D[a];
            if (std::fabs(d) > kEpsilon) {
                double ta = (-kBoxLimit - p) / d, tb = (kBoxLimit - p) / d;
                if (ta > tb) std::swap(ta, tb);
                lo = std::max(lo, ta);
                hi = std::min(hi, tb);
                if (hi < kEpsilon || lo > hi) return false;
            } else if (p < -kBoxLimit || p > kBoxLimit) {
                return false;
            }
        }
        *dmin = lo;
        *dmax = hi;
        return true;
    }

    // Secant and bisection together, keeping the bracket (POV-Ray's solve_hit1).
    double solve(const Vec3& P, const Vec3& D, double k0, double v0, double k1, double v1) const {
        for (int i = 0; i < kMaxIterations; ++i) {
            if (std::fabs(v0) < kZero) return k0;
            if (std::fabs(v1) < kZero) return k1;
            double k2 = k0 + (k1 - k0) * (std::fabs(v0) / std::fabs(v1 - v0));
            double v2 = f(P + D * k2);
            double k3 = 0.5 * (k0 + k1);
            double v3 = f(P + D * k3);
            if (v2 * v3 < 0) {
                k0 = k2, v0 = v2;
                k1 = k3, v1 = v3;
            } else if (std::fabs(v2) < std::fabs(v3)) {
                if (v0 * v2 < 0) k1 = k2, v1 = v2;
                else k0 = k2, v0 = v2;
            } else {
                if (v0 * v3 < 0) k1 = k3, v1 = v3;
                else k0 = k3, v0 = v3;
            }
        }
        return std::fabs(v0) < std::fabs(v1) ? k0 : k1;
    }

    // No sign change between k0 and k1, but the ray may dip through the surface and back
    // (POV-Ray's check_hit2): secant steps from k0 towards a root; success when the sign flips.
    bool hidden_crossing(const Vec3& P, const Vec3& D, double k0, double v0, double k1,
                         double* out) const {
        double a = k0, b = k0 + 0.0001 * (k1 - k0);
        double maxdelta = k1 - k0;
        for (int i = 0; a < k1 && i < kMaxIterations; ++i) {
            double v1 = f(P + D * b);
            if (v0 * v1 < 0) {
                *out = solve(P, D, a, v0, b, v1);
                return true;
            }
            if (std::fabs(v1) < kZero) {
                *out = b;
                return true;
            }
            if ((v0 > 0 && v1 > v0) || (v0 < 0 && v1 < v0) || v1 == v0) return false;
            double delta = v1 * (b - a) / (v1 - v0);
            if (std::fabs(delta) > maxdelta) return false;
            v0 = v1;
            a = b;
            b -= delta;
        }
        return false;
    }

    double px_, pz_;
};

}  // namespace

std::unique_ptr<Primitive> make_superellipsoid(const scene::Superellipsoid& s, const char** why) {
    if (!(s.e > 0) || !(s.n > 0) || !std::isfinite(s.e) || !std::isfinite(s.n)) {
        *why = "superellipsoid with non-positive exponents";
        return nullptr;
    }
    return std::make_unique<SuperellipsoidPrim>(s.e, s.n);
}

}  // namespace glint::render
