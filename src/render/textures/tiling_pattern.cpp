// The tilings are folded onto one fundamental piece by the plane's symmetries (translations,
// then mirrors), and the value is the distance to the nearest tile edge scaled so that the
// edge is 1. The arithmetic follows POV-Ray's order so the edges fall on the same pixels.
#include "render/textures/tiling_pattern.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace glint::render {
namespace {

constexpr double kSqrt3 = 1.7320508075688772935274463415059;
constexpr double kHalfSqrt3 = 0.86602540378443864676372317075294;

// |v| folded into [0, 1): 0 at a tile's middle, 1 at its edge.
double fold_unit(double v) {
    double t = std::fabs(v);
    t -= std::floor(t);
    return 2 * std::fabs(t - 0.5);
}

// tiling 1: unit squares.
double squares(const Vec3& p) { return std::max(fold_unit(p.x), fold_unit(p.z)); }

// tiling 2: hexagons with unit edges, one centred at x = 1, z = sqrt(3)/2.
double hexagons(const Vec3& p) {
    double x = p.x + 0.5;
    x -= 3.0 * std::floor(x / 3.0);
    double z = p.z - kSqrt3 * std::floor(p.z / kSqrt3);
    if (z > kHalfSqrt3) z = kSqrt3 - z;
    if (x > 1.5) {
        x -= 1.5;
        z = kHalfSqrt3 - z;
    }
    if (kSqrt3 * x + z < kHalfSqrt3) {  // the corner of the neighbouring hexagon
        x = 0.5 - x;
        z = kHalfSqrt3 - z;
    }
    if (x > 1.0) x = 2.0 - x;
    const double across = 1.0 - z / kHalfSqrt3;
    const double slanted = 1.0 - (kSqrt3 * x + z - kHalfSqrt3) / kSqrt3;
    return std::clamp(std::max(across, slanted), 0.0, 1.0);
}

// tiling 3: equilateral triangles with unit edges, pointing up in [0, 0.5) and down in
// [0.5, 1).
double triangles(const Vec3& p) {
    double x = p.x - std::floor(p.x);
    double z = p.z - kSqrt3 * std::floor(p.z / kSqrt3);
    int flipped = 0;
    if (z > kHalfSqrt3) {
        z = kSqrt3 - z;
        flipped = 1 - flipped;
    }
    if (x > 0.5) x = 1.0 - x;
    if (x == 0.0) {  // POV-Ray mirrors this line without counting it as the other triangle
        z = kHalfSqrt3 - z;
        x = 0.5;
    } else if (z / x > kSqrt3) {  // beyond the slanted edge: the other triangle
        z = kHalfSqrt3 - z;
        x = 0.5 - x;
        flipped = 1 - flipped;
    }
    const double base = 1.0 - z * 2 * kSqrt3;
    const double side = 1.0 - (kSqrt3 * x - z) * kSqrt3;
    return flipped / 2.0 + 0.5 * std::max(base, side);
}

// The lozenge of tilings 4 and 5, from its folded piece x in [-0.25, 0.75], z in [0, sqrt3/4].
double lozenge_value(double x, double z) {
    if (2.0 * z > kHalfSqrt3) {
        z = kHalfSqrt3 - z;
        x = 1.5 - x;
    }
    if (x > 0.75) x -= 1.0;
    if (x != 0.0 && z / x > kSqrt3) {
        z = kHalfSqrt3 - z;
        x = 0.5 - x;
    }
    const double base = 1.0 - z * 4.0 * kSqrt3 / 3.0;
    const double side = 1.0 - std::fabs(kSqrt3 * x - z) * kSqrt3 * 2.0 / 3.0;
    return std::max(base, side);
}

// tiling 4: lozenges (rhombi of 60 degrees), all in one orientation.
double lozenges(const Vec3& p) {
    double x = p.x - std::floor(p.x);
    double z = p.z - kSqrt3 * std::floor(p.z / kSqrt3);
    if (z > kHalfSqrt3) {
        z -= kHalfSqrt3;
        x += 0.5;
    }
    return lozenge_value(x, z);
}

// tiling 5: lozenges in three orientations (a tumbling-blocks pattern), each orientation its
// own third of [0, 1].
double rhombi(const Vec3& p) {
    double x = p.x + 0.5;
    x -= 3.0 * std::floor(x / 3.0);
    double z = p.z - kSqrt3 * std::floor(p.z / kSqrt3);
    int third = 0;  // which orientation: 0, 1 or 2
    if (z > kHalfSqrt3) {
        z = kSqrt3 - z;
        third = 2 - third;
    }
    if (x > 1.5) {
        x -= 1.5;
        z = kHalfSqrt3 - z;
        third = 2 - third;
    }
    if (x < 0.5) {
        x = 1.0 - x;
        third = 2 - third;
    }
    x -= 0.5;
    if (x == 0.0 || z / x > kSqrt3) {
        // the upright lozenge: rotated by -60 degrees onto the horizontal one
        const double rx = x / 2.0 + z * kHalfSqrt3;
        const double rz = z / 2.0 - x * kHalfSqrt3;
        x = rx;
        z = rz;
        third = 1;
    }
    double v = lozenge_value(x, z) / 3.0 + third / 3.0;
    return std::clamp(v, 0.0, 1.0);
}

// tiling 6: 2x1 rectangles in a basket weave. The 4x4 cell is cut into unit squares; each
// names the offset that brings its rectangle's half onto the unit square at the origin and
// whether the rectangle lies along x (value band [0.5, 1]) or along z ([0, 0.5]).
double rectangles(const Vec3& p) {
    struct Half {
        double dx, dz;
        bool along_x;
    };
    static constexpr Half kHalves[16] = {
        {0, 1, true},  {2, 0, false}, {2, 0, false}, {3, 0, true},
        {0, 1, true},  {1, 2, true},  {3, 1, false}, {3, 1, false},
        {0, 2, false}, {1, 2, true},  {2, 3, true},  {4, 2, false},
        {1, 3, false}, {1, 3, false}, {2, 3, true},  {3, 4, true}};
    double x = p.x - 4.0 * std::floor(p.x / 4.0);
    double z = p.z - 4.0 * std::floor(p.z / 4.0);
    const int cell = static_cast<int>(x) + static_cast<int>(z) * 4;
    // x or z can round up to 4: such a point keeps its place, along x, as in POV-Ray
    const Half h = cell >= 0 && cell < 16 ? kHalves[cell] : Half{0, 0, true};
    x -= h.dx;
    z -= h.dz;
    double ex, ez;
    if (h.along_x) {
        ex = 2 * std::fabs(x - 0.5);
        ez = 2 * (std::max(std::fabs(z), 0.5) - 0.5);
    } else {
        ex = 2 * (std::max(std::fabs(x), 0.5) - 0.5);
        ez = 2 * std::fabs(z - 0.5);
    }
    return std::fabs(std::max(ex, ez) / 2.0 + (h.along_x ? 1.0 : 0.0) / 2);
}

// tiling 7: octagons with small squares between them; squares in [0, 0.5), octagons above.
double octagons_squares(const Vec3& p) {
    constexpr double kSqrt2 = 1.4142135623730950488016887242097;
    constexpr double kHalfSqrt2 = 0.70710678118654752440084436210485;
    constexpr double kPeriod = kSqrt2 + 1.0;
    auto fold = [](double v) {
        v -= kPeriod * std::floor(v / kPeriod);
        return std::fabs(v - (kHalfSqrt2 + 0.5));
    };
    double z = fold(p.z);
    double x = fold(p.x);
    if (z > x) std::swap(x, z);
    if (x + z < kHalfSqrt2) return (x + z) / kSqrt2;  // a square
    const double straight = 1.0 - z;
    const double diagonal = (kSqrt2 + kHalfSqrt2 - (x + z)) / kSqrt2;
    // POV-Ray keeps octagons just above one half
    return std::max(0.500000000001, std::max(straight, diagonal));
}

// tiling 10: unit squares, every other row shifted by half a square.
double squares_offset(const Vec3& p) {
    double z = p.z - 2.0 * std::floor(p.z / 2.0);
    double x = p.x;
    if (z > 1.0) {
        x += 0.5;
        z -= 1.0;
    }
    x -= std::floor(x);
    return std::max(2 * std::fabs(x - 0.5), 2 * std::fabs(z - 0.5));
}

}  // namespace

double tiling(int type, const Vec3& p) {
    switch (type) {
        case 2: return hexagons(p);
        case 3: return triangles(p);
        case 4: return lozenges(p);
        case 5: return rhombi(p);
        case 6: return rectangles(p);
        case 7: return octagons_squares(p);
        case 10: return squares_offset(p);
        default: return squares(p);
    }
}

}  // namespace glint::render
