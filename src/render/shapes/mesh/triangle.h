// The watertight ray/triangle test (Woop, Benthin, Wald 2013, "Watertight Ray/Triangle
// Intersection", JCGT 2(1)), shared by triangle, smooth_triangle and meshes. Edges shared by
// two triangles are evaluated identically from both sides, so no ray slips between them.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/float.h"
#include "core/math.h"
#include "render/ray.h"

namespace glint::render {

struct TriangleHit {
    double t;
    double b[3];  // barycentrics of p0, p1, p2, each in [0, 1], summing to 1
};

// The ray's shear, computed once per ray (the paper's kx, ky, kz and Sx, Sy, Sz).
// Inline: meshes build one per ray per query, and small meshes (an OBJ's parts) are many.
struct RayShear {
    explicit RayShear(const Ray& ray) : origin(ray.origin) {
        const double ax = std::fabs(ray.dir.x), ay = std::fabs(ray.dir.y),
                     az = std::fabs(ray.dir.z);
        kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        static constexpr int kNext[3] = {1, 2, 0}, kAfter[3] = {2, 0, 1};
        kx = kNext[kz];
        ky = kAfter[kz];
        // Keep the winding: swapping x and y when looking down -kz.
        const double dz = ray.dir[kz];
        if (dz < 0) std::swap(kx, ky);
        sz = 1.0 / dz;
        sx = ray.dir[kx] * sz;
        sy = ray.dir[ky] * sz;
    }
    Vec3 origin;
    int kx, ky, kz;
    double sx, sy, sz;
};

// Hit with 0 < t < tmax; t must also exceed its rounding error bound (pbrt-v4, 6.8.4), so a
// ray leaving the triangle's plane does not re-hit it.
inline bool intersect_triangle(const RayShear& s, const Vec3& p0, const Vec3& p1, const Vec3& p2,
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

// Inline so that mesh loops keep their per-ray values in registers.
inline bool intersect_triangle(const RayShear& s, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                        double tmax, TriangleHit* hit) {
    if (!std::isfinite(s.sz)) return false;  // zero direction
    // The vertices relative to the origin as plain arrays: indexing them by kx, ky, kz is a
    // load, where Vec3::operator[] branches.
    const Vec3 da = p0 - s.origin, db = p1 - s.origin, dc = p2 - s.origin;
    const double a[3] = {da.x, da.y, da.z}, b[3] = {db.x, db.y, db.z}, c[3] = {dc.x, dc.y, dc.z};
    double ax = a[s.kx] - s.sx * a[s.kz], ay = a[s.ky] - s.sy * a[s.kz];
    double bx = b[s.kx] - s.sx * b[s.kz], by = b[s.ky] - s.sy * b[s.kz];
    double cx = c[s.kx] - s.sx * c[s.kz], cy = c[s.ky] - s.sy * c[s.kz];
    // Edge functions (2D cross products in the sheared frame).
    double u = cx * by - cy * bx;
    double v = ax * cy - ay * cx;
    double w = bx * ay - by * ax;
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
    double det = u + v + w;
    if (det == 0 || !std::isfinite(det)) return false;
    double az = s.sz * a[s.kz], bz = s.sz * b[s.kz], cz = s.sz * c[s.kz];
    double t_scaled = u * az + v * bz + w * cz;
    if (det < 0 ? (t_scaled >= 0 || t_scaled < tmax * det) : (t_scaled <= 0 || t_scaled > tmax * det))
        return false;
    double inv = 1.0 / det;
    double t = t_scaled * inv;
    if (!(t < tmax)) return false;
    // Conservative bound on t's rounding error (pbrt-v4, 6.8.4 "Conservative ray-triangle t").
    double max_z = std::max({std::fabs(az), std::fabs(bz), std::fabs(cz)});
    double max_x = std::max({std::fabs(ax), std::fabs(bx), std::fabs(cx)});
    double max_y = std::max({std::fabs(ay), std::fabs(by), std::fabs(cy)});
    double dz = gamma(3) * max_z;
    double dx = gamma(5) * (max_x + max_z);
    double dy = gamma(5) * (max_y + max_z);
    // Symmetric in x and y (max_x * max_y first), so a mirrored mesh and ray (which may swap
    // the sheared x and y) get the same bound bit for bit (mesh_prim.h, bake_exact).
    double de = 2 * (gamma(2) * (max_x * max_y) + dy * max_x + dx * max_y);
    double max_e = std::max({std::fabs(u), std::fabs(v), std::fabs(w)});
    double dt = 3 * (gamma(3) * max_e * max_z + de * max_z + dz * max_e) * std::fabs(inv);
    if (t <= dt) return false;
    hit->t = t;
    hit->b[0] = u * inv;
    hit->b[1] = v * inv;
    hit->b[2] = w * inv;
    return true;
}

}  // namespace glint::render
