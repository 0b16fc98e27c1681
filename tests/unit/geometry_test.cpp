// build_geometry() end to end: hit fields, transforms, ties, flags, material inheritance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/float.h"
#include "geom_test_util.h"

namespace glint {
namespace {

using render::Hit;
using test::build;
using test::build_one;
using test::object;
using test::ray;
using test::scene_of;

TEST(Geometry, SphereHitFields) {
    auto g = build_one(scene::Sphere{{0, 0, 0}, 2});
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -10}, {0, 0, 1}), &h));
    EXPECT_DOUBLE_EQ(h.t, 8);
    EXPECT_DOUBLE_EQ(h.p.z, -2);
    EXPECT_DOUBLE_EQ(h.ng.z, -1);
    EXPECT_DOUBLE_EQ(h.n.z, -1);
    EXPECT_EQ(h.object, 0);
    EXPECT_EQ(h.material, 0);
    EXPECT_TRUE(h.has_uv);
    EXPECT_GT(h.p_error.z, 0);
    EXPECT_LT(h.p_error.z, 1e-14);
}

TEST(Geometry, UnnormalizedDirectionKeepsTUnits) {
    auto g = build_one(scene::Sphere{{0, 0, 0}, 1});
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 4}), &h));
    EXPECT_DOUBLE_EQ(h.t, 1);
}

TEST(Geometry, TmaxLimitsHits) {
    auto g = build_one(scene::Sphere{{0, 0, 0}, 1});
    Hit h;
    EXPECT_FALSE(g->intersect(ray({0, 0, -5}, {0, 0, 1}, 3.9), &h));
    EXPECT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}, 4.1), &h));
    EXPECT_FALSE(g->occluded(ray({0, 0, -5}, {0, 0, 1}, 3.9)));
    EXPECT_TRUE(g->occluded(ray({0, 0, -5}, {0, 0, 1}, 4.1)));
}

TEST(Geometry, ScaledTranslatedSphere) {
    Transform xf = Transform::scale({2, 1, 1}).then(Transform::translate({10, 0, 0}));
    auto g = build_one(scene::Sphere{{0, 0, 0}, 1}, xf);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 8, 1e-12);
    EXPECT_NEAR(h.ng.x, -1, 1e-12);
    // On the ellipsoid's flank the normal is the inverse-transpose of the sphere's.
    ASSERT_TRUE(g->intersect(ray({10 + std::sqrt(2.0), 5, 0}, {0, -1, 0}), &h));
    Vec3 expect = normalize(Vec3(std::sqrt(0.5) / 2, std::sqrt(0.5), 0));
    EXPECT_NEAR(h.ng.x, expect.x, 1e-12);
    EXPECT_NEAR(h.ng.y, expect.y, 1e-12);
    EXPECT_NEAR(length(h.n), 1, 1e-14);
}

TEST(Geometry, PlaneInsideAndHit) {
    auto g = build_one(scene::Plane{{0, 1, 0}, -1});
    Hit h;
    ASSERT_TRUE(g->intersect(ray({3, 5, 2}, {0, -2, 0}), &h));
    EXPECT_DOUBLE_EQ(h.t, 3);
    EXPECT_EQ(h.p.y, -1);
    EXPECT_EQ(h.ng.y, 1);
    EXPECT_FALSE(h.has_uv);
    EXPECT_FALSE(g->intersect(ray({3, 5, 2}, {1, 0, 0}), &h));
    EXPECT_TRUE(std::isinf(g->bounds().hi.x));
}

TEST(Geometry, BoxFaces) {
    auto g = build_one(scene::Box{{-1, -2, -3}, {1, 2, 3}});
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -10}, {0, 0, 1}), &h));
    EXPECT_EQ(h.t, 7);
    EXPECT_EQ(h.ng, Vec3(0, 0, -1));
    ASSERT_TRUE(g->intersect(ray({0, 0, 0}, {0, 1, 0}), &h));
    EXPECT_EQ(h.t, 2);
    EXPECT_EQ(h.ng, Vec3(0, 1, 0));
    EXPECT_EQ(h.p, Vec3(0, 2, 0));
}

TEST(Geometry, ClosestObjectAndTieByIndex) {
    auto s = scene_of({object(scene::Sphere{{0, 0, 5}, 1}, {}, 1),
                       object(scene::Sphere{{0, 0, 2}, 1}, {}, 2),
                       object(scene::Box{{-1, -1, 1}, {1, 1, 3}}, {}, 3)});
    auto g = build(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 0, -10}, {0, 0, 1}), &h));
    EXPECT_EQ(h.t, 11);
    // Sphere 1 and the box touch z = 1 at the same t: the lower index wins.
    EXPECT_EQ(h.object, 1);
    EXPECT_EQ(h.material, 2);
}

TEST(Geometry, NoShadowObjectsDoNotOcclude) {
    auto s = scene_of({object(scene::Sphere{{0, 0, 0}, 1})});
    s.objects[0].no_shadow = true;
    auto g = build(s);
    Hit h;
    EXPECT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
    EXPECT_EQ(h.flags & render::kNoShadow, render::kNoShadow);
    EXPECT_FALSE(g->occluded(ray({0, 0, -5}, {0, 0, 1})));
}

TEST(Geometry, DegenerateRaysHitNothing) {
    auto g = test::build(scene_of({object(scene::Box{{-1, -1, -1}, {1, 1, 1}}),
                                   object(scene::Plane{{0, 1, 0}, -2})}));
    const double nan = std::nan("");
    Hit h;
    EXPECT_FALSE(g->intersect(ray({nan, 0, -5}, {0, 0, 1}), &h));
    EXPECT_FALSE(g->intersect(ray({0, 0, -5}, {0, nan, 1}), &h));
    EXPECT_FALSE(g->intersect(ray({0, 0, -5}, {0, 0, 0}), &h));
    EXPECT_FALSE(g->intersect(ray({0, kInfinity, -5}, {0, 0, 1}), &h));
    EXPECT_FALSE(g->occluded(ray({nan, 0, -5}, {0, 0, 1})));
    EXPECT_TRUE(g->intersect(ray({0, 0, -5}, {0, 0, 1}), &h));
}

TEST(Geometry, EmptySceneHitsNothing) {
    auto g = build(scene_of({}));
    Hit h;
    EXPECT_FALSE(g->intersect(ray({0, 0, 0}, {0, 0, 1}), &h));
    EXPECT_FALSE(g->occluded(ray({0, 0, 0}, {0, 0, 1})));
}


// Rays leaving hit points through offset_ray_origin() never re-hit the surface they leave, at
// any scale or distance from the origin (the integrators' contract: tmin 0, no epsilons).
struct AcneCase {
    const char* name;
    scene::Shape shape;
    bool convex;  // closed convex solid: outward rays escape, inward rays cross the interior
    bool two_sided_flat;  // flat surface: no re-hit in either direction
};

int acne_failures(const AcneCase& c, double scale, Vec3 shift, int* spawned) {
    // A skewed frame: rotated and non-uniformly scaled, then placed.
    Transform xf = Transform::rotate_xyz_degrees({20, 35, -40})
                       .then(Transform::scale(Vec3(1, 0.6, 1.7) * scale))
                       .then(Transform::rotate_axis({1, 2, 3}, 17))
                       .then(Transform::translate(shift));
    auto g = build_one(c.shape, xf);
    std::mt19937_64 rng(7);
    std::normal_distribution<double> nd;
    int fails = 0;
    for (int i = 0; i < 1000; ++i) {
        Vec3 o = shift + normalize(Vec3(nd(rng), nd(rng) + 2, nd(rng))) * (5 * scale);
        Vec3 target = shift + Vec3(nd(rng), nd(rng), nd(rng)) * (0.4 * scale);
        Hit h;
        if (!g->intersect(ray(o, target - o), &h)) continue;
        for (int k = 0; k < 8; ++k) {
            Vec3 w = normalize(Vec3(nd(rng), nd(rng), nd(rng)));
            Vec3 po = offset_ray_origin(h.p, h.p_error, h.ng, w);
            Hit h2;
            bool again = g->intersect(ray(po, w), &h2);
            ++*spawned;
            bool outward = dot(w, h.ng) > 0;
            if (c.two_sided_flat) {
                fails += again;
            } else if (c.convex && outward) {
                fails += again;
            } else if (c.convex) {
                // Inward: the far side, well away from the origin.
                fails += !again || h2.t < 1e-6 * scale;
            } else {
                fails += again && h2.t < 1e-6 * scale;
            }
        }
    }
    return fails;
}

// VALIDATION.md case 2: a ground plane seen from height 1 at grazing angles out to 1e5 units:
// shadow rays to a light above and mirror rays leave the plane without re-hitting it.
TEST(Geometry, GrazingGroundPlaneHasNoAcne) {
    for (scene::Plane plane : {scene::Plane{{0, 1, 0}, 0}, scene::Plane{{0.001, 1, 0.002}, -0.5}}) {
        auto g = build_one(plane);
        std::mt19937_64 rng(2);
        std::uniform_real_distribution<double> u(0, 1);
        int hits = 0, acne = 0;
        for (int i = 0; i < 20000; ++i) {
            double dist = std::pow(10.0, 5 * u(rng));  // 1 .. 1e5 away
            double az = 2 * kPi * u(rng);
            Vec3 o(3, 1, -2);
            Vec3 target(o.x + dist * std::cos(az), -0.5, o.z + dist * std::sin(az));
            Hit h;
            if (!g->intersect(ray(o, target - o), &h)) continue;
            ++hits;
            Vec3 d = normalize(target - o);
            Vec3 mirror = d - h.ng * (2 * dot(d, h.ng));
            Vec3 to_light = Vec3(0, 1e4, 0) - h.p;
            for (Vec3 w : {mirror, to_light}) {
                Vec3 po = offset_ray_origin(h.p, h.p_error, h.ng, w);
                Hit h2;
                acne += g->intersect(ray(po, w), &h2);
            }
        }
        EXPECT_GT(hits, 15000);
        EXPECT_EQ(acne, 0);
    }
}

// p_error bounds the hit point's distance to the true surface (measured in long double).
TEST(Geometry, ErrorBoundCoversTrueSurfaceDistance) {
    std::mt19937_64 rng(31);
    std::normal_distribution<double> nd;
    int checked = 0, violations = 0;
    for (double scale : {1e-4, 1.0, 1e4}) {
        Vec3 c = Vec3(1e5, -3e4, 7e4) * (scale >= 1 ? 1.0 : 1e-3);
        double r = 1.7 * scale;
        auto g = build_one(scene::Sphere{c, r});
        for (int i = 0; i < 2000; ++i) {
            Vec3 o = c + normalize(Vec3(nd(rng), nd(rng), nd(rng))) * (10 * r);
            Vec3 t = c + Vec3(nd(rng), nd(rng), nd(rng)) * (0.3 * r);
            Hit h;
            if (!g->intersect(ray(o, t - o), &h)) continue;
            ++checked;
            long double dx = (long double)h.p.x - c.x, dy = (long double)h.p.y - c.y,
                        dz = (long double)h.p.z - c.z;
            long double dist = std::fabs(std::sqrt(dx * dx + dy * dy + dz * dz) - r);
            if (dist > dot(abs(h.ng), h.p_error)) ++violations;
        }
    }
    EXPECT_GT(checked, 3000);
    EXPECT_EQ(violations, 0);
}

TEST(Geometry, NoSelfIntersectionAtAnyScale) {
    std::vector<AcneCase> cases = {
        {"sphere", scene::Sphere{{0.1, 0.2, 0.3}, 1}, true, false},
        {"box", scene::Box{{-1, -0.7, -1.2}, {0.9, 1, 1}}, true, false},
        {"cylinder", scene::Cylinder{{0, -1, 0}, {0.2, 1, 0.1}, 0.8, false}, true, false},
        {"cone", scene::Cone{{0, -1, 0}, 1, {0, 1, 0}, 0.3, false}, true, false},
        {"plane", scene::Plane{{0.2, 1, 0.1}, 0.05}, false, false},
        {"torus", scene::Torus{0.9, 0.35, false}, false, false},
        {"disc", scene::Disc{{0, 0, 0}, {0.3, 1, 0.2}, 1.5, 0.2}, false, true},
        {"triangle", scene::Triangle{{{-2, -0.3, -1}, {2, 0.2, -1.5}, {0, 0.1, 2}}}, false,
         true},
    };
    for (const auto& c : cases) {
        for (double scale : {1e-4, 1.0, 1e4}) {
            for (Vec3 shift : {Vec3(0, 0, 0), Vec3(1e5, -1e5, 1e5)}) {
                int spawned = 0;
                int fails = acne_failures(c, scale, shift, &spawned);
                EXPECT_EQ(fails, 0) << c.name << " scale " << scale << " shift " << shift.x;
                EXPECT_GT(spawned, 1000) << c.name;
            }
        }
    }
}

}  // namespace
}  // namespace glint
