#include "render/textures/normal.h"

#include <cmath>

namespace glint::render {
namespace {

using scene::PatternKind;
using scene::WarpKind;

// normal.cpp Pyramid_Vect: the corners of a regular tetrahedron around the point.
constexpr Vec3 kPyramid[4] = {{0.942809041, -0.333333333, 0.0},
                              {-0.471404521, -0.333333333, 0.816496581},
                              {-0.471404521, -0.333333333, -0.816496581},
                              {0.0, 1.0, 0.0}};

Vec3 safe_normalize(const Vec3& v) {
    double l = length(v);
    return l > 0 ? v / l : v;
}

// normal.cpp Hermite_Cubic.
double hermite_cubic(double t, const scene::SlopeMapEntry& a, const scene::SlopeMapEntry& b) {
    double tt = t * t, ttt = tt * t;
    double r = ttt * (a.slope + b.slope + 2.0 * (a.height - b.height));
    r += -tt * (2.0 * a.slope + b.slope + 3.0 * (a.height - b.height));
    r += t * a.slope + a.height;
    return r;
}

// Do_Slope_Map: the pattern value reshaped by the slope_map (none: the value itself).
double slope_value(const std::vector<scene::SlopeMapEntry>& map, double value) {
    if (map.empty()) return value;
    BlendPick b = search_blend_map(map, value);
    if (b.prev == b.cur) return map[b.cur].height;
    return hermite_cubic(b.fraction, map[b.prev], map[b.cur]);
}

// Parameters for evaluating at an already warped point (Evaluate_TPat without Warp_EPoint):
// no warps, except the classic turbulence that marble, wood, agate and the spirals read inside
// their pattern functions (agate's with no displacement; the spirals' is displaced again).
scene::PatternParams unwarped(PatternKind kind, const scene::PatternParams& params) {
    scene::PatternParams p = params;
    p.warps.clear();
    for (const scene::Warp& w : params.warps) {
        if (w.kind != WarpKind::ClassicTurbulence) continue;
        if (kind == PatternKind::Marble || kind == PatternKind::Wood ||
            kind == PatternKind::Spiral1 || kind == PatternKind::Spiral2) {
            p.warps.push_back(w);
        } else if (kind == PatternKind::Agate) {
            scene::Warp z = w;
            z.turbulence.amount = Vec3(0, 0, 0);
            p.warps.push_back(z);
        }
    }
    return p;
}

Vec3 perturb(const scene::Normal& nrm, const Vec3& point, const Vec3& n_in,
             const PatternContext& ctx);

Vec3 perturb_entries(const scene::Normal& nrm, const Vec3& local, const Vec3& n_in,
                     const PatternContext& ctx) {
    const scene::PatternParams& pp = nrm.params;
    const double value = evaluate_pattern(nrm.kind, pp, local, ctx);
    Vec3 n = warp_normal(Transform(), pp, n_in);
    const Vec3 tp = pp.warps.empty() ? local : warp_point(nrm.kind, pp, local);
    Vec3 out;
    if (!nrm.entries.empty()) {
        out = perturb(nrm.entries[block_index(value, nrm.entries.size())], tp, n, ctx);
    } else {
        const auto& map = nrm.normal_map;
        BlendPick b = search_blend_map(map, value);
        out = perturb(map[b.cur].normal[0], tp, n, ctx);
        if (b.prev != b.cur) {
            Vec3 prev = perturb(map[b.prev].normal[0], tp, n, ctx);
            out = prev * (1.0 - b.fraction) + out * b.fraction;
        }
    }
    return unwarp_normal(Transform(), pp, out);
}

// Perturb_Normal at `point` (the parent's pattern space); `n_in` is in that space too.
Vec3 perturb(const scene::Normal& nrm, const Vec3& point, const Vec3& n_in,
             const PatternContext& ctx) {
    if (nrm.kind == PatternKind::Plain) return n_in;
    const scene::PatternParams& pp = nrm.params;
    const Vec3 local = nrm.transform.is_identity() ? point : nrm.transform.inverse_point(point);
    if (nrm.kind != PatternKind::Average && (!nrm.normal_map.empty() || !nrm.entries.empty())) {
        // The entries see the normal in this pattern's space.
        Vec3 n = safe_normalize(nrm.transform.is_identity() ? n_in
                                                            : nrm.transform.inverse().normal(n_in));
        n = perturb_entries(nrm, local, n, ctx);
        return nrm.transform.is_identity() ? n : safe_normalize(nrm.transform.normal(n));
    }
    if (has_special_normal(nrm.kind)) {
        Vec3 n = safe_normalize(nrm.transform.is_identity() ? n_in
                                                            : nrm.transform.inverse().normal(n_in));
        n = special_normal(nrm.kind, pp, local, n, nrm.amount, ctx);
        return nrm.transform.is_identity() ? n : safe_normalize(nrm.transform.normal(n));
    }
    if (nrm.kind == PatternKind::Average) {
        // Do_Average_Normals.
        Vec3 n = warp_normal(nrm.transform, pp, n_in);
        const Vec3 tp = pp.warps.empty() ? local : warp_point(nrm.kind, pp, local);
        Vec3 sum(0, 0, 0);
        double total = 0;
        for (const scene::NormalMapEntry& e : nrm.normal_map) {
            sum += perturb(e.normal[0], tp, n, ctx) * e.value;
            total += e.value;
        }
        return unwarp_normal(nrm.transform, pp, sum / total);
    }
    if (nrm.kind == PatternKind::ImageMap) return n_in;  // bump_map: announced as unsupported
    // The slope of the pattern value: four samples around the warped point.
    Vec3 n = warp_normal(nrm.transform, pp, n_in);
    const double amount = nrm.amount * -5.0 * (0.02 / nrm.accuracy);
    const Vec3 tp = pp.warps.empty() ? local : warp_point(nrm.kind, pp, local);
    const bool plain_params = pp.warps.empty();
    const scene::PatternParams stripped = plain_params ? scene::PatternParams{} : unwarped(nrm.kind, pp);
    const scene::PatternParams& eval_params = plain_params ? pp : stripped;
    for (const Vec3& d : kPyramid) {
        Vec3 p1 = tp + d * nrm.accuracy;
        double v = slope_value(nrm.slope_map, evaluate_pattern(nrm.kind, eval_params, p1, ctx));
        n += d * (v * amount);
    }
    return unwarp_normal(nrm.transform, pp, n);
}

}  // namespace

Vec3 warp_normal(const Transform& head, const scene::PatternParams& params, const Vec3& n_in) {
    Vec3 n = safe_normalize(n_in);
    if (!head.is_identity()) n = head.inverse().normal(n);
    for (const scene::Warp& w : params.warps)
        if (w.kind == WarpKind::Transform) n = w.transform.inverse().normal(n);
    return safe_normalize(n);
}

Vec3 unwarp_normal(const Transform& head, const scene::PatternParams& params, const Vec3& n_in) {
    Vec3 n = safe_normalize(n_in);
    for (auto it = params.warps.rbegin(); it != params.warps.rend(); ++it)
        if (it->kind == WarpKind::Transform) n = it->transform.normal(n);
    if (!head.is_identity()) n = head.normal(n);
    return safe_normalize(n);
}

Vec3 perturb_normal(const scene::Normal& normal, const PatternPoint& at, const Vec3& n,
                    const PatternContext& ctx) {
    if (normal.kind == PatternKind::Plain) return n;
    Vec3 p = at.p;
    if (normal.uv_mapping) {
        if (!at.has_uv)
            throw Error(ErrorKind::Render, normal.loc,
                        "uv_mapping on a surface that has no uv coordinates");
        p = Vec3(at.uv.x, at.uv.y, 0);
    }
    return perturb(normal, p, n, ctx);
}

}  // namespace glint::render
