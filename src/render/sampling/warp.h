// Small mappings from uniform numbers to directions, shared by the lights and the photon
// integrator.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/math.h"
#include "render/sampling/sampler.h"

namespace glint::render {

// Two unit vectors completing the unit vector n to an orthonormal frame.
inline void tangents(const Vec3& n, Vec3* a, Vec3* b) {
    *a = normalize(std::fabs(n.x) > 0.9 ? cross(n, Vec3(0, 1, 0)) : cross(n, Vec3(1, 0, 0)));
    *b = cross(n, *a);
}

// A uniformly distributed unit vector.
inline Vec3 uniform_sphere(Sample2 u) {
    const double z = 1 - 2 * u.u;
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = 2 * kPi * u.v;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// A unit vector around the unit `n` with density cos / pi.
inline Vec3 cosine_around(const Vec3& n, Sample2 u) {
    Vec3 a, b;
    tangents(n, &a, &b);
    const double r = std::sqrt(u.u), phi = 2 * kPi * u.v;
    const double z = std::sqrt(std::max(0.0, 1 - u.u));
    return normalize(a * (r * std::cos(phi)) + b * (r * std::sin(phi)) + n * z);
}

// A unit vector within the cone of directions whose cosine with the unit `axis` is at least
// `cos_min`, uniformly: density 1 / (2 pi (1 - cos_min)).
inline Vec3 uniform_cone_around(const Vec3& axis, double cos_min, Sample2 u) {
    Vec3 a, b;
    tangents(axis, &a, &b);
    const double z = cos_min + (1 - cos_min) * u.u;
    const double r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u.v;
    return normalize(a * (r * std::cos(phi)) + b * (r * std::sin(phi)) + axis * z);
}

}  // namespace glint::render
