// VALIDATION.md case 15: a clear sphere of ior 1.0 vanishes (the linear film differs from the
// film without it by at most 1e-5), and ior 1.0001, 1.5, 2.4 and 100, with a cube that forces
// total internal reflection, give no NaN or infinite pixel.
#include <gtest/gtest.h>

#include <cstdio>

#include "stability_support.h"

namespace glint::stability {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kMaxVanishDiff = 1e-5;

TEST(StabilityIor, Ior1SphereVanishes) {
    const render::Image without = render_file("ior_sphere.pov", "#declare Show_Sphere = 0;",
                                              kWidth, kHeight);
    const render::Image with = render_file("ior_sphere.pov", "#declare Ior = 1.0;", kWidth,
                                           kHeight);
    ASSERT_EQ(with.rgba.size(), without.rgba.size());
    double max_diff = 0;
    int at_x = 0, at_y = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            for (int c = 0; c < 3; ++c) {
                const double d = std::fabs(static_cast<double>(with.pixel(x, y)[c]) -
                                           static_cast<double>(without.pixel(x, y)[c]));
                if (!(d <= max_diff)) {  // also catches NaN
                    max_diff = d;
                    at_x = x;
                    at_y = y;
                }
            }
        }
    }
    std::printf("ior 1.0 sphere vs no sphere: max linear difference = %.3g at %d,%d "
                "(bound <= %.0e)\n", max_diff, at_x, at_y, kMaxVanishDiff);
    EXPECT_LE(max_diff, kMaxVanishDiff);

    // Not vacuous: the same sphere with ior 1.5 does show.
    const render::Image glass = render_file("ior_sphere.pov", "#declare Ior = 1.5;", kWidth,
                                            kHeight);
    const double unchanged = fraction_within(glass, without, 0);
    std::printf("ior 1.5 sphere vs no sphere: unchanged pixels = %.4f (bound < 0.99)\n",
                unchanged);
    EXPECT_LT(unchanged, 0.99);
}

TEST(StabilityIor, ExtremeIorsAndTotalInternalReflectionStayFinite) {
    for (const char* ior : {"1.0001", "1.5", "2.4", "100"}) {
        const std::string prelude =
            std::string("#declare Ior = ") + ior + "; #declare Show_Cube = 1;";
        const render::Image image = render_file("ior_sphere.pov", prelude, kWidth, kHeight);
        ASSERT_EQ(image.width, kWidth);
        const long bad = count_nonfinite(image);
        std::printf("ior %s (sphere + TIR cube): non-finite values = %ld (bound 0)\n", ior, bad);
        EXPECT_EQ(bad, 0) << "ior " << ior;
    }
}

}  // namespace
}  // namespace glint::stability
