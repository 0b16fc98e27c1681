// The watertight ray/triangle test (Woop, Benthin, Wald 2013, "Watertight Ray/Triangle
// Intersection", JCGT 2(1)), shared by triangle, smooth_triangle and meshes. Edges shared by
// two triangles are evaluated identically from both sides, so no ray slips between them.
#pragma once

#include "core/float.h"
#include "core/math.h"
#include "render/ray.h"

namespace glint::render {

struct TriangleHit {
    double t;
    double b[3];  // barycentrics of p0, p1, p2, each in [0, 1], summing to 1
};

// The ray's shear, computed once per ray (the paper's kx, ky, kz and Sx, Sy, Sz).
struct RayShear {
    explicit RayShear(const Ray& ray);
    Vec3 origin;
    int kx, ky, kz;
    double sx, sy, sz;
};

// Hit with 0 < t < tmax; t must also exceed its rounding error bound (pbrt-v4, 6.8.4), so a
// ray leaving the triangle's plane does not re-hit it.
bool intersect_triangle(const RayShear& s, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                        double tmax, TriangleHit* hit);

// The hit point from barycentrics and its error bound (pbrt-v4: gamma(7) of the abs sum).
inline Vec3 triangle_point(const Vec3& p0, const Vec3& p1, const Vec3& p2, const double b[3],
                           Vec3* error);

inline Vec3 triangle_point(const Vec3& p0, const Vec3& p1, const Vec3& p2, const double b[3],
                           Vec3* error) {
    Vec3 a = abs(p0 * b[0]) + abs(p1 * b[1]) + abs(p2 * b[2]);
    *error = a * gamma(7);
    return p0 * b[0] + p1 * b[1] + p2 * b[2];
}

}  // namespace glint::render
