// The contained_by of isosurfaces and parametrics (scene::Container) as POV-Ray's shapes use
// it: its bounds, and the stretch of a ray inside it (Box::Intersect / Sphere::Intersect).
#pragma once

#include <cmath>

#include "core/math.h"
#include "scene/shape.h"

namespace glint::render {

inline Bounds3 container_bounds(const scene::Container& c) {
    if (c.sphere) {
        const Vec3 r(c.radius, c.radius, c.radius);
        return {c.center - r, c.center + r};
    }
    return {c.corner1, c.corner2};
}

// The depths [t1, t2] of o + t d inside the container; false when the ray misses it or the
// stretch ends before POV-Ray's DEPTH_TOLERANCE. For a sphere `d` must be of unit length (as
// POV-Ray passes it); a box takes any `d`. `side1`/`side2` (may be null): the box face the
// ray enters/leaves by, 2 axis + 1 for the low face, 2 axis + 2 for the high one, 0 where
// it starts inside, and 0 for a sphere.
inline bool container_interval(const scene::Container& c, const Vec3& o, const Vec3& d,
                               double* t1, double* t2, int* side1 = nullptr,
                               int* side2 = nullptr) {
    constexpr double kEpsilon = 1e-10;        // POV-Ray's EPSILON
    constexpr double kBoundHuge = 2e10;       // BOUND_HUGE
    constexpr double kDepthTolerance = 1e-6;  // boxes.cpp DEPTH_TOLERANCE
    int smin = 0, smax = 0;
    if (c.sphere) {
        const Vec3 oc = c.center - o;
        const double oc2 = dot(oc, oc), closest = dot(oc, d), r2 = c.radius * c.radius;
        if (oc2 >= r2 && closest < kEpsilon) return false;
        const double half2 = r2 - oc2 + closest * closest;
        if (!(half2 > kEpsilon)) return false;
        const double half = std::sqrt(half2);
        *t1 = closest - half;
        *t2 = closest + half;
    } else {
        double tmin = 0, tmax = kBoundHuge;
        for (int i = 0; i < 3; ++i) {
            const double oi = o[i], di = d[i];
            const double lo = c.corner1[i], hi = c.corner2[i];
            if (di < -kEpsilon || di > kEpsilon) {
                const bool neg = di < 0;
                const double t_far = ((neg ? lo : hi) - oi) / di;
                const double t_near = ((neg ? hi : lo) - oi) / di;
                if (t_far < tmin) return false;
                if (t_far <= tmax) {
                    tmax = t_far;
                    smax = 2 * i + (neg ? 1 : 2);
                }
                if (t_near >= tmin) {
                    if (t_near > tmax) return false;
                    tmin = t_near;
                    smin = 2 * i + (neg ? 2 : 1);
                }
            } else if (oi < lo || oi > hi || std::isnan(oi)) {
                return false;
            }
        }
        if (tmax < kDepthTolerance) return false;
        *t1 = tmin;
        *t2 = tmax;
    }
    if (side1) *side1 = smin;
    if (side2) *side2 = smax;
    return true;
}

}  // namespace glint::render
