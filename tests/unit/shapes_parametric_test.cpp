// POV-Ray's parametric (fpmetric.cpp): hits within the search's accuracy of closed forms, the
// (u, v) of the hit, normals from the parametrisation, precompute giving the same hits, the
// depths measured in the placing space, and the importer.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geom_test_util.h"
#include "pov_test_util.h"
#include "render/shapes/object_node.h"
#include "render/shapes/shapes.h"

namespace glint {
namespace {

using render::Hit;
using test::ray;

scene::Scene parse(const std::string& text) { return pov::testing::parse(text); }

// The plane z = 0 over u, v in [-1, 1].
const char* kSquare =
    "parametric { function { u } function { v } function { 0 } <-1, -1>, <1, 1>\n"
    "  contained_by { box { <-2, -2, -0.5>, <2, 2, 0.5> } } %s }";

std::string with(const char* format, const std::string& extra) {
    char buf[512];
    std::snprintf(buf, sizeof buf, format, extra.c_str());
    return buf;
}

// A torus of radii 1.2 and 0.4 about y.
const char* kTorus =
    "parametric { function { cos(u) * (1.2 + 0.4 * cos(v)) } function { 0.4 * sin(v) }\n"
    "  function { sin(u) * (1.2 + 0.4 * cos(v)) } <0, 0>, <2 * pi, 2 * pi>\n"
    "  contained_by { box { <-1.7, -0.5, -1.7>, <1.7, 0.5, 1.7> } } max_gradient 2 %s }";

TEST(Parametric, PlaneHitUvAndNormal) {
    auto sc = parse(with(kSquare, ""));
    auto g = test::build(sc);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0.3, 0.2, -5}, {0, 0, 1}), &h));
    // The hit is where the ray enters the slab of the nearest piece narrower than accuracy:
    // at most a few accuracies before the plane, never behind it.
    EXPECT_LE(h.t, 5.0);
    EXPECT_GT(h.t, 5.0 - 0.005);
    ASSERT_TRUE(h.has_uv);
    EXPECT_NEAR(h.uv.x, 0.3, 0.002);
    EXPECT_NEAR(h.uv.y, 0.2, 0.002);
    EXPECT_NEAR(std::fabs(h.ng.z), 1, 1e-9);
    // Outside the uv range, and outside the container: misses.
    EXPECT_FALSE(g->intersect(ray({1.3, 0.2, -5}, {0, 0, 1}), &h));
    EXPECT_FALSE(g->intersect(ray({0.3, 0.2, -5}, {0, 0, -1}), &h));
}

TEST(Parametric, TorusHitsLieOnTheTorus) {
    auto sc = parse(with(kTorus, "accuracy 0.002"));
    auto g = test::build(sc);
    int hits = 0;
    for (int i = 0; i < 40; ++i) {
        const double a = -0.9 + 1.8 * i / 40;
        const Vec3 o(3 * std::sin(a), 2.5, -3 * std::cos(a));
        const Vec3 d = normalize(Vec3(1.2 * std::sin(a), 0, -1.2 * std::cos(a)) - o);
        Hit h;
        if (!g->intersect(ray(o, d), &h)) continue;
        ++hits;
        // The hit is where the ray enters the nearest small piece's slab: on the torus or a
        // little in front of it (the ranges reach past the piece and are lowered by accuracy).
        const double w = std::hypot(h.p.x, h.p.z) - 1.2;
        EXPECT_GT(std::hypot(w, h.p.y), 0.4 - 0.002) << i;
        EXPECT_LT(std::hypot(w, h.p.y), 0.4 + 0.03) << i;
        // The normal is the tube's, up to orientation.
        const Vec3 c = Vec3(h.p.x, 0, h.p.z) * (1.2 / std::hypot(h.p.x, h.p.z));
        EXPECT_GT(std::fabs(dot(h.ng, normalize(h.p - c))), 0.99) << i;
        // (u, v) maps to the hit point.
        const double u = h.uv.x, v = h.uv.y;
        const Vec3 q(std::cos(u) * (1.2 + 0.4 * std::cos(v)), 0.4 * std::sin(v),
                     std::sin(u) * (1.2 + 0.4 * std::cos(v)));
        EXPECT_LT(length(q - h.p), 0.02) << i;
    }
    EXPECT_GT(hits, 30);
}

TEST(Parametric, PrecomputeFindsTheSameSurface) {
    // precompute only changes the ranges of the first pieces (to the union of their
    // children's): the same pieces of the surface are found.
    auto plain = test::build(parse(with(kTorus, "accuracy 0.005")));
    auto pre = test::build(parse(with(kTorus, "accuracy 0.005 precompute 12 x, y, z")));
    auto some = test::build(parse(with(kTorus, "accuracy 0.005 precompute 8 y")));
    int hits = 0;
    for (int i = 0; i < 20; ++i) {
        const Vec3 o(-2 + 0.2 * i, 2, -3);
        const Vec3 d = normalize(Vec3(0, 0, -1.2) - o);
        Hit a, b, c;
        const bool ha = plain->intersect(ray(o, d), &a);
        ASSERT_EQ(ha, pre->intersect(ray(o, d), &b)) << i;
        ASSERT_EQ(ha, some->intersect(ray(o, d), &c)) << i;
        if (!ha) continue;
        ++hits;
        EXPECT_NEAR(a.t, b.t, 0.02) << i;
        EXPECT_NEAR(a.t, c.t, 0.02) << i;
    }
    EXPECT_GT(hits, 10);
}

TEST(Parametric, Transformed) {
    // Scaled by 4: the plane keeps z = 0, (u, v) is the point over 4.
    auto g = test::build(parse(with(kSquare, "accuracy 0.01 scale 4")));
    Hit h;
    ASSERT_TRUE(g->intersect(ray({1.2, 0.8, -10}, {0, 0, 2}), &h));
    EXPECT_LE(h.t * 2, 10.0);
    EXPECT_GT(h.t * 2, 10.0 - 0.2);
    EXPECT_NEAR(h.uv.x, 0.3, 0.02);
    EXPECT_NEAR(h.uv.y, 0.2, 0.02);
    EXPECT_NEAR(std::fabs(h.ng.z), 1, 1e-9);
}

TEST(Parametric, NoInsideAndNearHitsDropped) {
    auto sc = parse(with(kSquare, ""));
    Diagnostics diag;
    auto node = render::ObjectNode::build(sc.objects.at(0), sc, diag);
    EXPECT_FALSE(node->inside({0, 0, 0}));
    // A ray leaving the surface: the search skips 4 accuracies past the container's entry.
    Hit h;
    auto g = test::build(sc);
    EXPECT_FALSE(g->intersect(ray({0.3, 0.2, -0.001}, {0, 0, 1}), &h));
    // The sphere container: a ray starting inside finds the surface ahead of it.
    auto sp = test::build(parse(
        "parametric { function { u } function { v } function { 0 } <-1, -1>, <1, 1>\n"
        "  contained_by { sphere { 0, 1.5 } } }"));
    ASSERT_TRUE(sp->intersect(ray({0.3, 0.2, -1}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 1, 0.005);
}

TEST(ParametricParser, IntoTheIrAndMessages) {
    auto sc = parse(
        "parametric { function { u } function { v } function { u * v } <1, 2>, <-1, 0>\n"
        "  accuracy 0.01 max_gradient 3 precompute 10, x, z\n"
        "  contained_by { sphere { <1, 2, 3>, 4 } } }");
    ASSERT_EQ(sc.objects.size(), 1u);
    const auto& s = std::get<scene::Parametric>(sc.objects[0].shape);
    EXPECT_EQ(s.uv_min.x, -1);  // sorted per component
    EXPECT_EQ(s.uv_min.y, 0);
    EXPECT_EQ(s.uv_max.x, 1);
    EXPECT_EQ(s.uv_max.y, 2);
    EXPECT_EQ(s.accuracy, 0.01);
    EXPECT_EQ(s.max_gradient, 3);
    EXPECT_EQ(s.precompute_depth, 10);
    EXPECT_TRUE(s.precompute[0]);
    EXPECT_FALSE(s.precompute[1]);
    EXPECT_TRUE(s.precompute[2]);
    EXPECT_TRUE(s.container.sphere);
    EXPECT_EQ(s.container.center, Vec3(1, 2, 3));
    EXPECT_EQ(s.container.radius, 4);
    for (int f : s.function) EXPECT_GE(f, 0);
    // POV-Ray's defaults.
    auto d = parse("parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> }");
    const auto& ds = std::get<scene::Parametric>(d.objects.at(0).shape);
    EXPECT_EQ(ds.accuracy, 0.001);
    EXPECT_EQ(ds.max_gradient, 1);
    EXPECT_FALSE(ds.container.sphere);
    EXPECT_EQ(ds.container.corner1, Vec3(-1, -1, -1));
    EXPECT_EQ(ds.precompute_depth, 0);
    EXPECT_EQ(pov::testing::error_of(
                  "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1>\n"
                  "precompute 21 x }"),
              "2:1: parametric precompute depth must be 1 to 20, got 21");
    EXPECT_EQ(pov::testing::error_of("parametric { function { u } function { v } <0, 0>, <1, 1> }"),
              "1:44: expected the function for z in parametric (function { ... }), got '<'");
    EXPECT_EQ(pov::testing::error_of(
                  "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1>\n"
                  "accuracy 0 }"),
              "1:1: parametric accuracy must be positive");
}

}  // namespace
}  // namespace glint
