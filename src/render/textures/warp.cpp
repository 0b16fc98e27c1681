// POV-Ray 3.7's warps (backend/pattern/warps.cpp, Warp_EPoint): turbulence, transforms, repeat,
// black hole and the cylindrical, spherical, toroidal, planar and cubic mappings, applied in
// list order to a pattern-space point (warp_point in pattern.h), in POV-Ray's arithmetic.
#include <algorithm>
#include <cmath>

#include "core/noise.h"
#include "render/textures/pattern.h"
#include "render/textures/pov_numbers.h"

namespace glint::render {
namespace {

using scene::PatternKind;
using scene::PatternParams;
using scene::Warp;
using scene::WarpKind;

using pov_numbers::kTwoPi;
using pov_numbers::pov_int;
// Warp_EPoint clamps warped coordinates to this magnitude.
constexpr double kCoordinateLimit = 1.0e17;

// The orientation rotation shared by the cylindrical, spherical, toroidal and planar warps:
// (x, y, z) are the warp's own coordinates, placed so that the warp's z axis follows `o`.
Vec3 orient(const Vec3& o, double x, double y, double z) {
    if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0) return {x, y, z};
    return {o.x * z + o.y * x + o.z * x, o.x * y + o.y * -z + o.z * y,
            o.x * -x + o.y * y + o.z * z};
}

// Angle of (x, z) from +x in [0, 2 pi), POV-Ray's acos form.
double angle_xz(double x, double z, double len) {
    if (z == 0.0) return x > 0 ? 0.0 : kPi;
    double theta = std::acos(x / len);
    return z < 0.0 ? kTwoPi - theta : theta;
}

Vec3 warp_cylindrical(const Warp& w, const Vec3& p) {
    double len = std::sqrt(p.x * p.x + p.z * p.z);
    if (len == 0.0) return p;
    double theta = angle_xz(p.x, p.z, len) / kTwoPi;
    if (w.dist_exp == 1.0) {
        theta *= len;
    } else if (w.dist_exp != 0.0) {
        theta *= std::pow(len, w.dist_exp);
    }
    return orient(w.orientation, theta, p.y, len);
}

Vec3 warp_spherical(const Warp& w, const Vec3& p) {
    double dist = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    if (dist == 0.0) return p;
    double x = p.x / dist, y = p.y / dist, z = p.z / dist;
    double phi = 0.5 + std::asin(y) / kPi;
    double len = std::sqrt(x * x + z * z);
    double theta = len == 0.0 ? 0.0 : angle_xz(x, z, len) / kTwoPi;
    if (w.dist_exp == 1.0) {
        theta *= dist;
        phi *= dist;
    } else if (w.dist_exp != 0.0) {
        double f = std::pow(dist, w.dist_exp);
        theta *= f;
        phi *= f;
    }
    return orient(w.orientation, theta, phi, dist);
}

Vec3 warp_toroidal(const Warp& w, const Vec3& p) {
    double len = std::sqrt(p.x * p.x + p.z * p.z);
    if (len == 0.0) return p;
    double theta = 0.0 - angle_xz(p.x, p.z, len);
    double x = len - w.major_radius;
    len = std::sqrt(x * x + p.y * p.y);
    double phi = std::acos(-x / len);
    if (p.y > 0.0) phi = kTwoPi - phi;
    theta /= -kTwoPi;
    phi /= kTwoPi;
    if (w.dist_exp == 1.0) {
        theta *= len;
        phi *= len;
    } else if (w.dist_exp != 0.0) {
        double f = std::pow(len, w.dist_exp);
        theta *= f;
        phi *= f;
    }
    return orient(w.orientation, theta, phi, len);
}

Vec3 warp_cubic(const Vec3& p) {
    double x = p.x, y = p.y, z = p.z;
    const double ax = std::fabs(x), ay = std::fabs(y), az = std::fabs(z);
    constexpr double kThird = 1.0 / 3.0;
    if (x >= 0 && x >= ay && x >= az)
        return {0.75 - 0.25 * (z / x + 1.0) / 2.0, kThird + kThird * (y / x + 1.0) / 2.0, x};
    if (y >= 0 && y >= ax && y >= az)
        return {0.25 + 0.25 * (x / y + 1.0) / 2.0, 1.0 - kThird * (z / y + 1.0) / 2.0, y};
    if (z >= 0 && z >= ax && z >= ay)
        return {0.25 + 0.25 * (x / z + 1.0) / 2.0, kThird + kThird * (y / z + 1.0) / 2.0, z};
    if (x < 0 && x <= -ay && x <= -az) {
        x = -x;
        return {0.25 * (z / x + 1.0) / 2.0, kThird + kThird * (y / x + 1.0) / 2.0, x};
    }
    if (y < 0 && y <= -ax && y <= -az) {
        y = -y;
        return {0.25 + 0.25 * (x / y + 1.0) / 2.0, kThird * (z / y + 1.0) / 2.0, y};
    }
    z = -z;
    return {1.0 - 0.25 * (x / z + 1.0) / 2.0, kThird + kThird * (y / z + 1.0) / 2.0, z};
}

Vec3 warp_repeat(const Warp& w, const Vec3& p) {
    // The direction has one non-zero component: its axis and the repeat width.
    int axis = w.direction.x != 0.0 ? 0 : (w.direction.y != 0.0 ? 1 : 2);
    double width = w.direction[axis];
    if (width == 0.0) return p;
    // POV-Ray keeps the block number in single precision (SNGL).
    float block = static_cast<float>(std::floor(p[axis] / width));
    Vec3 r = p;
    r[axis] = p[axis] - block * width;
    if (pov_int(block) & 1) {
        // A non-zero flip component mirrors that axis in odd blocks.
        Vec3 flip(w.flip.x != 0.0 ? -1.0 : 1.0, w.flip.y != 0.0 ? -1.0 : 1.0,
                  w.flip.z != 0.0 ? -1.0 : 1.0);
        r = r * flip;
        if (flip[axis] < 0) r[axis] = width + r[axis];
    }
    return r + w.offset * static_cast<double>(block);
}

Vec3 warp_black_hole(const Warp& w, const Vec3& p) {
    Vec3 center = w.center;
    const bool repeat = w.repeat != Vec3(0, 0, 0);
    const Vec3& uncertainty = w.turbulence.amount;  // black_hole's `turbulence <v>`
    if (repeat) {
        // POV-Ray's parser (Check_BH_Parameters) keeps each repeated hole inside its cell: the
        // centre moves to at least the radius and the repeat grows to centre + radius +
        // uncertainty on every axis with a positive repeat.
        Vec3 cell = w.repeat;
        for (int k = 0; k < 3; ++k) {
            if (cell[k] <= 0.0) continue;
            if (center[k] < w.radius) center[k] = w.radius;
            cell[k] = std::max(cell[k], center[k] + w.radius + uncertainty[k]);
            if (cell[k] < kPovEpsilon) cell[k] = 0.0;
        }
        int block[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k)
            if (cell[k] >= kPovEpsilon) block[k] = pov_int(std::floor(p[k] / cell[k]));
        if (uncertainty != Vec3(0, 0, 0)) {
            unsigned seed = static_cast<unsigned>(hash3d(block[0], block[1], block[2]));
            for (int k = 0; k < 3; ++k) center[k] += pattern_random(seed + k) * uncertainty[k];
        }
        for (int k = 0; k < 3; ++k) center[k] += cell[k] * block[k];
    }
    Vec3 delta = p - center;
    double len = length(delta);
    if (len >= w.radius) return p;
    len = (w.radius - len) / w.radius;
    double strength = std::pow(len, w.falloff) * w.strength;
    if (strength > 1.0) strength = 1.0;
    return p + delta * (w.inverse ? -strength : strength);
}

}  // namespace

Vec3 warp_point(PatternKind kind, const PatternParams& params, const Vec3& p_in) {
    Vec3 p = p_in;
    for (const Warp& w : params.warps) {
        switch (w.kind) {
            case WarpKind::ClassicTurbulence:
                if (kind == PatternKind::Marble || kind == PatternKind::Wood) break;
                [[fallthrough]];
            case WarpKind::Turbulence: {
                Vec3 t = dturbulence(p, TurbulenceParams{w.turbulence.octaves, w.turbulence.omega, w.turbulence.lambda});
                p.x += t.x * w.turbulence.amount.x;
                p.y += t.y * w.turbulence.amount.y;
                p.z += t.z * w.turbulence.amount.z;
                break;
            }
            case WarpKind::Transform:
                p = w.transform.inverse_point(p);
                break;
            case WarpKind::Repeat:
                p = warp_repeat(w, p);
                break;
            case WarpKind::BlackHole:
                p = warp_black_hole(w, p);
                break;
            case WarpKind::Cylindrical:
                p = warp_cylindrical(w, p);
                break;
            case WarpKind::Spherical:
                p = warp_spherical(w, p);
                break;
            case WarpKind::Toroidal:
                p = warp_toroidal(w, p);
                break;
            case WarpKind::Planar:
                p = orient(w.orientation, p.x, p.y, w.planar_offset);
                break;
            case WarpKind::Cubic:
                p = warp_cubic(p);
                break;
        }
    }
    for (int k = 0; k < 3; ++k) p[k] = std::clamp(p[k], -kCoordinateLimit, kCoordinateLimit);
    return p;
}

}  // namespace glint::render
