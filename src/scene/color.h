// POV-Ray colors carry two transparency channels beside RGB: filter (light passes tinted by
// the color) and transmit (light passes untinted). Every pigment evaluates to a ColorFT.
#pragma once

#include "core/math.h"

namespace glint::scene {

struct ColorFT {
    Color rgb;
    double filter = 0;
    double transmit = 0;

    constexpr ColorFT() = default;
    constexpr ColorFT(Color c, double f = 0, double t = 0) : rgb(c), filter(f), transmit(t) {}
    constexpr bool operator==(const ColorFT&) const = default;

    constexpr ColorFT operator+(const ColorFT& o) const {
        return {rgb + o.rgb, filter + o.filter, transmit + o.transmit};
    }
    constexpr ColorFT operator*(double s) const { return {rgb * s, filter * s, transmit * s}; }
    // Fraction of light that passes through at all.
    constexpr double transparency() const { return filter + transmit; }
    bool opaque() const { return filter == 0 && transmit == 0; }
};

// Linear interpolation used by color maps and block patterns: a + (b - a) * t on all five
// channels, in that form (not a * (1 - t) + b * t) as POV-Ray's Compute_Pigment blends.
constexpr ColorFT lerp(const ColorFT& a, const ColorFT& b, double t) {
    return a + (b + a * -1.0) * t;
}

}  // namespace glint::scene
