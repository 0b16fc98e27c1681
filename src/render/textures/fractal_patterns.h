// POV-Ray's mandel, julia and magnet patterns (fractal.cpp in POV-Ray 3.7): exponent 2, 3 and 4
// written out, 5 to 33 through binomial expansion; the exterior and interior types colour
// the escape and the orbit. Called by evaluate_pattern (pattern.cpp).
#pragma once

#include "core/math.h"
#include "scene/texture.h"

namespace glint::render {

// POV-Ray's FRACTAL_MAX_EXPONENT: its parser clamps the exponent to 2..33.
constexpr int kMaxFractalExponent = 33;

double fractal2(const scene::PatternParams& params, const Vec3& p, bool julia);
double fractal34(const scene::PatternParams& params, const Vec3& p, bool julia, int exponent);
double fractalx(const scene::PatternParams& params, const Vec3& p, bool julia, int exponent);
// magnet 1|2 mandel|julia (PatternParams::magnet_type, magnet_julia).
double magnet(const scene::PatternParams& params, const Vec3& p);

}  // namespace glint::render
