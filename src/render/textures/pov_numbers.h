// POV-Ray's constants and integer conversion as its pattern and warp code use them (pattern.cpp,
// warp.cpp): spelled as POV-Ray spells them, so that results match to the last bit.
#pragma once

#include <cstdint>

namespace glint::render::pov_numbers {

constexpr double kTwoPi = 6.283185307179586476925286766560;
constexpr double kHalfPi = 1.57079632679489661923;
constexpr double kSqrt3 = 1.7320508075688772935274463415059;
constexpr double kSqrt3Half = 0.86602540378443864676372317075294;

// POV-Ray's (int) casts of cell coordinates; x86 turns an out-of-range or NaN value into
// INT_MIN, which C++ leaves undefined, so that case is spelled out.
inline int pov_int(double v) {
    if (!(v > -2147483649.0 && v < 2147483648.0)) return INT32_MIN;
    return static_cast<int>(v);
}

}  // namespace glint::render::pov_numbers
