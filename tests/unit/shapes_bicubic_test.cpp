// bicubic_patch: flat patches hit where their plane is, with the patch's normal and uv;
// curved ones hit near the Bezier surface; the importer's forms.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/common/ir_printer.h"
#include "geom_test_util.h"
#include "pov_test_util.h"

namespace glint {
namespace {

using render::Hit;
using test::build_one;
using test::ray;

// Control points (i, j, height(i, j)) scaled by `size`.
template <class F>
scene::BicubicPatch patch(F height, int steps = 3, double size = 1) {
    scene::BicubicPatch s;
    s.flatness = 0.01;
    s.u_steps = s.v_steps = steps;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) s.points[i][j] = Vec3(i, j, height(i, j)) * size;
    return s;
}

// The Bezier surface at (u, v).
Vec3 bezier(const scene::BicubicPatch& s, double u, double v) {
    auto b = [](int i, double t) {
        const double c[] = {1, 3, 3, 1};
        return c[i] * std::pow(t, i) * std::pow(1 - t, 3 - i);
    };
    Vec3 p(0.0);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) p = p + s.points[i][j] * (b(i, u) * b(j, v));
    return p;
}

TEST(BicubicPatch, FlatPatchHitsItsPlane) {
    // Flat at once, and subdivided to the steps (flatness 0: nothing is flat enough).
    for (double z : {0.0, 2.0}) {
        auto s = patch([&](int, int) { return z; });
        if (z > 0) s.flatness = 0;
        auto g = build_one(s);
        Hit h;
        ASSERT_TRUE(g->intersect(ray({1.5, 0.75, -5}, {0, 0, 1}), &h)) << z;
        EXPECT_NEAR(h.t, 5 + z, 1e-9);
        EXPECT_NEAR(h.p.x, 1.5, 1e-9);
        EXPECT_NEAR(h.n.z, 1, 1e-9);  // u along x, v along y: du x dv = +z
        ASSERT_TRUE(h.has_uv);
        // uv_vectors default: v runs along the first uv axis, u along the second.
        EXPECT_NEAR(h.uv.x, 0.25, 1e-9);
        EXPECT_NEAR(h.uv.y, 0.5, 1e-9);
        EXPECT_FALSE(g->intersect(ray({3.5, 0.75, -5}, {0, 0, 1}), &h));
        EXPECT_FALSE(g->intersect(ray({1.5, 0.75, -5}, {0, 0, -1}), &h));
    }
}

TEST(BicubicPatch, CurvedPatchHitsNearTheSurface) {
    auto bump = [](int i, int j) { return (i == 1 || i == 2) && (j == 1 || j == 2) ? 1.5 : 0; };
    auto s = patch(bump, 5);
    auto g = build_one(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({1.5, 1.5, 5}, {0, 0, -1}), &h));
    const Vec3 top = bezier(s, 0.5, 0.5);  // (1.5, 1.5, 1.5 * 0.75^2)
    EXPECT_NEAR(h.p.z, top.z, 5e-3);
    EXPECT_NEAR(std::fabs(h.n.z), 1, 1e-2);
    // A transformed patch: the same surface, moved and scaled.
    auto moved = build_one(s, Transform::scale({2, 2, 2}).then(Transform::translate({10, 0, 0})));
    ASSERT_TRUE(moved->intersect(ray({13, 3, 5}, {0, 0, -1}), &h));
    EXPECT_NEAR(h.p.z, 2 * top.z, 1e-2);
}

TEST(BicubicPatch, Importer) {
    auto sc = pov::testing::parse(
        "bicubic_patch { type 1 flatness 0.1 u_steps 3 v_steps 4\n"
        " <0,0,2>, <1,0,0>, <2,0,0>, <3,0,-2>, <0,1,0>, <1,1,0>, <2,1,0>, <3,1,0>,\n"
        " <0,2,0>, <1,2,0>, <2,2,0>, <3,2,0>, <0,3,2>, <1,3,0>, <2,3,0>, <3,3,-2> }\n"
        "bicubic_patch { type 0 uv_vectors <0,0>, <2,0>, <2,2>, <0,2>"
        " 0,0,0,0, 0,0,0,0, 0,0,0,0, 0,0,0,1 }\n");
    ASSERT_EQ(sc.objects.size(), 2u);
    const auto* b = std::get_if<scene::BicubicPatch>(&sc.objects[0].shape);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->type, 1);
    EXPECT_EQ(b->flatness, 0.1);
    EXPECT_EQ(b->u_steps, 3);
    EXPECT_EQ(b->v_steps, 4);
    EXPECT_EQ(b->points[0][3], Vec3(3, 0, -2));
    EXPECT_EQ(b->points[3][3], Vec3(3, 3, -2));
    const auto* c = std::get_if<scene::BicubicPatch>(&sc.objects[1].shape);
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->uv[2], Vec2(2, 2));
    EXPECT_EQ(c->points[3][3], Vec3(1, 1, 1));
    EXPECT_NE(formats::print_ir(sc).find("bicubic_patch type 1 flatness 0.1 u_steps 3 v_steps 4"),
              std::string::npos);
    EXPECT_EQ(pov::testing::error_of("bicubic_patch { flatness 0.1 <0, 0, 0> }"),
              "1:1: undefined bicubic_patch type");
}

}  // namespace
}  // namespace glint
