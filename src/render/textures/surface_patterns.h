// Patterns that read more than the point: slope (the surface normal, PatternContext::normal),
// aoi, pigment_pattern (a whole pigment evaluated at the point) and image_pattern (an image,
// PatternContext::textures). Called by evaluate_pattern.
#pragma once

#include "render/textures/pattern.h"

namespace glint::render {

// POV-Ray's slope_pattern; 0 where the context has no surface normal.
double slope_pattern(const scene::SlopeParams& s, const Vec3& p, const PatternContext& ctx);
// POV-Ray's aoi_pattern: the angle between the surface normal facing the ray and the ray's
// direction, over pi (0.5 to 1 on a surface seen from its front); 0 where the context has
// no normal or ray.
double aoi_pattern(const PatternContext& ctx);
// POV-Ray's pigment_pattern: params.pigment's grey at p, 0 where it has no color.
// imageutil.cpp image_pattern: the image (mapped as an image_map) at the point: its grey, or
// under use_alpha its transmit (red without alpha), within 0..1; 0 off an image used once.
double image_pattern(const scene::PatternParams& params, const Vec3& p, const PatternContext& ctx);
double pigment_pattern(const scene::PatternParams& params, const Vec3& p,
                       const PatternContext& ctx);

}  // namespace glint::render
