// POV-Ray's tiling pattern (pattern.cpp tiling_pattern in POV-Ray 3.7): the x-z plane filled
// with regular tiles. Called by evaluate_pattern (pattern.cpp).
#pragma once

#include "core/math.h"

namespace glint::render {

// The value at p of tiling `type`: with one kind of tile, 0 deep inside a tile rising to 1 at
// its edge; with several kinds, each kind has its own band of [0, 1]. Tilings 1 to 7 and 10;
// the others (which the parser warns about) are drawn as tiling 1.
double tiling(int type, const Vec3& p);

}  // namespace glint::render
