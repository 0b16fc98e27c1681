// julia_fractal: sets with closed forms (c = 0 makes the quaternion set the unit ball and the
// hypercomplex one two crossed cylinders), the complex functions against identities, and the
// importer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "formats/common/ir_printer.h"
#include "geom_test_util.h"
#include "pov_test_util.h"
#include "render/shapes/julia_orbit.h"
#include "render/shapes/object_node.h"

namespace glint {
namespace {

using render::Hit;
using test::build_one;
using test::ray;

scene::JuliaFractal ball(scene::JuliaFunction f = scene::JuliaFunction::Sqr) {
    scene::JuliaFractal s;
    s.c[0] = 0;
    s.function = f;
    // Few iterations: deep inside, z^(3^20) underflows and leaves no normal (POV-Ray's too).
    s.max_iteration = 8;
    return s;
}

std::unique_ptr<render::ObjectNode> node_of(const scene::Shape& s) {
    static const scene::Scene sc = test::scene_of({});
    Diagnostics diag;
    return render::ObjectNode::build(test::object(s), sc, diag);
}

TEST(JuliaFractal, QuaternionSquareWithZeroCIsTheUnitBall) {
    for (auto f : {scene::JuliaFunction::Sqr, scene::JuliaFunction::Cube}) {
        auto g = build_one(ball(f));
        Hit h;
        ASSERT_TRUE(g->intersect(ray({0.3, 0.2, -5}, {0, 0, 1}), &h));
        EXPECT_NEAR(h.t, 5 - std::sqrt(1 - 0.13), 1e-6);
        const Vec3 n = normalize(h.p);
        EXPECT_NEAR(h.ng.x, n.x, 1e-5);
        EXPECT_NEAR(h.ng.y, n.y, 1e-5);
        EXPECT_NEAR(h.ng.z, n.z, 1e-5);
        // A scaled direction gives the same point at a scaled t.
        ASSERT_TRUE(g->intersect(ray({0.3, 0.2, -5}, {0, 0, 2}), &h));
        EXPECT_NEAR(h.t, (5 - std::sqrt(1 - 0.13)) / 2, 1e-6);
        EXPECT_FALSE(g->intersect(ray({1.2, 0, -5}, {0, 0, 1}), &h));
        EXPECT_FALSE(g->intersect(ray({0, 0, -5}, {0, 0, -1}), &h));
        auto node = node_of(ball(f));
        EXPECT_TRUE(node->inside({0.5, 0.5, 0.5}));
        EXPECT_FALSE(node->inside({0.6, 0.6, 0.6}));
    }
}

TEST(JuliaFractal, RaysLeavingTheSurfaceDoNotHitItAgain) {
    // POV-Ray drops crossings nearer than 1e-4, and outside CSG the fractal reports only its
    // first: a ray from a hit point, outwards or along the surface, passes.
    auto g = build_one(ball());
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0.3, 0.2, -5}, {0, 0, 1}), &h));
    const Vec3 p = h.p;
    EXPECT_FALSE(g->intersect(ray(p, normalize(p)), &h));
    EXPECT_FALSE(g->intersect(ray(p, normalize(cross(p, Vec3(0, 1, 0)))), &h));
}

TEST(JuliaFractal, AllHitsOfTheBall) {
    auto node = node_of(ball());
    render::HitList hits;
    node->intersect_all(ray({0, 0, -5}, {0, 0, 1}), kInfinity, &hits);
    ASSERT_EQ(hits.size(), 2u);
    std::vector<double> t = {hits[0].t, hits[1].t};
    std::sort(t.begin(), t.end());
    EXPECT_NEAR(t[0], 4, 1e-6);
    // POV-Ray counts the depth of later crossings from the earlier crossing, not from where
    // the march resumed, so the exit reads up to one step (1 / precision) short; its point
    // is exact.
    EXPECT_LE(t[1], 6 + 1e-6);
    EXPECT_GT(t[1], 6 - 0.06);
    const render::LocalHit& exit = hits[0].t > hits[1].t ? hits[0] : hits[1];
    EXPECT_NEAR(exit.p.z, 1, 1e-6);
    EXPECT_GT(exit.ng.z, 0.999);
}

TEST(JuliaFractal, HypercomplexSquareWithZeroCIsTwoCylinders) {
    // Duplex form with t = 0: (x, y + z) and (x, y - z) each squared, so the set is
    // x^2 + (y + z)^2 <= 1 and x^2 + (y - z)^2 <= 1, up to the escape radius (16) reached
    // within the iterations: a point r = 1 + e escapes when r^(2^20) > 16, e ~ 2.6e-6.
    scene::JuliaFractal s = ball();
    s.max_iteration = 20;
    s.algebra = scene::JuliaAlgebra::Hypercomplex;
    auto g = build_one(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 4, 5e-6);
    ASSERT_TRUE(g->intersect(ray({-5, 0.1, 0.1}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 5 - std::sqrt(1 - 0.04), 5e-6);
    EXPECT_LT(h.ng.x, -0.9);
    auto node = node_of(s);
    EXPECT_TRUE(node->inside({0.5, 0.2, 0.1}));
    EXPECT_FALSE(node->inside({0, 0.6, 0.6}));
}

TEST(JuliaFractal, HitsAreFiniteForEveryFunction) {
    using F = scene::JuliaFunction;
    for (int f = 0; f <= static_cast<int>(F::Reciprocal); ++f) {
        scene::JuliaFractal s;
        s.algebra = scene::JuliaAlgebra::Hypercomplex;
        s.function = static_cast<F>(f);
        s.c[0] = 0.3, s.c[1] = 0.2, s.c[2] = -0.1, s.c[3] = 0.05;
        s.exponent = {2, 0.5};
        s.max_iteration = 6;
        auto g = build_one(s);
        for (int i = 0; i < 20; ++i) {
            Hit h;
            if (!g->intersect(ray({-0.5 + 0.05 * i, 0.1, -6}, {0.01, 0.02, 1}), &h)) continue;
            EXPECT_TRUE(std::isfinite(h.t) && is_finite(h.p) && is_finite(h.ng)) << f;
            EXPECT_NEAR(length(h.ng), 1, 1e-9) << f;
        }
    }
}

TEST(JuliaFractal, ComplexFunctionsMatchTheirIdentities) {
    using render::julia::Complex;
    using render::julia::complex_function;
    using F = scene::JuliaFunction;
    auto eval = [](F f, Complex z, Complex e = {}) {
        Complex out;
        complex_function(f, z, e, &out);
        return out;
    };
    Complex r = eval(F::Exp, {0, std::numbers::pi});
    EXPECT_NEAR(r.x, -1, 1e-12);
    EXPECT_NEAR(r.y, 0, 1e-12);
    const Complex z{0.3, -0.4};
    for (auto [f, inv] : {std::pair{F::Sin, F::Asin}, std::pair{F::Cos, F::Acos},
                          std::pair{F::Tan, F::Atan}, std::pair{F::Sinh, F::Asinh},
                          std::pair{F::Cosh, F::Acosh}, std::pair{F::Tanh, F::Atanh},
                          std::pair{F::Exp, F::Ln}}) {
        Complex back = eval(inv, eval(f, z));
        // acos and acosh answer the root with the other sign.
        const double sign = (inv == F::Acos || inv == F::Acosh) && back.x * z.x < 0 ? -1 : 1;
        EXPECT_NEAR(sign * back.x, z.x, 1e-12) << static_cast<int>(f);
        EXPECT_NEAR(sign * back.y, z.y, 1e-12) << static_cast<int>(f);
    }
    r = eval(F::Pwr, z, {2, 0});
    EXPECT_NEAR(r.x, z.x * z.x - z.y * z.y, 1e-12);
    EXPECT_NEAR(r.y, 2 * z.x * z.y, 1e-12);
}

TEST(JuliaFractal, Importer) {
    auto sc = pov::testing::parse(
        "julia_fractal { <-0.083, 0, -0.83, -0.025> hypercomplex pwr(2, 0.5) max_iteration 8.7"
        " precision 0.5 slice <0, 0, 0, 2>, 0.5 }\n");
    ASSERT_EQ(sc.objects.size(), 1u);
    const auto* j = std::get_if<scene::JuliaFractal>(&sc.objects[0].shape);
    ASSERT_NE(j, nullptr);
    EXPECT_EQ(j->algebra, scene::JuliaAlgebra::Hypercomplex);
    EXPECT_EQ(j->function, scene::JuliaFunction::Pwr);
    EXPECT_EQ(j->exponent, Vec2(2, 0.5));
    EXPECT_EQ(j->max_iteration, 8);
    EXPECT_EQ(j->precision, 1);  // POV-Ray raises it to 1
    EXPECT_EQ(j->slice[3], 1);   // normalized
    EXPECT_EQ(j->slice_distance, 0.5);
    EXPECT_EQ(j->c[2], -0.83);
    EXPECT_NE(formats::print_ir(sc).find(
                  "julia_fractal <-0.083, 0, -0.83, -0.025> hypercomplex pwr"),
              std::string::npos);
    using pov::testing::error_of;
    EXPECT_EQ(error_of("julia_fractal { <0, 0, 0, 0> quaternion sin }"),
              "1:41: julia_fractal: quaternion supports only sqr and cube");
    EXPECT_EQ(error_of("julia_fractal { <0, 0, 0, 0> slice <1, 0, 0, 0>, 0 }"),
              "1:30: julia_fractal slice t component is zero");
}

}  // namespace
}  // namespace glint
