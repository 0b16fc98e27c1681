// POV-Ray's ovus (ovus.cpp): hits on each of its three pieces against closed forms, normals,
// the inside test, uv, and the importer (the sphere POV-Ray substitutes, errors, and lemon,
// which POV-Ray 3.7 does not know).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "geom_test_util.h"
#include "pov_test_util.h"
#include "render/shapes/object_node.h"
#include "render/shapes/shapes.h"

namespace glint {
namespace {

using render::Hit;
using test::build_one;
using test::ray;
using test::inside;
using test::node_of;

scene::Ovus ovus(double bottom, double top) {
    scene::Ovus o;
    o.bottom_radius = bottom;
    o.top_radius = top;
    return o;
}

// Parse_Ovus's values for bottom 1, top 0.5: the band's circle has radius 2 about
// <-hp, vp> in the (h, y) half plane, between heights 0.125 and 1.375.
constexpr double kVp = -0.125;
const double kHp = std::sqrt(1 - kVp * kVp);

TEST(Ovus, BottomSphereTopSphereAndBand) {
    auto g = build_one(ovus(1, 0.5));
    Hit h;
    // Below the band: the bottom sphere.
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 4, 1e-12);
    EXPECT_NEAR(h.ng.z, -1, 1e-12);
    // Straight down: the top sphere's pole at b + t.
    ASSERT_TRUE(g->intersect(ray({0, 5, 0}, {0, -2, 0}), &h));
    EXPECT_NEAR(h.t, (5 - 1.5) / 2, 1e-12);
    EXPECT_NEAR(h.ng.y, 1, 1e-12);
    // In the band at y = 0.8: (w + hp)^2 + (0.8 - vp)^2 = 4.
    const double w = std::sqrt(4 - (0.8 - kVp) * (0.8 - kVp)) - kHp;
    ASSERT_TRUE(g->intersect(ray({0, 0.8, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 5 - w, 1e-9);
    const Vec3 n = normalize(Vec3(0, 0.8 - kVp, -w - kHp));
    EXPECT_NEAR(h.ng.y, n.y, 1e-9);
    EXPECT_NEAR(h.ng.z, n.z, 1e-9);
    // Both crossings for CSG, and a miss beside it.
    auto t = test::hit_depths(ovus(1, 0.5), ray({0, 0.8, -5}, {0, 0, 1}));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5 - w, 1e-9);
    EXPECT_NEAR(t[1], 5 + w, 1e-9);
    EXPECT_FALSE(g->intersect(ray({0, 0.8, -5}, {0, 0, -1}), &h));
    EXPECT_FALSE(g->intersect(ray({1.2, 0, -5}, {0, 0, 1}), &h));
}

TEST(Ovus, SurfaceIsSmoothAcrossThePieces) {
    // Rays from all around: the hit lies on its piece's implicit surface, and stepping a
    // little along the normal leaves the inside (the pieces meet tangentially).
    for (const auto& [b, t] : {std::pair{1.0, 0.5}, std::pair{0.6, 0.9}, std::pair{1.0, 1.0}}) {
        auto node = node_of(ovus(b, t));
        auto g = build_one(ovus(b, t));
        for (int i = 0; i < 60; ++i) {
            const double a = 0.1 + 3.0 * i / 60;  // polar angle of the ray's direction
            const Vec3 dir(std::sin(a) * 0.6, -std::cos(a), std::sin(a) * 0.8);
            const Vec3 o = Vec3(0, b / 2, 0) - dir * 6;
            Hit h;
            ASSERT_TRUE(g->intersect(ray(o, dir), &h)) << b << " " << t << " " << a;
            EXPECT_FALSE(node->inside(h.p + h.ng * 1e-6)) << b << " " << t << " " << a;
            EXPECT_TRUE(node->inside(h.p - h.ng * 1e-6)) << b << " " << t << " " << a;
            EXPECT_LT(dot(h.ng, dir), 0);
        }
    }
}

TEST(Ovus, InsideTest) {
    auto node = node_of(ovus(1, 0.5));
    const double w = std::sqrt(4 - (0.8 - kVp) * (0.8 - kVp)) - kHp;
    EXPECT_TRUE(node->inside({0, 0.5, 0}));
    EXPECT_TRUE(node->inside({0, 0.8, w - 1e-6}));
    EXPECT_FALSE(node->inside({0, 0.8, w + 1e-6}));
    EXPECT_TRUE(node->inside({0, 1.45, 0}));   // in the top sphere
    EXPECT_FALSE(node->inside({0, 1.55, 0}));  // above it
    EXPECT_FALSE(node->inside({0, -1.01, 0}));
}

TEST(Ovus, UvIsTheSphereMappingAboutHalfTheTopRadius) {
    // Ovus::CalcUV: the point less <0, top/2, 0>, mapped as a sphere's.
    auto g = build_one(ovus(1, 0.5));
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    ASSERT_TRUE(h.has_uv);
    EXPECT_NEAR(h.uv.x, 0.75, 1e-12);
    EXPECT_NEAR(h.uv.y, 0.5 + std::asin(-0.25 / std::sqrt(1.0625)) / kPi, 1e-12);
    ASSERT_TRUE(g->intersect(ray({5, 0.25, 0}, {-1, 0, 0}), &h));
    EXPECT_NEAR(h.uv.x, 0, 1e-12);
    EXPECT_NEAR(h.uv.y, 0.5, 1e-12);
}

TEST(Ovus, Transformed) {
    auto g =
        build_one(ovus(1, 0.5), Transform::translate({0, 0, 3}).then(Transform::scale({2, 2, 2})));
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 5 + 6 - 2, 1e-9);
}

TEST(OvusParser, IntoTheIrSphereSubstituteAndErrors) {
    auto sc = pov::testing::parse("ovus { 1, 0.65 scale 2 }");
    ASSERT_EQ(sc.objects.size(), 1u);
    const auto& o = std::get<scene::Ovus>(sc.objects[0].shape);
    EXPECT_EQ(o.bottom_radius, 1);
    EXPECT_EQ(o.top_radius, 0.65);
    // Parse_Ovus: a top radius of twice the bottom one or more is a sphere, with a warning.
    Diagnostics diag;
    auto sp = pov::parse_string("ovus { 0.5, 1 }", "test.pov", {}, diag);
    const auto& s = std::get<scene::Sphere>(sp.objects.at(0).shape);
    EXPECT_EQ(s.center, Vec3(0, 0.5, 0));
    EXPECT_EQ(s.radius, 1);
    int about_ovus = 0;
    for (const Diagnostic& d : diag.all())
        about_ovus += d.message.find("ovus top radius") != std::string::npos;
    EXPECT_EQ(about_ovus, 1);
    EXPECT_EQ(pov::testing::error_of("ovus { -1, 0.5 }"),
              "1:8: both ovus radii must be positive");
    EXPECT_EQ(pov::testing::error_of("ovus { }"), "1:8: expected a value, got '}'");
}

TEST(OvusParser, LemonIsNotAPovRay37Shape) {
    // POV-Ray 3.7.0 stops at `lemon`: "undeclared identifier 'lemon'" (it came with 3.8).
    EXPECT_EQ(pov::testing::error_of("lemon { <0, 0, 0>, 1, <0, 1, 0>, 0.5, 1 }"),
              "1:1: 'lemon' is not a POV-Ray 3.7 shape (it came with POV-Ray 3.8); POV-Ray 3.7 "
              "stops here: undeclared identifier 'lemon'");
    EXPECT_EQ(pov::testing::error_of("union { sphere { 0, 1 } lemon { 0, 1, y, 0.5, 1 } }"),
              "1:25: 'lemon' is not a POV-Ray 3.7 shape (it came with POV-Ray 3.8); POV-Ray 3.7 "
              "stops here: undeclared identifier 'lemon'");
    // To POV-Ray 3.7 it is a name like any other.
    auto sc = pov::testing::parse("#declare lemon = sphere { 0, 1 }\nobject { lemon }");
    EXPECT_EQ(sc.objects.size(), 1u);
}

}  // namespace
}  // namespace glint
