#include "render/textures/surface_patterns.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/textures/image_texture.h"
#include "render/textures/pigment.h"

namespace glint::render {

double aoi_pattern(const PatternContext& ctx) {
    if (!ctx.normal || !ctx.ray_dir) return 0.0;
    const double la = length(*ctx.normal), lb = length(*ctx.ray_dir);
    if (!(la > 0) || !(lb > 0)) return 0.0;
    return std::acos(std::clamp(dot(*ctx.normal, *ctx.ray_dir) / (la * lb), -1.0, 1.0)) / kPi;
}

// POV-Ray's slope_pattern: the normal's angle against the slope vector (or towards a point)
// mapped to 0..1, optionally mixed with the point's height along the altitude vector.
double slope_pattern(const scene::SlopeParams& s, const Vec3& p, const PatternContext& ctx) {
    if (!ctx.normal) return 0.0;
    const Vec3& n = *ctx.normal;
    double v1;
    if (s.point_at) {
        v1 = dot(n, normalize(s.vector - p));
    } else if (s.base > 0) {
        v1 = n[s.base - 1];
    } else if (s.base < 0) {
        v1 = -n[-s.base - 1];
    } else {
        v1 = dot(n, s.vector);
    }
    v1 = std::clamp(v1, -1.0, 1.0);
    v1 = (std::asin(v1) / kPi * 2 + 1.0) * 0.5;
    if (s.span != 0.0) v1 = (v1 - s.lo) / s.span;
    if (s.altitude_weight == 0.0) {
        if (v1 == 1.0) return v1 - kPovEpsilon;
        return v1 < 0.0 ? 1.0 + std::fmod(v1, 1.0) : std::fmod(v1, 1.0);
    }
    double v2;
    if (s.altitude_base > 0) {
        v2 = p[s.altitude_base - 1];
    } else if (s.altitude_base < 0) {
        v2 = -p[-s.altitude_base - 1];
    } else {
        v2 = dot(p, s.altitude);
    }
    if (s.altitude_span != 0.0) v2 = (v2 - s.altitude_lo) / s.altitude_span;
    double v = s.weight * v1 + s.altitude_weight * v2;
    if (v - 1.0 < kPovEpsilon && v >= 1.0) return v - kPovEpsilon;
    return v < 0.0 ? 1.0 + std::fmod(v, 1.0) : std::fmod(v, 1.0);
}

double image_pattern(const scene::PatternParams& params, const Vec3& p, const PatternContext& ctx) {
    const scene::ImageMap& im = params.image;
    const ImageTexture* image = ctx.textures ? ctx.textures->find(im) : nullptr;
    if (!image) throw Error(ErrorKind::Render, im.loc, "image '" + im.file + "' was not loaded");
    double xc, yc;
    if (!image_map_position(im, *image, p, &xc, &yc)) return 0.0;
    const scene::ColorFT c = image_map_sample(im, *image, xc, yc);
    const double v = !im.use_alpha ? 0.297 * c.rgb.r + 0.589 * c.rgb.g + 0.114 * c.rgb.b
                     : image->has_alpha() ? c.transmit
                                          : c.rgb.r;
    return std::clamp(v, 0.0, 1.0);
}

double pigment_pattern(const scene::PatternParams& params, const Vec3& p,
                       const PatternContext& ctx) {
    scene::ColorFT c;
    if (!params.pigment ||
        !PigmentEvaluator(ctx.textures, ctx).evaluate(*params.pigment, {p, {}, false}, &c))
        return 0.0;
    return 0.297 * c.rgb.r + 0.589 * c.rgb.g + 0.114 * c.rgb.b;
}

}  // namespace glint::render
