// POV-Ray's area_light shadows (trace.cpp TraceAreaLightShadowRay and
// TraceAreaLightSubsetShadowRay): a size1 x size2 grid of point samples spanning axis1 x axis2
// around the light centre, sampled at the grid's corners and subdivided where the corners
// disagree (or down to the `adaptive` level), then averaged region by region.
#pragma once

#include <functional>

#include "render/lights/light.h"

namespace glint::render {

// Filtered light arriving at the shading point along `dir` from a sample `depth` away:
// `light` times whatever the objects in between let through.
using PointShadowFn = std::function<Color(const Vec3& dir, double depth, const Color& light)>;

// The light reaching `p` from an area light whose centre-attenuated color is `light_color`.
// Jitter is not applied (POV-Ray's jitter draws random numbers); the caller warns about it.
Color area_light_shadow(const PreparedLight& light, const Vec3& p, const Color& light_color,
                        const PointShadowFn& shadow);

}  // namespace glint::render
