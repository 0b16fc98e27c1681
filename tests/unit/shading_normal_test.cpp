// The path tracer's bent shading normal (render/bsdf/shading_normal.h): Cycles' rule that the
// view's mirror direction must leave the surface.
#include "render/bsdf/shading_normal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace glint::render {
namespace {

Vec3 mirror(const Vec3& wo, const Vec3& n) { return n * (2 * dot(n, wo)) - wo; }

TEST(ShadingNormal, KeptWhereTheMirrorDirectionLeavesTheSurface) {
    const Vec3 ng(0, 0, 1);
    const Vec3 n = normalize(Vec3(0.3, 0.1, 1));
    const Vec3 wo = normalize(Vec3(-0.2, 0.4, 1));
    const Vec3 r = valid_reflection_normal(ng, wo, n);
    EXPECT_EQ(r, n);  // untouched, bit for bit
}

TEST(ShadingNormal, BentJustEnoughNearASilhouette) {
    // A smooth normal tilted 40 degrees away from a viewer who looks at 80 degrees from the
    // geometric normal: its mirror direction points into the surface.
    const Vec3 ng(0, 0, 1);
    const double tilt = 40 * kPi / 180, view = 80 * kPi / 180;
    const Vec3 n(std::sin(tilt), 0, std::cos(tilt));
    const Vec3 wo(-std::sin(view), 0.1, std::cos(view));
    const Vec3 wo_unit = normalize(wo);
    ASSERT_LT(dot(mirror(wo_unit, n), ng), 0);
    const Vec3 b = valid_reflection_normal(ng, wo_unit, n);
    EXPECT_NEAR(length(b), 1, 1e-12);
    EXPECT_NEAR(b.y, 0, 1e-12);  // in the plane of ng and n
    EXPECT_GT(b.x, 0);           // tilted the way n was, less far
    EXPECT_LT(b.x, n.x);
    // The mirror direction rises exactly min(0.9 cos(view), 0.01) above the surface.
    const double t = std::min(0.9 * dot(ng, wo_unit), 0.01);
    EXPECT_NEAR(dot(mirror(wo_unit, b), ng), t, 1e-12);
}

TEST(ShadingNormal, BackSideMirrorsTheFrontSide) {
    // A hit seen from behind (wo below ng) is bent as the mirrored hit seen from the front,
    // and handed back on the side its normal came in.
    const Vec3 ng(0, 0, 1);
    const Vec3 n = normalize(Vec3(0.6, 0, 0.8));
    const Vec3 wo = normalize(Vec3(-0.95, 0.05, 0.2));
    const Vec3 front = valid_reflection_normal(ng, wo, n);
    const Vec3 back = valid_reflection_normal(-ng, -wo, -n);
    ASSERT_NE(front, n);
    EXPECT_NEAR(back.x, -front.x, 1e-15);
    EXPECT_NEAR(back.y, -front.y, 1e-15);
    EXPECT_NEAR(back.z, -front.z, 1e-15);
}

TEST(ShadingNormal, FiniteForEveryViewAndTilt) {
    const Vec3 ng(0, 0, 1);
    int bent = 0;
    for (int a = 0; a <= 90; a += 3)
        for (int v = -89; v <= 89; v += 2) {
            const double ta = a * kPi / 180, tv = v * kPi / 180;
            const Vec3 n(std::sin(ta), 0, std::cos(ta));
            const Vec3 wo(std::sin(tv), 0, std::cos(tv));
            const Vec3 b = valid_reflection_normal(ng, wo, n);
            ASSERT_TRUE(std::isfinite(b.x) && std::isfinite(b.y) && std::isfinite(b.z))
                << a << " " << v;
            EXPECT_NEAR(length(b), 1, 1e-9) << a << " " << v;
            EXPECT_GE(b.z, 0) << a << " " << v;  // never past the geometric normal's horizon
            if (b != n) {
                ++bent;
                // Wherever it bends, the mirror direction clears the surface.
                EXPECT_GT(dot(mirror(wo, b), ng), 0) << a << " " << v;
            }
        }
    EXPECT_GT(bent, 100);  // the sweep does reach the bending cases
}

}  // namespace
}  // namespace glint::render
