// POV-Ray's isosurface: hits within `accuracy` of closed forms, the container's own surface
// (closed vs open), the inside test, all_intersections through CSG, and the importer.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "geom_test_util.h"
#include "pov_test_util.h"
#include "render/render.h"
#include "render/shapes/object_node.h"
#include "render/shapes/shapes.h"

namespace glint {
namespace {

using render::Hit;
using test::ray;

constexpr double kAcc = 0.001;  // the default accuracy

// One isosurface (or any object) parsed from POV-Ray text.
scene::Scene parse(const std::string& object) {
    return pov::testing::parse("#declare Unit = function { sqrt(x*x + y*y + z*z) - 1 }\n" + object);
}

std::unique_ptr<render::ObjectNode> node_of(const scene::Scene& sc) {
    Diagnostics diag;
    return render::ObjectNode::build(sc.objects.at(0), sc, diag);
}

std::vector<double> all_hits(const scene::Scene& sc, const render::Ray& r) {
    return test::hit_depths(*node_of(sc), r);
}

TEST(Isosurface, SphereFunctionHitsTheSphere) {
    auto sc = parse("isosurface { function { Unit(x, y, z) } contained_by { box { -2, 2 } } }");
    ASSERT_EQ(sc.objects.size(), 1u);
    auto g = test::build(sc);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    // The root is the far end of the first interval narrower than accuracy where f < 0.
    EXPECT_GE(h.t, 4.0);
    EXPECT_LT(h.t, 4.0 + kAcc);
    EXPECT_NEAR(h.ng.z, -1, 1e-3);
    // An oblique ray: the hit lies on the unit sphere within accuracy, the normal is radial.
    const Vec3 o(3, 2, -4), d = normalize(Vec3(-3, -1.7, 4.2));
    ASSERT_TRUE(g->intersect(ray(o, d), &h));
    EXPECT_NEAR(length(h.p), 1.0, kAcc);
    EXPECT_GT(dot(h.ng, normalize(h.p)), 0.999);
    // A miss.
    EXPECT_FALSE(g->intersect(ray({0, 1.2, -5}, {0, 0, 1}), &h));
}

TEST(Isosurface, ThresholdAndSphereContainer) {
    // f = |p|, threshold 0.5: the sphere of radius 0.5; the container sphere of radius 0.8.
    auto sc = parse(
        "isosurface { function { sqrt(x*x + y*y + z*z) } threshold 0.5 "
        "contained_by { sphere { 0, 0.8 } } translate <1, 0, 0> }");
    auto g = test::build(sc);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({1, 0, -5}, {0, 0, 1}), &h));
    EXPECT_GE(h.t, 4.5);
    EXPECT_LT(h.t, 4.5 + kAcc);
    EXPECT_NEAR(g->bounds().hi.x, 1.8, 1e-9);
}

TEST(Isosurface, ClosedContainerShowsTheCutOpenDoesNot) {
    // A sphere of radius 1.5 cut by the default container box { -1, 1 }.
    const std::string fn = "function { Unit(x, y, z) - 0.5 }";
    auto closed = test::build(parse("isosurface { " + fn + " }"));
    Hit h;
    ASSERT_TRUE(closed->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_DOUBLE_EQ(h.t, 4.0);  // the container's face, exactly
    EXPECT_DOUBLE_EQ(h.ng.z, -1.0);
    auto open = test::build(parse("isosurface { " + fn + " open }"));
    EXPECT_FALSE(open->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    // Through the box's corner region the sphere itself is met, closed or open.
    ASSERT_TRUE(open->intersect(ray({0.9, 0.9, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 5 - std::sqrt(1.5 * 1.5 - 2 * 0.81), 2 * kAcc);
}

TEST(Isosurface, InsideTest) {
    auto sc = parse("isosurface { function { Unit(x, y, z) } contained_by { box { -2, 2 } } }");
    auto node = node_of(sc);
    EXPECT_TRUE(node->inside({0, 0, 0}));
    EXPECT_TRUE(node->inside({0.99, 0, 0}));
    EXPECT_FALSE(node->inside({1.01, 0, 0}));
    // Inside the function but outside the container: outside.
    auto cut = node_of(parse("isosurface { function { Unit(x, y, z) - 0.5 } }"));
    EXPECT_TRUE(cut->inside({0.9, 0, 0}));
    EXPECT_FALSE(cut->inside({1.1, 0, 0}));
}

TEST(Isosurface, AllIntersections) {
    // Two unit spheres at z = -2 and z = 2: four roots along the z axis.
    const std::string two =
        "function { min(sqrt(x*x + y*y + (z+2)*(z+2)), sqrt(x*x + y*y + (z-2)*(z-2))) - 1 } "
        "contained_by { box { <-2, -2, -4>, <2, 2, 4> } }";
    auto one = all_hits(parse("isosurface { " + two + " }"), ray({0, 0, -5}, {0, 0, 1}));
    ASSERT_EQ(one.size(), 1u);
    EXPECT_NEAR(one[0], 2, kAcc);
    auto all = all_hits(parse("isosurface { " + two + " all_intersections }"),
                        ray({0, 0, -5}, {0, 0, 1}));
    ASSERT_EQ(all.size(), 4u);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(all[i], 2.0 * (i + 1), 2 * kAcc);
    // In an intersection with the half space z >= 0 only the third root survives: without
    // all_intersections the ray finds nothing (the box face at z = 0 is outside both spheres).
    const std::string cut = " box { <-3, -3, 0>, <3, 3, 5> } }";
    Hit h;
    auto with_all = test::build(parse("intersection { isosurface { " + two +
                                      " all_intersections }" + cut));
    ASSERT_TRUE(with_all->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 6, 2 * kAcc);
    auto first_only = test::build(parse("intersection { isosurface { " + two + " }" + cut));
    EXPECT_FALSE(first_only->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
}

TEST(Isosurface, LowMaxGradientLeavesHoles) {
    // f = 10 (|p| - 1) is steeper than max_gradient 1.1 allows: POV-Ray's search skips the
    // root along a grazing ray and finds it with max_gradient 10.
    const std::string f = "function { 10 * Unit(x, y, z) } contained_by { box { -2, 2 } }";
    Hit h;
    auto low = test::build(parse("isosurface { " + f + " }"));
    auto high = test::build(parse("isosurface { " + f + " max_gradient 10 }"));
    EXPECT_TRUE(high->intersect(ray({0, 0.9, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 5 - std::sqrt(1 - 0.81), 2 * kAcc);
    EXPECT_FALSE(low->intersect(ray({0, 0.9, -5}, {0, 0, 1}), &h));
}

TEST(Isosurface, PigmentFunction) {
    // gradient x gives gray = x on [0, 1): the surface is the plane x = 0.5.
    auto sc = parse(
        "#declare P = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } }\n"
        "isosurface { function { P(x, y, z).gray - 0.5 } contained_by { box { 0, 0.99 } } }");
    auto g = test::build(sc);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({2, 0.5, 0.5}, {-1, 0, 0}), &h));
    EXPECT_NEAR(h.p.x, 0.5, 2 * kAcc);
    EXPECT_NEAR(h.ng.x, 1, 1e-3);
}

TEST(Isosurface, TraceWhileParsing) {
    pov::ParseOptions opts;
    opts.prepare_object = render::prepare_object_query;
    auto sc = pov::testing::parse(
        "#declare I = isosurface { function { sqrt(x*x + y*y + z*z) - 1 } "
        "contained_by { box { -2, 2 } } }\n"
        "#declare N = <0, 0, 0>;\n"
        "#declare P = trace(I, <0, 0, -5>, z, N);\n"
        "sphere { P, 0.1 }\n"
        "sphere { N, 0.1 }\n",
        opts);
    ASSERT_EQ(sc.objects.size(), 2u);
    EXPECT_NEAR(std::get<scene::Sphere>(sc.objects[0].shape).center.z, -1, kAcc);
    EXPECT_NEAR(std::get<scene::Sphere>(sc.objects[1].shape).center.z, -1, 1e-3);
}

TEST(Isosurface, GradientReportAfterTheRender) {
    // f = -5x needs max_gradient 5: with 1.1 POV-Ray warns of holes; f = -x with max_gradient 100
    // gets the advice to lower it. Two copies of one isosurface give one warning.
    auto sc = parse(
        "#declare Steep = isosurface { function { -5 * x } }\n"
        "object { Steep } object { Steep translate 3 * y }\n"
        "isosurface { function { -x } max_gradient 100 translate 6 * y }\n");
    auto g = test::build(sc);
    Hit h;
    for (double y : {0.0, 3.0, 6.0}) g->intersect(ray({-5, y + 0.5, 0.5}, {1, 0, 0}), &h);
    std::vector<render::GradientNote> notes;
    g->gradient_notes(&notes);
    ASSERT_EQ(notes.size(), 3u);
    Diagnostics diag;
    render::report_gradients(notes, sc, diag);
    ASSERT_EQ(diag.all().size(), 2u);
    EXPECT_EQ(diag.all()[0].message,
              "isosurface found a gradient of 5.000 where max_gradient is 1.100: it may have "
              "holes; raise max_gradient");
    EXPECT_EQ(diag.all()[0].loc.line, 2);
    EXPECT_EQ(diag.all()[1].message,
              "isosurface found a gradient of 1.000 where max_gradient is 100.000: a lower "
              "max_gradient would render it faster");
}

TEST(IsosurfaceParser, IntoTheIrAndMessages) {
    Diagnostics diag;
    auto sc = pov::parse_string(
        "isosurface { function { x } contained_by { sphere { <1, 2, 3>, 4 } } threshold 0.25 "
        "accuracy 0.01 max_gradient 3 evaluate 1, 2, 0.9 max_trace 20 open }",
        "test.pov", {}, diag);
    ASSERT_EQ(sc.objects.size(), 1u);
    const auto& s = std::get<scene::Isosurface>(sc.objects[0].shape);
    EXPECT_TRUE(s.container.sphere);
    EXPECT_EQ(s.container.center, Vec3(1, 2, 3));
    EXPECT_EQ(s.container.radius, 4);
    EXPECT_EQ(s.threshold, 0.25);
    EXPECT_EQ(s.accuracy, 0.01);
    EXPECT_EQ(s.max_gradient, 3);
    EXPECT_TRUE(s.evaluate);
    EXPECT_EQ(s.eval[2], 0.9);
    EXPECT_EQ(s.max_trace, 10);  // clamped, with a warning
    EXPECT_TRUE(s.open);
    EXPECT_GE(diag.warning_count(), 1);
    auto box = pov::testing::parse("isosurface { function { x } contained_by { box { 1, -1 } } }");
    const auto& b = std::get<scene::Isosurface>(box.objects.at(0).shape);
    EXPECT_EQ(b.container.corner1, Vec3(-1, -1, -1));  // corners sorted
    EXPECT_EQ(b.container.corner2, Vec3(1, 1, 1));
    EXPECT_EQ(pov::testing::error_of("isosurface { threshold 1 }"),
              "1:14: expected function after isosurface {, got 'threshold'");
}

}  // namespace
}  // namespace glint
