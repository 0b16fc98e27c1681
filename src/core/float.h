// Floating-point helpers for rounding-error bounds (pbrt-v4, "Managing Rounding Error"):
// gamma(n) bounds the relative error of n successive IEEE operations; next_up/next_down step
// one ulp; offset_ray_origin moves a hit point off its surface by its error bound, so
// secondary rays never re-hit the surface they leave, at any scene scale.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/math.h"

namespace glint {

constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon() * 0.5;

constexpr double gamma(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

inline double next_up(double v) { return std::nextafter(v, kInfinity); }
inline double next_down(double v) { return std::nextafter(v, -kInfinity); }

// Moves `p` (with absolute error bound `p_error`) off the surface with geometric normal `n`,
// to the side `w` points to.
inline Vec3 offset_ray_origin(const Vec3& p, const Vec3& p_error, const Vec3& n, const Vec3& w) {
    Vec3 an = abs(n);
    double d = dot(an, p_error);
    Vec3 offset = n * d;
    if (dot(w, n) < 0) offset = -offset;
    Vec3 po = p + offset;
    // Round away from p so the offset is not lost to rounding.
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0) po[i] = next_up(po[i]);
        else if (offset[i] < 0) po[i] = next_down(po[i]);
    }
    return po;
}

}  // namespace glint
