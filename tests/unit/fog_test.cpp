// fog and rainbow: the parser's statements (POV-Ray's stored values) and the atmosphere's
// closed forms (constant fog exp(-d / distance), ground fog's mean density, fog filter and
// transmit, the rainbow's color across the bow).
#include <gtest/gtest.h>

#include <cmath>

#include "render/integrators/atmosphere.h"
#include "unit/pov_test_util.h"

namespace glint {
namespace {

using pov::testing::error_of;
using pov::testing::parse;

TEST(FogParser, DefaultsTransformsAndTypes) {
    auto s = parse(
        "fog { distance 10 color rgbf <0.5, 0.6, 0.7, 0.2> }\n"
        "fog { fog_type 2 distance 3 fog_offset 1 fog_alt 0.5 up <0, 2, 0> rotate <0, 0, 90> "
        "turbulence 0.5 octaves 20 }");
    ASSERT_EQ(s.fogs.size(), 2u);
    EXPECT_EQ(s.fogs[0].type, scene::FogType::Constant);
    EXPECT_EQ(s.fogs[0].distance, 10);
    EXPECT_EQ(s.fogs[0].color.filter, 0.2);
    EXPECT_FALSE(s.fogs[0].turbulent);
    const scene::Fog& g = s.fogs[1];
    EXPECT_EQ(g.type, scene::FogType::Ground);
    EXPECT_NEAR(g.up.x, -1.0, 1e-12);  // normalized after the rotation
    EXPECT_NEAR(g.up.y, 0.0, 1e-12);
    EXPECT_TRUE(g.turbulent);
    EXPECT_EQ(g.turbulence, Vec3(0.5, 0.5, 0.5));
    EXPECT_EQ(g.octaves, 10);  // clamped to 1..10
    EXPECT_EQ(g.turb_depth, 0.5);
}

TEST(RainbowParser, AnglesInRadiansAndErrors) {
    auto s = parse(
        "rainbow { angle 42 width 4 direction <0, 0, 2> arc_angle 120 "
        "color_map { [0 rgb 1] [1 rgb 0] } }");
    ASSERT_EQ(s.rainbows.size(), 1u);
    const scene::Rainbow& r = s.rainbows[0];
    EXPECT_NEAR(r.angle, 40.0 * kPi / 180.0, 1e-12);  // inner edge: angle - width / 2
    EXPECT_NEAR(r.width, 4.0 * kPi / 180.0, 1e-12);
    EXPECT_NEAR(r.arc_angle, kPi / 3.0, 1e-12);       // half of 120 degrees
    EXPECT_EQ(r.falloff_angle, r.arc_angle);           // arc_angle alone sets both
    EXPECT_EQ(r.antisolar, Vec3(0, 0, 1));
    EXPECT_EQ(error_of("rainbow { angle 42 width 4 direction <0, 1, 0> }"),
              "1:9: rainbow's up and direction vector are co-linear");
    EXPECT_EQ(error_of("rainbow { direction z arc_angle 400 }"),
              "1:33: illegal arc_angle in rainbow (use 0 to 360 degrees)");
}

TEST(Atmosphere, ConstantFogBlendsTowardsItsColor) {
    scene::Scene s;
    scene::Fog f;
    f.distance = 2;
    f.color = scene::ColorFT(Color(0.5, 0.25, 1.0));
    s.fogs.push_back(f);
    render::Atmosphere a(s);
    Color c = a.apply(Vec3(0, 0, 0), Vec3(0, 0, 1), 3.0, Color(0.2, 0.4, 0.6));
    double k = std::exp(-1.5);
    EXPECT_NEAR(c.r, 0.5 * (1 - k) + 0.2 * k, 1e-12);
    EXPECT_NEAR(c.g, 0.25 * (1 - k) + 0.4 * k, 1e-12);
    // A miss is fully fogged.
    Color miss = a.apply(Vec3(0, 0, 0), Vec3(0, 0, 1), render::Atmosphere::kMissDepth, Color(1.0));
    EXPECT_NEAR(miss.b, 1.0, 1e-12);
    EXPECT_NEAR(miss.g, 0.25, 1e-12);
}

TEST(Atmosphere, FogTransmitAndFilter) {
    scene::Scene s;
    scene::Fog f;
    f.distance = 1;
    f.color = scene::ColorFT(Color(1.0, 0.0, 0.0), 0.5, 0.25);
    s.fogs.push_back(f);
    render::Atmosphere a(s);
    // Far away the attenuation falls to the transmit floor 0.25; filter tints what passes.
    Color c = a.apply(Vec3(0, 0, 0), Vec3(0, 0, 1), 1e6, Color(1.0));
    EXPECT_NEAR(c.r, 0.75 * 1.0 + 0.25 * (0.5 + 0.5 * 1.0), 1e-12);
    EXPECT_NEAR(c.g, 0.25 * 0.5, 1e-12);
}

TEST(Atmosphere, GroundFogIsDenseBelowItsOffset) {
    scene::Scene s;
    scene::Fog f;
    f.type = scene::FogType::Ground;
    f.distance = 1;
    f.offset = 1;
    f.alt = 1;
    s.fogs.push_back(f);
    render::Atmosphere a(s);
    // Entirely below the offset: like constant fog.
    Color low = a.apply(Vec3(0, 0, 0), Vec3(1, 0, 0), 2.0, Color(1.0));
    EXPECT_NEAR(low.r, std::exp(-2.0), 1e-12);
    // At height 2 (h = 1) the density is 1 / (1 + 1) = 0.5.
    Color high = a.apply(Vec3(0, 2, 0), Vec3(1, 0, 0), 2.0, Color(1.0));
    EXPECT_NEAR(high.r, std::exp(-1.0), 1e-12);
}

TEST(Atmosphere, RainbowColorAcrossTheBow) {
    auto s = parse(
        "rainbow { angle 30 width 10 direction z color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, "
        "1>] } }");
    render::Atmosphere a(s);
    // 27.5 degrees off the antisolar point: a quarter across the bow (25..35 degrees).
    double th = 27.5 * kPi / 180.0;
    Vec3 d(0, std::sin(th), std::cos(th));
    Color c = a.apply(Vec3(0, 0, 0), d, render::Atmosphere::kMissDepth, Color(0.0));
    EXPECT_NEAR(c.r, 0.75, 1e-9);
    EXPECT_NEAR(c.b, 0.25, 1e-9);
    // Outside the bow nothing changes.
    Color out = a.apply(Vec3(0, 0, 0), Vec3(0, 0, 1), 1.0, Color(0.3));
    EXPECT_EQ(out, Color(0.3));
}

}  // namespace
}  // namespace glint
