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

// Bit-level steps (pbrt-v4 NextFloatUp/Down): inline, unlike std::nextafter, because the BVH
// traversal calls them per primitive. NaN and the infinity in the stepping direction stay put.
inline double next_up(double v) {
    if (std::isnan(v) || v == kInfinity) return v;
    if (v == 0) v = 0.0;  // -0 steps to the smallest positive value too
    uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    u = v >= 0 ? u + 1 : u - 1;
    std::memcpy(&v, &u, sizeof v);
    return v;
}
inline double next_down(double v) {
    if (std::isnan(v) || v == -kInfinity) return v;
    if (v == 0) v = -0.0;
    uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    u = v > 0 ? u - 1 : u + 1;
    std::memcpy(&v, &u, sizeof v);
    return v;
}

// The nearest floats at or below / at or above a double (beyond the float range: the largest
// float, or an infinity), so that float boxes and bounds enclose double values. Branch-free
// (the float box test's ray set-up calls them per ray, on values that round either way): the
// rounded float's bits step one towards the double where rounding went past it. Stepping the
// bits of +-0, +-inf and the largest float gives the right neighbour; NaN stays NaN.
inline float float_up(double v) {
    float f = static_cast<float>(v);
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    const uint32_t step = static_cast<double>(f) < v;
    const uint32_t neg = 0u - static_cast<uint32_t>(std::signbit(f));  // all ones if negative
    u += (step ^ neg) - neg;                                            // -step if negative
    std::memcpy(&f, &u, sizeof f);
    return f;
}
inline float float_down(double v) {
    float f = static_cast<float>(v);
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    const uint32_t step = static_cast<double>(f) > v;
    const uint32_t pos = static_cast<uint32_t>(std::signbit(f)) - 1u;  // all ones if positive
    u += (step ^ pos) - pos;                                           // -step if positive
    std::memcpy(&f, &u, sizeof f);
    return f;
}

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
