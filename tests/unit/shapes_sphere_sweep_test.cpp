// POV-Ray's sphere_sweep: the importer's values and messages, a straight sweep of two equal
// spheres against the closed-form capsule, spline sweeps whose hits must lie on the envelope of
// their spheres, and POV-Ray's inside test (CSG).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geom_test_util.h"
#include "pov_test_util.h"
#include "render/shapes/object_node.h"

namespace glint {
namespace {

using render::Hit;
using test::build_one;
using test::ray;
using test::inside;

scene::SphereSweep sweep(scene::SweepSpline spline, std::vector<scene::Sphere> spheres) {
    scene::SphereSweep s;
    s.spline = spline;
    s.spheres = std::move(spheres);
    return s;
}

// The nearest hit of the ray o + t d (d unit) with the capsule of radius r around a..b, or
// infinity: the cylinder between the ends, then the two end spheres.
double capsule_hit(Vec3 o, Vec3 d, Vec3 a, Vec3 b, double r) {
    double best = kInfinity;
    Vec3 ax = b - a;
    double h = length(ax);
    ax = ax / h;
    Vec3 oa = o - a;
    Vec3 dp = d - ax * dot(d, ax), op = oa - ax * dot(oa, ax);
    double qa = dot(dp, dp), qb = 2 * dot(dp, op), qc = dot(op, op) - r * r;
    double disc = qb * qb - 4 * qa * qc;
    if (qa > 0 && disc >= 0)
        for (double s : {-1.0, 1.0}) {
            double t = (-qb + s * std::sqrt(disc)) / (2 * qa);
            double along = dot(oa + d * t, ax);
            if (t > 0 && along >= 0 && along <= h) best = std::min(best, t);
        }
    for (Vec3 c : {a, b}) {
        Vec3 oc = o - c;
        double pb = dot(oc, d), pc = dot(oc, oc) - r * r, pd = pb * pb - pc;
        if (pd < 0) continue;
        for (double s : {-1.0, 1.0}) {
            double t = -pb + s * std::sqrt(pd);
            if (t > 0) best = std::min(best, t);
        }
    }
    return best;
}

// ---- importer ----------------------------------------------------------------------------

TEST(SphereSweepParse, ValuesOfEachSpline) {
    auto sc = pov::testing::parse(
        "sphere_sweep { linear_spline 2, <0, 0, 0>, 0.5, <1, 2, 3>, 0.25 }\n"
        "sphere_sweep { b_spline, 4, <0,0,0>, 1 <1,0,0> 1 <2,0,0> 1, <3,0,0>, 1 tolerance 1e-3"
        " translate x }\n"
        "sphere_sweep { cubic_spline 4, 0, 1, <1,0,0>, 2, <2,0,0>, 3, <3,0,0>, 4 }\n");
    ASSERT_EQ(sc.objects.size(), 3u);
    const auto& a = std::get<scene::SphereSweep>(sc.objects[0].shape);
    EXPECT_EQ(a.spline, scene::SweepSpline::Linear);
    ASSERT_EQ(a.spheres.size(), 2u);
    EXPECT_EQ(a.spheres[1].center, Vec3(1, 2, 3));
    EXPECT_EQ(a.spheres[1].radius, 0.25);
    EXPECT_EQ(a.tolerance, 1e-6);
    const auto& b = std::get<scene::SphereSweep>(sc.objects[1].shape);
    EXPECT_EQ(b.spline, scene::SweepSpline::BSpline);
    ASSERT_EQ(b.spheres.size(), 4u);  // `1 <1,0,0>`: a radius, then the next centre
    EXPECT_EQ(b.spheres[1].center, Vec3(1, 0, 0));
    EXPECT_EQ(b.tolerance, 1e-3);
    EXPECT_EQ(sc.objects[1].transform.point({0, 0, 0}), Vec3(1, 0, 0));
    const auto& c = std::get<scene::SphereSweep>(sc.objects[2].shape);
    EXPECT_EQ(c.spline, scene::SweepSpline::Cubic);
    EXPECT_EQ(c.spheres[0].center, Vec3(0, 0, 0));  // a float centre is a vector
    EXPECT_EQ(c.spheres[3].radius, 4);
}

TEST(SphereSweepParse, Errors) {
    using pov::testing::error_of;
    EXPECT_EQ(error_of("sphere_sweep { linear_spline 1, <0,0,0>, 1 }"),
              "1:30: sphere_sweep with linear_spline needs at least 2 spheres");
    EXPECT_EQ(error_of("sphere_sweep { b_spline 3, 0, 1, 1, 1, 2, 1 }"),
              "1:25: sphere_sweep with b_spline needs at least 4 spheres");
    EXPECT_EQ(error_of("sphere_sweep { cubic_spline 3, 0, 1, 1, 1, 2, 1 }"),
              "1:29: sphere_sweep with cubic_spline needs at least 4 spheres");
    EXPECT_EQ(error_of("sphere_sweep { linear_spline 2, <0,0,0>, 1, <1,0,0>, -0.5 }"),
              "1:54: sphere_sweep sphere 2 has a negative radius");
    EXPECT_EQ(error_of("sphere_sweep { 2, <0,0,0>, 1, <1,0,0>, 1 }"),
              "1:16: sphere_sweep needs linear_spline, b_spline or cubic_spline first");
    EXPECT_EQ(error_of("sphere_sweep { linear_spline 2, 0, 1, 1, 1 tolerance -1 }"),
              "1:54: sphere_sweep tolerance must not be negative");
}

// ---- a straight sweep of equal spheres is a capsule ----------------------------------------

TEST(SphereSweep, LinearEqualSpheresIsACapsule) {
    const Vec3 a(0, 0, 0), b(2, 0, 0);
    const double r = 0.5;
    auto s = sweep(scene::SweepSpline::Linear, {{a, r}, {b, r}});
    auto g = build_one(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({1, 5, 0}, {0, -1, 0}), &h));  // the side
    EXPECT_NEAR(h.t, 4.5, 1e-9);
    EXPECT_NEAR(h.ng.y, 1, 1e-9);
    ASSERT_TRUE(g->intersect(ray({-5, 0, 0}, {1, 0, 0}), &h));  // an end, along the axis
    EXPECT_NEAR(h.t, 4.5, 1e-9);
    EXPECT_NEAR(h.ng.x, -1, 1e-9);
    EXPECT_FALSE(g->intersect(ray({1, 0.6, -5}, {0, 0, 1}), &h));  // passes above

    // Random rays through the capsule's neighbourhood against the closed form.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        Vec3 o = normalize(Vec3(U(rng), U(rng), U(rng))) * 6 + Vec3(1, 0, 0);
        Vec3 target(1 + 1.6 * U(rng), 0.7 * U(rng), 0.7 * U(rng));
        Vec3 d = normalize(target - o);
        double want = capsule_hit(o, d, a, b, r);
        bool got = g->intersect(ray(o, d), &h);
        if (!std::isfinite(want)) {
            // A miss by the closed form may still graze the silhouette within rounding.
            if (got) {
                Vec3 p = o + d * h.t;
                double along = std::clamp(dot(p - a, b - a) / dot(b - a, b - a), 0.0, 1.0);
                EXPECT_NEAR(length(p - (a + (b - a) * along)), r, 1e-6) << "ray " << i;
            }
            continue;
        }
        ASSERT_TRUE(got) << "ray " << i;
        ++hits;
        EXPECT_NEAR(h.t, want, 1e-7) << "ray " << i;
        Vec3 p = o + d * h.t;
        // The outward normal of a capsule: from the nearest axis point to the hit.
        double along = std::clamp(dot(p - a, b - a) / dot(b - a, b - a), 0.0, 1.0);
        Vec3 n = normalize(p - (a + (b - a) * along));
        EXPECT_NEAR(dot(n, h.ng), 1, 1e-6) << "ray " << i;
    }
    EXPECT_GT(hits, 500);
}

TEST(SphereSweep, LinearAllHitsAreTheCapsulesTwo) {
    auto s = sweep(scene::SweepSpline::Linear, {{{0, 0, 0}, 0.5}, {{2, 0, 0}, 0.5}});
    // Through the middle, across the axis and along it: one entry, one exit; the spheres and
    // discs inside the capsule are merged away.
    auto t = test::hit_depths(s, ray({1, 5, 0}, {0, -1, 0}));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.5, 1e-9);
    EXPECT_NEAR(t[1], 5.5, 1e-9);
    t = test::hit_depths(s, ray({-5, 0.1, 0.1}, {1, 0, 0}));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[1] - t[0], 2 + 2 * std::sqrt(0.25 - 0.02), 1e-9);
}

TEST(SphereSweep, LinearVaryingRadiusIsATangentCone) {
    // Spheres of radius 1 at 0 and 0.5 at 3: the side is the cone tangent to both; its
    // silhouette seen from far up y is at sin(angle) = 0.5 / 3 from the axis.
    auto s = sweep(scene::SweepSpline::Linear, {{{0, 0, 0}, 1}, {{3, 0, 0}, 0.5}});
    auto g = build_one(s);
    Hit h;
    const double sin_a = 0.5 / 3, cos_a = std::sqrt(1 - sin_a * sin_a);
    // The tangent line on the xy silhouette runs from (sin_a, cos_a) on the first sphere.
    const Vec3 p0(sin_a, cos_a, 0), p1 = Vec3(3, 0, 0) + Vec3(sin_a, cos_a, 0) * 0.5;
    Vec3 mid = (p0 + p1) * 0.5;
    Vec3 n(sin_a, cos_a, 0);
    ASSERT_TRUE(g->intersect(ray(mid + n * 4, n * -1), &h));
    EXPECT_NEAR(h.t, 4, 1e-9);
    EXPECT_NEAR(dot(h.ng, n), 1, 1e-9);
}

// ---- spline sweeps: hits on the envelope ---------------------------------------------------

// The signed distance from p to the union of a piece's spheres, min over u of |p - C(u)| - r(u),
// for C, r given by per-u callbacks: sampled, then narrowed around the best sample.
template <class Center, class Radius>
double envelope_distance(const Vec3& p, Center C, Radius R) {
    auto f = [&](double u) { return length(p - C(u)) - std::fabs(R(u)); };
    const int n = 400;
    int best = 0;
    for (int i = 1; i <= n; ++i)
        if (f(double(i) / n) < f(double(best) / n)) best = i;
    double lo = std::max(0.0, (best - 1.0) / n), hi = std::min(1.0, (best + 1.0) / n);
    for (int it = 0; it < 100; ++it) {
        double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        (f(m1) < f(m2) ? hi : lo) = f(m1) < f(m2) ? m2 : m1;
    }
    return f((lo + hi) / 2);
}

void expect_hits_on_envelope(scene::SweepSpline spline, const double m[4][4]) {
    std::vector<scene::Sphere> sp = {{{-3, 0, 0}, 0.3}, {{-1.5, 1, 0.5}, 0.5},
                                     {{0, -0.5, 0}, 0.7}, {{1.5, 0.8, -0.5}, 0.4},
                                     {{3, 0, 0.3}, 0.6}};
    auto s = sweep(spline, sp);
    auto g = build_one(s);
    auto C = [&](int i, double u) {
        Vec3 c;
        double pw[4] = {1, u, u * u, u * u * u};
        for (int k = 0; k < 4; ++k)
            for (int j = 0; j < 4; ++j) c += sp[i + j].center * (m[k][j] * pw[k]);
        return c;
    };
    auto R = [&](int i, double u) {
        double r = 0, pw[4] = {1, u, u * u, u * u * u};
        for (int k = 0; k < 4; ++k)
            for (int j = 0; j < 4; ++j) r += sp[i + j].radius * m[k][j] * pw[k];
        return r;
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(-1, 1);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
        Vec3 o = Vec3(U(rng) * 2, 4, -6);
        Vec3 target(U(rng) * 2, U(rng) * 0.8, U(rng) * 0.5);
        Vec3 d = normalize(target - o);
        Hit h;
        if (!g->intersect(ray(o, d), &h)) continue;
        ++hits;
        // Distance to the whole sweep: the nearest of its two pieces.
        double dist = kInfinity;
        for (int piece = 0; piece < 2; ++piece)
            dist = std::min(dist, envelope_distance(
                                      h.p, [&](double u) { return C(piece, u); },
                                      [&](double u) { return R(piece, u); }));
        EXPECT_NEAR(dist, 0, 1e-6) << "ray " << i;
        // Outward: the ray enters against the normal.
        EXPECT_LT(dot(h.ng, d), 0) << "ray " << i;
    }
    EXPECT_GT(hits, 50);
}

constexpr double kB[4][4] = {{1 / 6.0, 4 / 6.0, 1 / 6.0, 0},
                             {-3 / 6.0, 0, 3 / 6.0, 0},
                             {3 / 6.0, -6 / 6.0, 3 / 6.0, 0},
                             {-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0}};
constexpr double kCatmullRom[4][4] = {
    {0, 1, 0, 0}, {-0.5, 0, 0.5, 0}, {1, -2.5, 2, -0.5}, {-0.5, 1.5, -1.5, 0.5}};

TEST(SphereSweep, BSplineHitsLieOnTheEnvelope) {
    expect_hits_on_envelope(scene::SweepSpline::BSpline, kB);
}

TEST(SphereSweep, CubicSplineHitsLieOnTheEnvelope) {
    expect_hits_on_envelope(scene::SweepSpline::Cubic, kCatmullRom);
}

TEST(SphereSweep, EvenlySpacedSplinesAreCapsules) {
    // Collinear, evenly spaced, equal spheres: both splines run straight from the second
    // sphere's centre to the third's, so the sweep is the capsule between them.
    for (auto spline : {scene::SweepSpline::BSpline, scene::SweepSpline::Cubic}) {
        auto s = sweep(spline, {{{-1, 0, 0}, 0.5}, {{0, 0, 0}, 0.5}, {{1, 0, 0}, 0.5},
                                {{2, 0, 0}, 0.5}});
        auto g = build_one(s);
        Hit h;
        ASSERT_TRUE(g->intersect(ray({0.3, 4, 0}, {0, -1, 0}), &h));
        EXPECT_NEAR(h.t, 3.5, 1e-7);
        EXPECT_NEAR(h.ng.y, 1, 1e-6);
        ASSERT_TRUE(g->intersect(ray({-4, 0.1, 0}, {1, 0, 0}), &h));
        EXPECT_NEAR(h.t, 4 - std::sqrt(0.25 - 0.01), 1e-7);
        EXPECT_FALSE(g->intersect(ray({-0.6, 4, 0}, {0, -1, 0}), &h));  // before the piece
        EXPECT_TRUE(inside(s, {0.5, 0.3, 0}));
        EXPECT_FALSE(inside(s, {0.5, 0.6, 0}));
        EXPECT_FALSE(inside(s, {-0.7, 0, 0}));
    }
}

// ---- inside ------------------------------------------------------------------------------

TEST(SphereSweep, InsideAsPovRay) {
    auto s = sweep(scene::SweepSpline::Linear, {{{0, 0, 0}, 0.5}, {{2, 0, 0}, 0.5}});
    EXPECT_TRUE(inside(s, {1, 0.4, 0}));
    EXPECT_TRUE(inside(s, {1, 0, 0}));
    EXPECT_TRUE(inside(s, {-0.3, 0.2, 0}));  // in an end sphere
    EXPECT_FALSE(inside(s, {1, 0.6, 0}));
    EXPECT_FALSE(inside(s, {-0.6, 0, 0}));
    EXPECT_FALSE(inside(s, {5, 5, 5}));
    // POV-Ray calls a point inside when some sphere of the sweep has it on its surface; a point
    // that every sphere of a short fat piece holds has none, so it is outside (checked against
    // POV-Ray 3.7: an intersection with a small sphere there renders nothing).
    auto fat = sweep(scene::SweepSpline::Linear, {{{0, 0, 0}, 1}, {{0.5, 0, 0}, 1}});
    EXPECT_FALSE(inside(fat, {0.25, 0, 0}));
    EXPECT_TRUE(inside(fat, {0.25, 0.99, 0}));  // on the spheres of u = 0.22 and 0.78
}

TEST(SphereSweep, CsgDifferenceCutsIt) {
    // A capsule less a box over its middle: the ray down through the middle meets nothing of
    // the capsule's top, then the box's floor at y = -0.2 inside the capsule.
    scene::Csg d;
    d.op = scene::CsgOp::Difference;
    d.children.push_back(test::object(
        sweep(scene::SweepSpline::Linear, {{{0, 0, 0}, 0.5}, {{2, 0, 0}, 0.5}})));
    d.children.push_back(test::object(scene::Box{{0.5, -0.2, -1}, {1.5, 1, 1}}));
    auto g = build_one(d);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({1, 5, 0}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 5.2, 1e-9);
    ASSERT_TRUE(g->intersect(ray({-0.2, 5, 0}, {0, -1, 0}), &h));  // the uncut end sphere
    EXPECT_NEAR(h.p.y, std::sqrt(0.25 - 0.04), 1e-9);
}

TEST(SphereSweep, TooFewSpheresIsLeftOut) {
    auto s = sweep(scene::SweepSpline::Cubic, {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}});
    scene::Scene sc = test::scene_of({});
    scene::Object o = test::object(s);
    Diagnostics diag;
    EXPECT_EQ(render::ObjectNode::build(o, sc, diag), nullptr);
}

}  // namespace
}  // namespace glint
