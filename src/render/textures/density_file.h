// POV-Ray's density_file pattern (density_pattern in POV-Ray 3.7's pattern.cpp): a df3 grid
// over [0, 1)^3, 0 outside; nearest voxel, trilinear (neighbours wrapping around) or
// POV-Ray's tricubic, in single precision. Called by evaluate_pattern (pattern.cpp).
#pragma once

#include "core/math.h"
#include "scene/texture.h"

namespace glint::render {

double density_file(const scene::PatternParams& params, const Vec3& p);

}  // namespace glint::render
