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
             const PatternContext& ctx, const TextureCache* textures);

// imageutil.cpp bump_map: the heights (greyscale) of three neighbouring pixels make a small
// triangle whose normal replaces `normal`, expressed in a frame around it.
Vec3 bump_map(const scene::Normal& nrm, const Vec3& tp, const Vec3& normal,
              const TextureCache* textures) {
    const scene::ImageMap& im = nrm.params.image;
    const ImageTexture* tex = textures ? textures->find(im) : nullptr;
    if (!tex) throw Error(ErrorKind::Render, im.loc, "image '" + im.file + "' was not loaded");
    double x, y;
    if (!image_map_position(im, *tex, tp, &x, &y)) return normal;
    const double w = tex->width(), h = tex->height();
    auto grey = [](const scene::ColorFT& c) {
        return 0.297 * c.rgb.r + 0.589 * c.rgb.g + 0.114 * c.rgb.b;
    };
    // Heights: the grey of the colours, or (use_index on a palette image) the palette
    // indices, as POV-Ray's bump_map takes them.
    int i1 = -1, i2 = -1, i3 = -1;
    const double g1 = grey(image_map_sample(im, *tex, x, y, &i1));
    x -= 1.0;
    y += 1.0;
    if (x < 0.0) x += w;
    else if (x >= w) x -= w;
    if (y < 0.0) y += h;
    else if (y >= h) y -= h;
    const double g2 = grey(image_map_sample(im, *tex, x, y, &i2));
    x += 2.0;
    if (x < 0.0) x += w;
    else if (x >= w) x -= w;
    const double g3 = grey(image_map_sample(im, *tex, x, y, &i3));
    const bool by_index = im.use_index && i1 != -1 && i2 != -1 && i3 != -1;
    const double h1 = by_index ? i1 : g1, h2 = by_index ? i2 : g2, h3 = by_index ? i3 : g3;
    const double a = nrm.amount;
    const Vec3 p1(0, a * h1, 0), p2(-1, a * h2, 1), p3(1, a * h3, 1);
    const Vec3 bump = safe_normalize(cross(p3 - p2, p1 - p2));
    Vec3 yp = normal;
    Vec3 xp = cross(yp, Vec3(0, 1, 0));
    double len = length(xp);
    if (len < kPovEpsilon) {
        yp = std::fabs(normal.y - 1.0) < kPovEpsilon ? Vec3(0, 1, 0) : Vec3(0, -1, 0);
        xp = Vec3(1, 0, 0);
        len = 1.0;
    }
    xp = xp / len;
    const Vec3 zp = safe_normalize(cross(xp, yp));
    return xp * bump.x + yp * bump.y - zp * bump.z;
}

Vec3 perturb_entries(const scene::Normal& nrm, const Vec3& local, const Vec3& n_in,
                     const PatternContext& ctx, const TextureCache* textures) {
    const scene::PatternParams& pp = nrm.params;
    const double value = evaluate_pattern(nrm.kind, pp, local, ctx);
    Vec3 n = warp_normal(Transform(), pp, n_in);
    const Vec3 tp = pp.warps.empty() ? local : warp_point(nrm.kind, pp, local);
    Vec3 out;
    if (!nrm.entries.empty()) {
        out = perturb(nrm.entries[block_index(value, nrm.entries.size())], tp, n, ctx, textures);
    } else {
        const auto& map = nrm.normal_map;
        BlendPick b = search_blend_map(map, value);
        out = perturb(map[b.cur].normal[0], tp, n, ctx, textures);
        if (b.prev != b.cur) {
            Vec3 prev = perturb(map[b.prev].normal[0], tp, n, ctx, textures);
            out = prev * (1.0 - b.fraction) + out * b.fraction;
        }
    }
    return unwarp_normal(Transform(), pp, out);
}

// Perturb_Normal at `point` (the parent's pattern space); `n_in` is in that space too.
Vec3 perturb(const scene::Normal& nrm, const Vec3& point, const Vec3& n_in,
             const PatternContext& ctx, const TextureCache* textures) {
    if (nrm.kind == PatternKind::Plain) return n_in;
    const scene::PatternParams& pp = nrm.params;
    const Vec3 local = nrm.transform.is_identity() ? point : nrm.transform.inverse_point(point);
    if (nrm.kind != PatternKind::Average && (!nrm.normal_map.empty() || !nrm.entries.empty())) {
        // The entries see the normal in this pattern's space.
        Vec3 n = safe_normalize(nrm.transform.is_identity() ? n_in
                                                            : nrm.transform.inverse().normal(n_in));
        n = perturb_entries(nrm, local, n, ctx, textures);
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
            sum += perturb(e.normal[0], tp, n, ctx, textures) * e.value;
            total += e.value;
        }
        return unwarp_normal(nrm.transform, pp, sum / total);
    }
    if (nrm.kind == PatternKind::ImageMap) {
        Vec3 n = warp_normal(nrm.transform, pp, n_in);
        const Vec3 tp = pp.warps.empty() ? local : warp_point(nrm.kind, pp, local);
        return unwarp_normal(nrm.transform, pp, bump_map(nrm, tp, n, textures));
    }
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
                    const PatternContext& ctx, const TextureCache* textures) {
    if (normal.kind == PatternKind::Plain) return n;
    Vec3 p = at.p;
    if (normal.uv_mapping) p = uv_mapped(at);
    return perturb(normal, p, n, ctx, textures);
}

}  // namespace glint::render
