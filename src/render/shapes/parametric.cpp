// parametric (POV-Ray 3.7 reference 3.4.5.1.10; fpmetric.cpp, D. Skarda, T. Bily, R. Suzuki):
// the surface <fx(u, v), fy(u, v), fz(u, v)> over a rectangle of (u, v), found by subdividing
// the rectangle. Each piece's range of every coordinate is bounded from its four corner values
// and max_gradient (Evaluate_Function_Interval_UV, which also takes `accuracy` off each corner
// value); a piece is dropped when the slab of depths those ranges allow misses the ray, the
// container's interval, or the other coordinates' slabs, and halved across its longer side
// otherwise, until that side or the widest slab is below `accuracy`. The nearest such piece's
// slab entry (the last non-parallel axis's, as POV-Ray keeps it) is the hit and its low corner
// the hit's (u, v); the normal is the cross product of forward differences of step `accuracy`
// there. `precompute` keeps the ranges of the first 2^depth pieces per coordinate.
// All depths are measured as POV-Ray measures them: along the ray in the units of the space the
// object is placed in (the transform it is built with; enclosing CSG transforms are not seen),
// so that accuracy, the 4 * accuracy the search skips past the container's entry, and POV-Ray's
// MIN_ISECT_DEPTH (the caller drops the only hit when nearer than that) act alike.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "render/shapes/container.h"
#include "render/shapes/shapes.h"
#include "render/textures/pattern.h"
#include "scene/scene.h"

namespace glint::render {
namespace {

constexpr double kEpsilon = 1e-10;        // POV-Ray's EPSILON
constexpr double kMinDepth = 1e-4;        // MIN_ISECT_DEPTH
constexpr int kMaxSector = 10000000;      // fpmetric.cpp Max_intNumber
constexpr int kStack = 64;                // POV-Ray's 32, which deep searches overrun

struct Range {
    double lo, hi;
};

class ParametricPrim final : public Primitive {
public:
    ParametricPrim(const scene::Parametric& s, const scene::Scene& scene, const Transform& xf)
        : s_(s), functions_(scene.functions), xf_(xf) {
        ctx_.noise_generator = scene.global.noise_generator;
        ctx_.number_of_waves = scene.global.number_of_waves;
        ctx_.functions = &functions_;
        env_ = user_function_env(ctx_);
        if (s_.precompute_depth > 0 && (s_.precompute[0] || s_.precompute[1] || s_.precompute[2])) {
            const size_t n = size_t{1} << s_.precompute_depth;
            for (int j = 0; j < 3; ++j)
                if (s_.precompute[j]) pre_[j].resize(n);
            last_ = 1 << (s_.precompute_depth - 1);
            precompute(1, s_.uv_min.x, s_.uv_min.y, s_.uv_max.x, s_.uv_max.y);
        }
    }
    ParametricPrim(const ParametricPrim&) = delete;
    ParametricPrim& operator=(const ParametricPrim&) = delete;

    Bounds3 bounds() const override { return container_bounds(s_.container); }

    bool intersect(const Ray& ray, double tmax, LocalHit* hit) const override {
        double t;
        Vec2 uv;
        if (!trace(ray, &t, &uv) || !(t < tmax)) return false;
        fill(ray, t, uv, hit);
        return true;
    }

    bool occludes(const Ray& ray, double tmax) const override {
        double t;
        Vec2 uv;
        return trace(ray, &t, &uv) && t < tmax;
    }

    void intersect_all(const Ray& ray, double tmax, HitList* hits) const override {
        double t;
        Vec2 uv;
        if (trace(ray, &t, &uv) && t < tmax) fill(ray, t, uv, &hits->emplace_back());
    }

    // Parametric::Inside: a parametric surface has no inside.
    bool inside(const Vec3&) const override { return false; }

private:
    double eval(int j, double u, double v) const {
        const double args[3] = {u, v, 0};
        return scene::evaluate_function(env_, s_.function[j], args, 3);
    }

    // Parametric::Interval: the range a function can reach along an edge of length dx whose
    // ends are a and b, given its gradient bound.
    static Range edge_range(double dx, double a, double b, double g) {
        const double dy = std::fabs(a - b);
        const double ofs = std::max(0.0, g * (dx - dy / g) / 2);
        return {std::min(a, b) - ofs, std::max(a, b) + ofs};
    }

    // Evaluate_Function_Interval_UV: corner values less `accuracy`, bounded along the two
    // edges of constant u, then across u between the edges' bounds.
    Range piece_range(int j, double u0, double v0, double u1, double v1) const {
        const double a = s_.accuracy, g = s_.max_gradient;
        const double f00 = eval(j, u0, v0) - a, f01 = eval(j, u0, v1) - a;
        const double f10 = eval(j, u1, v0) - a, f11 = eval(j, u1, v1) - a;
        const Range left = edge_range(v1 - v0, f00, f01, g);
        const Range right = edge_range(v1 - v0, f10, f11, g);
        return {edge_range(u1 - u0, left.lo, right.lo, g).lo,
                edge_range(u1 - u0, left.hi, right.hi, g).hi};
    }

    // Precomp_Par_Int: piece k's children are 2k (lower half) and 2k + 1, split across the
    // longer side (u when equal), as the search splits.
    void precompute(int k, double u0, double v0, double u1, double v1) {
        if (k >= last_) {
            for (int j = 0; j < 3; ++j)
                if (!pre_[j].empty())
                    pre_[j][static_cast<size_t>(k)] = piece_range(j, u0, v0, u1, v1);
            return;
        }
        if (u1 - u0 < v1 - v0) {
            const double vm = (v0 + v1) / 2.0;
            precompute(2 * k, u0, v0, u1, vm);
            precompute(2 * k + 1, u0, vm, u1, v1);
        } else {
            const double um = (u0 + u1) / 2.0;
            precompute(2 * k, u0, v0, um, v1);
            precompute(2 * k + 1, um, v0, u1, v1);
        }
        for (int j = 0; j < 3; ++j) {
            if (pre_[j].empty()) continue;
            const Range& a = pre_[j][static_cast<size_t>(2 * k)];
            const Range& b = pre_[j][static_cast<size_t>(2 * k + 1)];
            pre_[j][static_cast<size_t>(k)] = {std::min(a.lo, b.lo), std::max(a.hi, b.hi)};
        }
    }

    // The container's interval along P + t D (Box::Intersect with D as it is; Sphere::Intersect
    // with D normalized, its depths scaled back).
    bool container(const Vec3& p, const Vec3& d, double* t1, double* t2) const {
        if (!s_.container.sphere) return container_interval(s_.container, p, d, t1, t2);
        const double dl = length(d);
        if (!container_interval(s_.container, p, d / dl, t1, t2)) return false;
        *t1 /= dl;
        *t2 /= dl;
        return true;
    }

    // The slab of depths in which coordinate `axis` lies in `r`; false when the ray misses it
    // (parallel to the axis and outside, or the slab outside [t1, t2]).
    struct Slab {
        bool parallel = false;
        double lo = 0, hi = 0;
    };

    // Parametric::All_Intersections. `t`: the depth in the ray's units, `uv`: the piece's.
    bool trace(const Ray& ray, double* t_out, Vec2* uv_out) const {
        const double len = length(ray.dir);
        if (!(len > 0) || !std::isfinite(len)) return false;
        const Vec3 unit = ray.dir / len;
        const double scale = length(xf_.vector(unit));
        if (!(scale > 0) || !std::isfinite(scale)) return false;
        const Vec3 P = ray.origin;
        const Vec3 D = unit / scale;  // one unit of depth: one unit in the placing space
        double depth1, depth2;
        if (!container(P, D, &depth1, &depth2)) return false;
        if (depth1 == depth2) depth1 = 0;
        depth1 += 4 * s_.accuracy;
        if (depth1 > depth2) return false;

        double lo_u[kStack], hi_u[kStack], lo_v[kStack], hi_v[kStack];
        int sector[kStack];
        lo_u[0] = s_.uv_min.x;
        hi_u[0] = s_.uv_max.x;
        lo_v[0] = s_.uv_min.y;
        hi_v[0] = s_.uv_max.y;
        sector[0] = 1;
        int max_pre[3];
        for (int j = 0; j < 3; ++j)
            max_pre[j] = pre_[j].empty() ? 0 : 1 << s_.precompute_depth;

        double result = kInfinity;
        Vec2 uv;
        int i = 0;
        while (i >= 0) {
            const double u0 = lo_u[i], u1 = hi_u[i], v0 = lo_v[i], v1 = hi_v[i];
            double size = u1 - u0;
            bool split_v = false;
            if (v1 - v0 > size) {
                size = v1 - v0;
                split_v = true;
            }
            Slab slab[3];
            double potential = 0, widest = 0;
            bool missed = false;
            for (int j = 0; j < 3 && !missed; ++j) {
                const Range r = sector[i] < max_pre[j]
                                    ? pre_[j][static_cast<size_t>(sector[i])]
                                    : piece_range(j, u0, v0, u1, v1);
                if (std::fabs(D[j]) < kEpsilon) {
                    slab[j].parallel = true;
                    missed = r.hi < P[j] || r.lo > P[j];
                    continue;
                }
                double a = (r.hi - P[j]) / D[j], b = (r.lo - P[j]) / D[j];
                if (a > b) std::swap(a, b);
                slab[j].lo = a;
                slab[j].hi = b;
                if (a > depth2 || b < depth1 || a > result) {
                    missed = true;
                    continue;
                }
                potential = a;
                for (int k = 0; k < j; ++k)
                    if (!slab[k].parallel && (a > slab[k].hi || b < slab[k].lo)) missed = true;
                widest = std::max(widest, b - a);
            }
            if (missed) {
                --i;
                continue;
            }
            size = std::min(size, widest);
            if (size < s_.accuracy || i + 1 >= kStack) {
                if (result > potential && potential > depth1) {
                    result = potential;
                    uv = Vec2(u0, v0);
                }
                --i;
                continue;
            }
            sector[i] = std::min(sector[i] * 2, kMaxSector);
            sector[i + 1] = sector[i];
            sector[i]++;
            // Piece i keeps the upper half, i + 1 takes the lower.
            lo_u[i + 1] = u0;
            hi_u[i + 1] = u1;
            lo_v[i + 1] = v0;
            hi_v[i + 1] = v1;
            if (split_v) {
                const double m = (v0 + v1) / 2.0;
                hi_v[i + 1] = m;
                lo_v[i] = m;
            } else {
                const double m = (u0 + u1) / 2.0;
                hi_u[i + 1] = m;
                lo_u[i] = m;
            }
            ++i;
        }
        if (!(result < depth2) || result < kMinDepth) return false;
        *t_out = result / (scale * len);
        *uv_out = uv;
        return *t_out > 0;
    }

    // Parametric::Normal: the cross product of the forward differences in u and v.
    Vec3 normal_at(const Vec2& uv, const Vec3& dir) const {
        const double a = s_.accuracy;
        Vec3 f, fu, fv;
        for (int j = 0; j < 3; ++j) {
            f[j] = eval(j, uv.x, uv.y);
            fu[j] = eval(j, uv.x + a, uv.y);
            fv[j] = eval(j, uv.x, uv.y + a);
        }
        const Vec3 n = cross(fu - f, fv - f);
        const double l = length(n);
        if (!(l > 0) || !std::isfinite(l)) return -normalize(dir);  // degenerate: face the ray
        return n / l;
    }

    void fill(const Ray& ray, double t, const Vec2& uv, LocalHit* h) const {
        h->t = t;
        h->p = ray.origin + ray.dir * t;
        h->p_error = rounding_error(h->p, 4);
        h->ng = normal_at(uv, ray.dir);
        h->n = h->ng;
        h->uv = uv;
        h->has_uv = true;
    }

    scene::Parametric s_;
    // The scene's functions, copied (as the isosurface keeps them).
    std::vector<scene::Function> functions_;
    PatternContext ctx_;
    scene::FunctionEnv env_;
    Transform xf_;
    std::vector<Range> pre_[3];  // precompute: piece k's range at [k], k < 2^depth
    int last_ = 0;               // pieces from here on are leaves of the precomputation
};

}  // namespace

std::unique_ptr<Primitive> make_parametric(const scene::Parametric& s, const scene::Scene& scene,
                                           const Transform& xf, const char** why) {
    for (int f : s.function) {
        if (f < 0 || f >= static_cast<int>(scene.functions.size())) {
            *why = "parametric without its three functions";
            return nullptr;
        }
        if (scene.functions[static_cast<size_t>(f)].is_vector()) {
            *why = "parametric of a vector (pigment, transform or spline) function";
            return nullptr;
        }
    }
    if (!s.container.valid()) {
        *why = "parametric with an empty container";
        return nullptr;
    }
    if (!(s.accuracy > 0) || !(s.max_gradient > 0)) {
        *why = "parametric accuracy and max_gradient must be positive";
        return nullptr;
    }
    return std::make_unique<ParametricPrim>(s, scene, xf);
}

}  // namespace glint::render
