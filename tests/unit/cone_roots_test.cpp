// The cone and cylinder root finder is built twice, for any x86-64 and with FMA instructions
// (render/shapes/cone_roots.h): both must give the same roots to the bit, so that an image
// does not depend on the CPU it was rendered on. And the roots must be roots.
#include "render/shapes/cone_roots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace glint::render {
namespace {

struct Case {
    ConeShape cone;
    Ray ray;
};

// Rays aimed near the surface from all around: through it, grazing it, along its axis and
// along a generating line, from inside and outside, with lengths from 1e-3 to 1e3.
std::vector<Case> cases() {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    const ConeShape shapes[] = {{1, 1, false}, {1, 1, true},    {0.5, 0, false},
                                {0, 2, false}, {1, 0.25, true}, {1e-3, 1e-3, false}};
    std::vector<Case> out;
    for (const ConeShape& c : shapes) {
        for (int i = 0; i < 4000; ++i) {
            const double scale = std::pow(10.0, 3 * u(rng));
            const Vec3 origin(scale * u(rng), scale * u(rng), 0.5 + scale * u(rng));
            // A point on or near the surface to aim at.
            const double z = 0.5 + 0.6 * u(rng), phi = M_PI * u(rng);
            const double r = (c.r0 + (c.r1 - c.r0) * z) * (1 + 1e-6 * u(rng));
            Vec3 target(r * std::cos(phi), r * std::sin(phi), z);
            Vec3 dir = target - origin;
            if (i % 10 == 0) dir = Vec3(0, 0, u(rng) > 0 ? 1 : -1);  // along the axis
            if (i % 10 == 1) dir = Vec3(c.r1 - c.r0, 0, 1);          // along a side line
            out.push_back({c, Ray{origin, dir, kInfinity}});
        }
    }
    return out;
}

TEST(ConeRoots, BothBuildsGiveTheSameRootsBitForBit) {
    const ConeRootsFn fma = cone_roots_fma();
    if (!fma) GTEST_SKIP() << "this CPU has no FMA";
    const ConeRootsFn generic = cone_roots_generic();
    size_t roots = 0;
    for (const Case& k : cases()) {
        ConeRoot a[4], b[4];
        const int na = generic(k.cone, k.ray, kInfinity, a);
        const int nb = fma(k.cone, k.ray, kInfinity, b);
        ASSERT_EQ(na, nb);
        for (int i = 0; i < na; ++i) {
            ASSERT_EQ(a[i].part, b[i].part);
            ASSERT_EQ(std::memcmp(&a[i].t, &b[i].t, sizeof(double)), 0)
                << a[i].t << " against " << b[i].t;
        }
        roots += static_cast<size_t>(na);
    }
    EXPECT_GT(roots, 20000u);  // the rays do find the surface
}

TEST(ConeRoots, RootsLieOnTheSurface) {
    const ConeRootsFn roots = cone_roots();
    for (const Case& k : cases()) {
        ConeRoot out[4];
        const int n = roots(k.cone, k.ray, kInfinity, out);
        ASSERT_LE(n, 4);
        for (int i = 0; i < n; ++i) {
            const Vec3 p = k.ray.origin + k.ray.dir * out[i].t;
            const double scale = std::max({1.0, std::fabs(k.ray.origin.x),
                                           std::fabs(k.ray.origin.y), std::fabs(k.ray.origin.z)});
            // Rays nearly tangent to the side, or passing by a cone's apex where its two
            // nappes meet, have nearly double roots, known only to about the square root of the
            // rounding error: the bound is loose for them, and still far below any wrong root.
            const double tol = 1e-6 * scale;
            if (out[i].part == 0) {
                const double r = k.cone.r0 + (k.cone.r1 - k.cone.r0) * p.z;
                EXPECT_NEAR(std::hypot(p.x, p.y), r, tol * (1 + std::fabs(k.cone.r1 - k.cone.r0)));
                EXPECT_GE(p.z, -tol);
                EXPECT_LE(p.z, 1 + tol);
            } else {
                EXPECT_NEAR(p.z, out[i].part == 1 ? 0.0 : 1.0, tol);
                EXPECT_FALSE(k.cone.open);
            }
        }
    }
}

}  // namespace
}  // namespace glint::render
