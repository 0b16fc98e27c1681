// Every intersection routine against closed forms, plus VALIDATION.md cases 5 (axis-aligned
// rays through box faces and edges), 6 (grazing triangles) and 9 (camera inside a sphere).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/float.h"
#include "geom_test_util.h"
#include "render/shapes/mesh/mesh_prim.h"
#include "render/shapes/object_node.h"
#include "render/shapes/shapes.h"
#include "render/shapes/mesh/triangle.h"

namespace glint {
namespace {

using render::Hit;
using render::LocalHit;
using render::Ray;
using test::build_one;
using test::ray;
using test::unit_cube_mesh;

bool finite_hit(const Hit& h) {
    return std::isfinite(h.t) && is_finite(h.p) && is_finite(h.ng) && is_finite(h.n) &&
           is_finite(h.p_error) && std::isfinite(h.uv.x) && std::isfinite(h.uv.y);
}

void expect_vec(const Vec3& a, const Vec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// ---- sphere ------------------------------------------------------------------------------

TEST(Sphere, OffAxisChord) {
    auto g = build_one(scene::Sphere{{1, 2, 3}, 2});
    Hit h;
    // Line at distance 1 from the centre: half chord sqrt(3).
    ASSERT_TRUE(g->intersect(ray({-10, 3, 3}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 11 - std::sqrt(3.0), 1e-14);
    expect_vec(h.ng, normalize(Vec3(-std::sqrt(3.0), 1, 0)), 1e-14);
    EXPECT_FALSE(g->intersect(ray({-10, 4.0001, 3}, {1, 0, 0}), &h));
}

TEST(Sphere, UvFollowsPovRay) {
    auto g = build_one(scene::Sphere{{0, 0, 0}, 1});
    Hit h;
    ASSERT_TRUE(g->intersect(ray({5, 0, 0}, {-1, 0, 0}), &h));  // +x: u 0, v 0.5
    EXPECT_NEAR(h.uv.x, 0, 1e-12);
    EXPECT_NEAR(h.uv.y, 0.5, 1e-12);
    ASSERT_TRUE(g->intersect(ray({0, 0, 5}, {0, 0, -1}), &h));  // +z: u 0.25
    EXPECT_NEAR(h.uv.x, 0.25, 1e-12);
    ASSERT_TRUE(g->intersect(ray({0, 5, 0}, {0, -1, 0}), &h));  // north pole: v 1
    EXPECT_NEAR(h.uv.y, 1, 1e-12);
}

// VALIDATION.md case 9: every ray from the centre hits at t within 4 ulp of the radius.
TEST(Sphere, CameraInsideHitsAtRadius) {
    std::mt19937_64 rng(9);
    std::normal_distribution<double> nd;
    int bad = 0, total = 0;
    for (double r : {1e-4, 0.3, 1.0, 7.0, 1e4}) {
        for (Vec3 c : {Vec3(0, 0, 0), Vec3(0.5, -3, 2), Vec3(1e3, 1e3, -1e3)}) {
            auto g = build_one(scene::Sphere{c, r});
            for (int i = 0; i < 2000; ++i) {
                Vec3 d = normalize(Vec3(nd(rng), nd(rng), nd(rng)));
                Hit h;
                ++total;
                if (!g->intersect(ray(c, d), &h)) {
                    ++bad;
                    continue;
                }
                double ulp = next_up(r) - r;
                if (std::fabs(h.t - r) > 4 * ulp) ++bad;
                // Seen from inside, the normal still points out of the solid.
                if (!(dot(h.ng, d) > 0.999999)) ++bad;
            }
        }
    }
    EXPECT_EQ(bad, 0) << "of " << total;
}

// ---- box ---------------------------------------------------------------------------------

// VALIDATION.md case 5: rays along the axes with the other direction components exactly 0,
// through faces, along faces and along edges. Analytic count: 2 if the ray's line meets the
// closed box, else 0.
TEST(Box, AxisAlignedRaysFacesAndEdges) {
    auto prim = render::make_box(scene::Box{{-1, -1, -1}, {1, 1, 1}});
    const double coords[] = {-2, -1, -0.5, 0, 0.5, 1, 2};
    int checked = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0})
            for (double a : coords)
                for (double b : coords) {
                    Vec3 o, d;
                    o[axis] = -5 * sign;
                    o[(axis + 1) % 3] = a;
                    o[(axis + 2) % 3] = b;
                    d[axis] = sign;
                    render::HitList hits;
                    prim->intersect_all(ray(o, d), kInfinity, &hits);
                    int expect = (std::fabs(a) <= 1 && std::fabs(b) <= 1) ? 2 : 0;
                    EXPECT_EQ(static_cast<int>(hits.size()), expect) << axis << " " << a << " " << b;
                    for (const auto& h : hits) {
                        EXPECT_TRUE(std::isfinite(h.t) && is_finite(h.p) && is_finite(h.ng));
                        EXPECT_EQ(std::fabs(h.p[axis]), 1.0);
                        EXPECT_TRUE(h.t == 4 || h.t == 6);
                    }
                    ++checked;
                }
    EXPECT_EQ(checked, 3 * 2 * 49);
}

TEST(Box, DiagonalRayThroughEdge) {
    auto prim = render::make_box(scene::Box{{-1, -1, -1}, {1, 1, 1}});
    render::HitList hits;
    // Through the edge x = 1, y = 1 exactly: it touches the box in one point.
    prim->intersect_all(ray({0, 2, 0}, {1, -1, 0}), kInfinity, &hits);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].t, 1);
    EXPECT_EQ(hits[1].t, 1);
    for (const auto& h : hits) EXPECT_TRUE(is_finite(h.p) && is_finite(h.ng));
}

// A flat box (both corners' z equal) is a sheet: a ray is first met on the face it comes
// from, whichever way it goes, so a refracting sheet is entered and then left.
TEST(Box, FlatBoxIsEnteredFromTheRaysSide) {
    auto prim = render::make_box(scene::Box{{-1, -1, 0.25}, {1, 1, 0.25}});
    for (double dz : {-1.0, 1.0}) {
        render::HitList hits;
        prim->intersect_all(ray({0, 0, 0.25 - 3 * dz}, normalize(Vec3(0, 0.2, dz))),
                            kInfinity, &hits);
        ASSERT_EQ(hits.size(), 2u);
        EXPECT_EQ(hits[0].t, hits[1].t);
        EXPECT_EQ(hits[0].ng.z, -dz);  // facing the ray: entering
        EXPECT_EQ(hits[1].ng.z, dz);
    }
}

TEST(Box, InsideAndUv) {
    auto prim = render::make_box(scene::Box{{1, 1, 1}, {-1, -1, -1}});
    EXPECT_TRUE(prim->inside({0, 0, 0}));
    EXPECT_TRUE(prim->inside({1, 1, 1}));
    EXPECT_FALSE(prim->inside({1.01, 0, 0}));
    LocalHit h;
    ASSERT_TRUE(prim->intersect(ray({0, 0, -5}, {0, 0, 1}), kInfinity, &h));
    // POV-Ray's SIDE_Z_0 face: u = 1 - x/4 with x normalized to [0, 1]: 1 - 0.5/4.
    EXPECT_NEAR(h.uv.x, 1 - 0.125, 1e-15);
    EXPECT_NEAR(h.uv.y, 1.0 / 3 + 0.5 / 3, 1e-15);
}

// ---- cylinder, cone, disc ------------------------------------------------------------------

TEST(Cylinder, SideAndCaps) {
    scene::Cylinder c{{0, 0, 0}, {0, 2, 0}, 1, false};
    auto g = build_one(c);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-5, 1, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 4, 1e-14);
    expect_vec(h.ng, {-1, 0, 0}, 1e-14);
    ASSERT_TRUE(g->intersect(ray({0.5, 5, 0}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 3, 1e-14);
    expect_vec(h.ng, {0, 1, 0}, 1e-14);
    ASSERT_TRUE(g->intersect(ray({0.5, -5, 0.1}, {0, 1, 0}), &h));
    EXPECT_NEAR(h.t, 5, 1e-14);
    expect_vec(h.ng, {0, -1, 0}, 1e-14);
    // From inside: the far side.
    ASSERT_TRUE(g->intersect(ray({0, 1, 0}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 1, 1e-14);
    expect_vec(h.ng, {0, 0, 1}, 1e-14);
}

TEST(Cylinder, OpenHasNoCaps) {
    scene::Cylinder c{{0, 0, 0}, {0, 2, 0}, 1, true};
    auto g = build_one(c);
    Hit h;
    EXPECT_FALSE(g->intersect(ray({0.5, 5, 0}, {0, -1, 0}), &h));
    // Slanted ray through the open top hits the inside wall.
    ASSERT_TRUE(g->intersect(ray({0, 3, 0}, {1, -1, 0}), &h));
    EXPECT_NEAR(h.t, 1, 1e-14);
    expect_vec(h.ng, {1, 0, 0}, 1e-14);  // outward, facing away from the ray
}

TEST(Cylinder, ArbitraryAxis) {
    Vec3 a(1, 1, 1), b(3, 4, 5);
    scene::Cylinder c{a, b, 0.5, false};
    auto g = build_one(c);
    Vec3 axis = normalize(b - a);
    Vec3 perp = normalize(cross(axis, Vec3(0, 0, 1)));
    Vec3 mid = (a + b) * 0.5;
    Hit h;
    ASSERT_TRUE(g->intersect(ray(mid + perp * 10, -perp), &h));
    EXPECT_NEAR(h.t, 9.5, 1e-12);
    expect_vec(h.ng, perp, 1e-12);
    // Along the axis from beyond the cap.
    ASSERT_TRUE(g->intersect(ray(b + axis * 2, -axis), &h));
    EXPECT_NEAR(h.t, 2, 1e-12);
    expect_vec(h.ng, axis, 1e-12);
}

TEST(Cone, SideApexAndBase) {
    scene::Cone c{{0, 0, 0}, 1, {0, 1, 0}, 0, false};
    auto g = build_one(c);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({-5, 0.5, 0}, {1, 0, 0}), &h));
    EXPECT_NEAR(h.t, 4.5, 1e-14);
    expect_vec(h.ng, normalize(Vec3(-1, 1, 0)), 1e-14);
    ASSERT_TRUE(g->intersect(ray({0.2, -5, 0}, {0, 1, 0}), &h));
    EXPECT_NEAR(h.t, 5, 1e-14);
    expect_vec(h.ng, {0, -1, 0}, 1e-14);
    ASSERT_TRUE(g->intersect(ray({0, 5, 0}, {0, -1, 0}), &h));  // the apex
    EXPECT_NEAR(h.t, 4, 1e-9);
    EXPECT_TRUE(finite_hit(h));
    EXPECT_FALSE(g->intersect(ray({-5, 1.01, 0}, {1, 0, 0}), &h));
}

TEST(Cone, Frustum) {
    // Radius 2 at y = 0 to radius 1 at y = 2: at y = 1 radius 1.5.
    scene::Cone c{{0, 0, 0}, 2, {0, 2, 0}, 1, true};
    auto g = build_one(c);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 1, -5}, {0, 0, 1}), &h));
    EXPECT_NEAR(h.t, 3.5, 1e-14);
    expect_vec(h.ng, normalize(Vec3(0, 0.5, -1)), 1e-14);
    EXPECT_FALSE(g->intersect(ray({0.1, 5, 0}, {0, -1, 0}), &h));  // open
}

TEST(Disc, RingAndHole) {
    scene::Disc d{{0, 1, 0}, {0, 2, 0}, 2, 1};
    auto g = build_one(d);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({1.5, 5, 0}, {0, -1, 0}), &h));
    EXPECT_NEAR(h.t, 4, 1e-14);
    expect_vec(h.ng, {0, 1, 0}, 1e-14);
    EXPECT_FALSE(g->intersect(ray({0.5, 5, 0}, {0, -1, 0}), &h));
    EXPECT_FALSE(g->intersect(ray({2.5, 5, 0}, {0, -1, 0}), &h));
    ASSERT_TRUE(g->intersect(ray({0, -5, -1.5}, {0, 1, 0}), &h));  // from below
    expect_vec(h.ng, {0, 1, 0}, 1e-14);
}

// ---- torus -------------------------------------------------------------------------------

TEST(Torus, FourHitsAlongX) {
    auto prim = render::make_torus(scene::Torus{2, 0.5, false});
    render::HitList hits;
    prim->intersect_all(ray({-5, 0, 0}, {1, 0, 0}), kInfinity, &hits);
    ASSERT_EQ(hits.size(), 4u);
    const double expect[] = {2.5, 3.5, 6.5, 7.5};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(hits[i].t, expect[i], 1e-13);
    expect_vec(hits[0].ng, {-1, 0, 0}, 1e-13);
    expect_vec(hits[1].ng, {1, 0, 0}, 1e-13);
    EXPECT_TRUE(prim->inside({2, 0, 0}));
    EXPECT_FALSE(prim->inside({0, 0, 0}));
}

TEST(Torus, TopOfTubeAndScaledDirection) {
    auto g = build_one(scene::Torus{2, 0.5, false});
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0, 5, 2}, {0, -3, 0}), &h));
    EXPECT_NEAR(h.t, 1.5, 1e-14);
    expect_vec(h.ng, {0, 1, 0}, 1e-13);
    // POV-Ray's torus uv: u from the angle around y, v around the tube.
    EXPECT_TRUE(h.has_uv);
    EXPECT_NEAR(h.uv.x, 0.25, 1e-12);
    EXPECT_NEAR(h.uv.y, 0.75, 1e-12);
}

// Near-tangent rays over the top of the tube (y -> 0.5 from below) must keep both hits: the
// chord length follows the closed form 2 sqrt(r^2 - y^2) per tube crossing.
TEST(Torus, SilhouetteRaysKeepTheirHits) {
    auto prim = render::make_torus(scene::Torus{2, 0.5, false});
    for (double gap : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10}) {
        double y = 0.5 - gap;
        render::HitList hits;
        prim->intersect_all(ray({-5, y, 0}, {1, 0, 0}), kInfinity, &hits);
        ASSERT_EQ(hits.size(), 4u) << gap;
        double half = std::sqrt(0.25 - y * y);
        EXPECT_NEAR(hits[0].t, 3 - half, 1e-7) << gap;
        EXPECT_NEAR(hits[1].t, 3 + half, 1e-7) << gap;
        for (const auto& hh : hits) EXPECT_TRUE(is_finite(hh.p) && is_finite(hh.ng));
    }
    render::HitList hits;
    prim->intersect_all(ray({-5, 0.5 + 1e-9, 0}, {1, 0, 0}), kInfinity, &hits);
    EXPECT_EQ(hits.size(), 0u);
}

TEST(Torus, RandomRaysLandOnTheSurface) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(-1, 1);
    for (double scale : {1e-3, 1.0, 1e3}) {
        auto prim = render::make_torus(scene::Torus{2 * scale, 0.7 * scale, false});
        int hits_seen = 0;
        for (int i = 0; i < 3000; ++i) {
            Vec3 o(u(rng) * 6 * scale, u(rng) * 6 * scale, u(rng) * 6 * scale);
            Vec3 target(u(rng) * 2.7 * scale, u(rng) * 0.7 * scale, u(rng) * 2.7 * scale);
            render::HitList hits;
            prim->intersect_all(ray(o, target - o), kInfinity, &hits);
            for (const auto& h : hits) {
                ++hits_seen;
                double w = std::sqrt(h.p.x * h.p.x + h.p.z * h.p.z) - 2 * scale;
                double dist = std::fabs(std::sqrt(w * w + h.p.y * h.p.y) - 0.7 * scale);
                ASSERT_LE(dist, 1e-12 * scale);
                // The point the ray parameter gives is on the surface too.
                Vec3 q = o + (target - o) * h.t;
                ASSERT_LE(length(q - h.p), 1e-9 * scale);
            }
        }
        EXPECT_GT(hits_seen, 1000);
    }
}

// Extreme radius ratios keep the quartic well conditioned: closed-form hits along x.
TEST(Torus, ExtremeRadiusRatios) {
    for (auto [R, r] : {std::pair{1e4, 1.0}, std::pair{1.0, 1e-4}, std::pair{1e-3, 9e-4}}) {
        auto prim = render::make_torus(scene::Torus{R, r, false});
        render::HitList hits;
        double o = -3 * (R + r);
        prim->intersect_all(ray({o, 0, 0}, {1, 0, 0}), kInfinity, &hits);
        ASSERT_EQ(hits.size(), 4u) << R << " " << r;
        const double expect[] = {-R - r, -R + r, R - r, R + r};
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(hits[i].t, expect[i] - o, 1e-13 * (R + r)) << R << " " << r << " " << i;
    }
}

// Random rays on cylinders and cones at several scales land on the surface.
TEST(Quadrics, RandomHitsLieOnTheSurface) {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-1, 1);
    for (double s : {1e-4, 1.0, 1e4}) {
        scene::Cone cone{{0, -s, 0}, 0.8 * s, {0, s, 0}, 0.2 * s, false};
        Transform frame;
        const char* why = nullptr;
        auto prim = render::make_cone(cone, &frame, &why);
        ASSERT_TRUE(prim);
        int seen = 0;
        for (int i = 0; i < 3000; ++i) {
            Vec3 o(u(rng) * 4 * s, u(rng) * 4 * s, u(rng) * 4 * s);
            Vec3 target(u(rng) * 0.5 * s, u(rng) * s, u(rng) * 0.5 * s);
            Ray wr{o, target - o, kInfinity};
            Ray lr{frame.inverse_point(wr.origin), frame.inverse_vector(wr.dir), kInfinity};
            render::HitList hits;
            prim->intersect_all(lr, kInfinity, &hits);
            for (const auto& h : hits) {
                ++seen;
                Vec3 p = frame.point(h.p);
                double rad = std::sqrt(p.x * p.x + p.z * p.z);
                bool on_cap = std::fabs(std::fabs(p.y) - s) <= 1e-12 * s;
                double want = 0.8 * s - 0.3 * (p.y + s);
                if (!on_cap) {
                    ASSERT_NEAR(rad, want, 1e-12 * s);
                }
                ASSERT_LE(length(wr.origin + wr.dir * h.t - p), 1e-9 * s);
            }
        }
        EXPECT_GT(seen, 1000);
    }
}

// ---- triangles ---------------------------------------------------------------------------

TEST(Triangle, ClosedFormHit) {
    scene::Triangle tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    auto g = build_one(tri);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0.25, 0.25, 2}, {0, 0, -1}), &h));
    EXPECT_DOUBLE_EQ(h.t, 2);
    expect_vec(h.p, {0.25, 0.25, 0}, 1e-15);
    expect_vec(h.ng, {0, 0, 1}, 0);
    EXPECT_FALSE(g->intersect(ray({0.6, 0.6, 2}, {0, 0, -1}), &h));
}

TEST(SmoothTriangle, InterpolatedNormalOnNgSide) {
    scene::SmoothTriangle tri{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                              {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}};
    auto g = build_one(tri);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0.5, 0, 2}, {0, 0, -1}), &h));
    expect_vec(h.n, normalize(Vec3(0.5, 0, 1)), 1e-14);
    // Vertex normals on the other side are flipped to ng's side.
    scene::SmoothTriangle flip{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                               {{0, 0, -1}, {0, 0, -1}, {0, 0, -1}}};
    g = build_one(flip);
    ASSERT_TRUE(g->intersect(ray({0.2, 0.2, 2}, {0, 0, -1}), &h));
    expect_vec(h.n, {0, 0, 1}, 0);
}

// VALIDATION.md case 6: grazing and edge-on triangles: no NaN, barycentrics in [0, 1].
TEST(Triangle, GrazingAndEdgeOn) {
    Vec3 p[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    int hits = 0;
    for (double dz : {0.0, 1e-7, -1e-7, 1e-12, -1e-12}) {
        for (double y0 : {0.0, 0.1, 0.5, 1.0}) {
            render::Ray r{{-1, y0, 0}, {1, 0, dz}, kInfinity};
            r.origin.z = -dz;  // crosses z = 0 at x = 0
            render::RayShear s(r);
            render::TriangleHit th;
            if (render::intersect_triangle(s, p[0], p[1], p[2], kInfinity, &th)) {
                ++hits;
                ASSERT_TRUE(std::isfinite(th.t));
                for (double b : th.b) {
                    ASSERT_GE(b, 0);
                    ASSERT_LE(b, 1);
                }
            }
            // In the plane itself (dz = 0): edge-on, no hit and no NaN.
            if (dz == 0) {
                EXPECT_FALSE(render::intersect_triangle(s, p[0], p[1], p[2], kInfinity, &th));
            }
        }
    }
    EXPECT_GT(hits, 0);
}

// Rays through a shared edge or vertex of a fan never fall through (watertightness).
TEST(Triangle, WatertightFan) {
    scene::Mesh m;
    const int k = 7;
    m.positions.push_back({0, 0, 0});
    for (int i = 0; i < k; ++i) {
        double a = 2 * kPi * i / k;
        m.positions.push_back({std::cos(a), std::sin(a), 0});
    }
    for (int i = 0; i < k; ++i) {
        scene::MeshFace f;
        f.v = {0, 1 + i, 1 + (i + 1) % k};
        m.faces.push_back(f);
    }
    Diagnostics diag;
    auto prim = render::make_mesh(m, diag);
    ASSERT_TRUE(prim);
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u(-3, 3);
    int leaks = 0;
    for (int i = 0; i < 20000; ++i) {
        // Aim at the centre vertex or at a point on a spoke edge.
        Vec3 target = (i % 2) ? Vec3(0, 0, 0) : m.positions[1 + i % k] * (0.3 + 0.6 * (i % 5) / 5);
        Vec3 o(u(rng), u(rng), 1 + std::fabs(u(rng)));
        LocalHit h;
        if (!prim->intersect(ray(o, target - o), kInfinity, &h)) ++leaks;
    }
    EXPECT_EQ(leaks, 0);
}

// VALIDATION.md case 4: rays from inside a closed mesh aimed exactly at its vertices and edges
// never leak out.
TEST(Mesh, ClosedMeshDoesNotLeakAtVerticesAndEdges) {
    // A UV sphere closed by pole vertices, slightly irregular so edges are not axis-aligned.
    const int n = 24;
    scene::Mesh m;
    m.positions.push_back({0, 1, 0});
    for (int i = 1; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            double th = kPi * i / n, ph = kPi * j / n + 0.01 * i;
            double r = 1 + 0.03 * std::sin(3 * ph + i);
            m.positions.push_back({r * std::sin(th) * std::cos(ph), r * std::cos(th),
                                   r * std::sin(th) * std::sin(ph)});
        }
    m.positions.push_back({0, -1, 0});
    auto ring = [&](int i, int j) { return 1 + (i - 1) * 2 * n + (j % (2 * n)); };
    auto add = [&](int a, int b, int c) {
        scene::MeshFace f;
        f.v = {a, b, c};
        m.faces.push_back(f);
    };
    int south = static_cast<int>(m.positions.size()) - 1;
    for (int j = 0; j < 2 * n; ++j) {
        add(0, ring(1, j + 1), ring(1, j));
        add(south, ring(n - 1, j), ring(n - 1, j + 1));
        for (int i = 1; i < n - 1; ++i) {
            add(ring(i, j), ring(i, j + 1), ring(i + 1, j + 1));
            add(ring(i, j), ring(i + 1, j + 1), ring(i + 1, j));
        }
    }
    Diagnostics diag;
    auto prim = render::make_mesh(m, diag);
    ASSERT_TRUE(prim);
    std::mt19937_64 rng(44);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    std::uniform_int_distribution<size_t> pick(0, m.faces.size() - 1);
    int leaks = 0, rays = 0;
    for (int i = 0; i < 100000; ++i) {
        const scene::MeshFace& f = m.faces[pick(rng)];
        Vec3 a = m.positions[f.v[0]], b = m.positions[f.v[1]];
        Vec3 target = (i % 2) ? a : a + (b - a) * 0.5;  // a vertex or an edge midpoint
        if (i % 4 == 3) target = a + (b - a) * 0.37;
        Vec3 o(u(rng), u(rng), u(rng));
        LocalHit h;
        ++rays;
        if (!prim->intersect(ray(o, target - o), kInfinity, &h)) ++leaks;
    }
    EXPECT_EQ(leaks, 0) << "of " << rays;
}

// ---- meshes ------------------------------------------------------------------------------

scene::Mesh unit_square() {
    scene::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    scene::MeshFace a, b;
    a.v = {0, 1, 2};
    a.uv = {0, 1, 2};
    b.v = {0, 2, 3};
    b.uv = {0, 2, 3};
    b.material = 2;
    m.faces = {a, b};
    return m;
}

TEST(Mesh, UvAndPerFaceMaterial) {
    scene::Scene s = test::scene_with(test::object(scene::MeshRef{0}, {}, 1));
    s.meshes.push_back(unit_square());
    auto g = test::build(s);
    Hit h;
    ASSERT_TRUE(g->intersect(ray({0.75, 0.25, 1}, {0, 0, -1}), &h));
    EXPECT_EQ(h.material, 1);  // face without its own: the object's
    EXPECT_TRUE(h.has_uv);
    EXPECT_NEAR(h.uv.x, 0.75, 1e-15);
    EXPECT_NEAR(h.uv.y, 0.25, 1e-15);
    ASSERT_TRUE(g->intersect(ray({0.25, 0.75, 1}, {0, 0, -1}), &h));
    EXPECT_EQ(h.material, 2);
    // Any-hit queries respect tmax.
    EXPECT_FALSE(g->occluded(ray({0.25, 0.75, 1}, {0, 0, -1}, 0.999)));
    EXPECT_TRUE(g->occluded(ray({0.25, 0.75, 1}, {0, 0, -1}, 1.001)));
    EXPECT_FALSE(g->occluded(ray({1.25, 0.75, 1}, {0, 0, -1})));
}

TEST(Mesh, InterpolatedNormals) {
    scene::Mesh m = unit_square();
    m.normals = {{0, 0, 1}, {1, 0, 1}};
    m.faces[0].n = {0, 1, 1};
    Diagnostics diag;
    auto prim = render::make_mesh(m, diag);
    LocalHit h;
    ASSERT_TRUE(prim->intersect(ray({1, 0.5, 1}, {0, 0, -1}), kInfinity, &h));
    expect_vec(h.n, normalize(Vec3(1, 0, 1)), 1e-14);
}

TEST(Mesh, DegenerateFacesSkippedWithWarning) {
    scene::Mesh m = unit_square();
    m.positions.push_back({kInfinity, 0, 0});
    m.positions.push_back({std::nan(""), 0, 0});
    scene::MeshFace zero, inf, nan;
    zero.v = {0, 1, 1};
    inf.v = {0, 1, 4};
    nan.v = {5, 1, 2};
    m.faces.push_back(zero);
    m.faces.push_back(inf);
    m.faces.push_back(nan);
    Diagnostics diag;
    auto prim = render::make_mesh(m, diag);
    ASSERT_TRUE(prim);
    EXPECT_GE(diag.warning_count(), 1);
    LocalHit h;
    EXPECT_TRUE(prim->intersect(ray({0.5, 0.4, 1}, {0, 0, -1}), kInfinity, &h));
    EXPECT_TRUE(is_finite(prim->bounds().lo) && is_finite(prim->bounds().hi));
}

TEST(Mesh, SkippedFacesAreNamedByTheirObject) {
    // An OBJ object's name leads the warning (the Blender add-on turns it into the Blender
    // object's); POV-Ray's meshes have none and say nothing more.
    for (const std::string name : {"Sliver", ""}) {
        scene::Mesh m = unit_square();
        m.name = name;
        scene::MeshFace zero;
        zero.v = {0, 1, 1};
        m.faces.push_back(zero);
        Diagnostics diag;
        ASSERT_TRUE(render::make_mesh(m, diag));
        ASSERT_EQ(diag.warning_count(), 1);
        const std::string& said = diag.all().front().message;
        EXPECT_EQ(said.rfind("object 'Sliver': 1 degenerate", 0) == 0, !name.empty()) << said;
        EXPECT_EQ(said.rfind("1 degenerate", 0) == 0, name.empty()) << said;
    }
}

TEST(Mesh, EmptyMeshIsSkippedNotFatal) {
    scene::Scene s = test::scene_with(test::object(scene::MeshRef{0}));
    s.meshes.emplace_back();
    Diagnostics diag;
    auto g = render::build_geometry(s, scene::analyze(s), diag);
    EXPECT_GE(diag.warning_count(), 1);
    Hit h;
    EXPECT_FALSE(g->intersect(ray({0, 0, 1}, {0, 0, -1}), &h));
}

TEST(Mesh, InsideVectorParity) {
    // A closed unit cube from 12 triangles.
    scene::Mesh m = unit_cube_mesh();
    Diagnostics diag;
    auto without = render::make_mesh(m, diag);
    EXPECT_FALSE(without->inside({0.5, 0.5, 0.5}));
    m.has_inside_vector = true;
    m.inside_vector = {0.3, 0.2, 1};
    auto with = render::make_mesh(m, diag);
    EXPECT_TRUE(with->inside({0.5, 0.5, 0.5}));
    EXPECT_TRUE(with->inside({0.1, 0.9, 0.2}));
    EXPECT_FALSE(with->inside({1.5, 0.5, 0.5}));
    EXPECT_FALSE(with->inside({0.5, 0.5, -0.5}));
}

// A closed, irregular UV sphere with per-vertex normals and uvs (for the baking tests).
scene::Mesh smooth_uv_sphere(int n) {
    scene::Mesh m;
    auto vertex = [&](int i, int j) {
        double th = kPi * i / n, ph = 2 * kPi * j / (2 * n) + 0.013 * i;
        double r = 1 + 0.05 * std::sin(3 * ph + i) + 0.02 * std::cos(5 * th);
        Vec3 p(r * std::sin(th) * std::cos(ph), r * std::cos(th), r * std::sin(th) * std::sin(ph));
        m.positions.push_back(p + Vec3(0.3, -0.2, 0.1));
        m.normals.push_back(normalize(p + Vec3(0.02 * std::sin(7.0 * j), 0, 0)));
        m.uvs.push_back({static_cast<double>(j) / (2 * n), static_cast<double>(i) / n});
    };
    // Rings i = 0..n with 2n + 1 vertices each (the seam duplicated for the uvs).
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= 2 * n; ++j) vertex(i, j);
    auto id = [&](int i, int j) { return i * (2 * n + 1) + j; };
    auto add = [&](int a, int b, int c, int material) {
        scene::MeshFace f;
        f.v = f.n = f.uv = {a, b, c};
        f.material = material;
        m.faces.push_back(f);
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            if (i > 0) add(id(i, j), id(i, j + 1), id(i + 1, j + 1), j % 3);
            if (i < n - 1) add(id(i, j), id(i + 1, j + 1), id(i + 1, j), -1);
        }
    m.has_inside_vector = true;
    m.inside_vector = {0.31, 0.77, -0.2};
    return m;
}

void expect_same_bits(const LocalHit& a, const LocalHit& b) {
    EXPECT_EQ(a.t, b.t);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(a.p[k], b.p[k]);
        EXPECT_EQ(a.p_error[k], b.p_error[k]);
        EXPECT_EQ(a.ng[k], b.ng[k]);
        EXPECT_EQ(a.n[k], b.n[k]);
        EXPECT_EQ(a.dpdu[k], b.dpdu[k]);
        EXPECT_EQ(a.dpdv[k], b.dpdv[k]);
    }
    EXPECT_EQ(a.has_uv, b.has_uv);
    EXPECT_EQ(a.uv.x, b.uv.x);
    EXPECT_EQ(a.uv.y, b.uv.y);
    EXPECT_EQ(a.material, b.material);
}

// What a pure mirror does to an object-space hit, exactly: the mirrored components flip and
// nothing rounds, so the point keeps its error bound. Checks too that the bound is no looser
// than the general path's (transform_hit), which a baked mesh no longer takes.
void mirror_hit(const Transform& xf, LocalHit* h) {
    LocalHit general = *h;
    render::transform_hit(xf, &general);
    for (int k = 0; k < 3; ++k) {
        if (!(xf.matrix().m[k][k] < 0)) continue;
        h->p[k] = -h->p[k];
        h->ng[k] = -h->ng[k];
        h->n[k] = -h->n[k];
        h->dpdu[k] = -h->dpdu[k];
        h->dpdv[k] = -h->dpdv[k];
    }
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(h->p[k], general.p[k]);
        EXPECT_LE(h->p_error[k], general.p_error[k]);
    }
}

// A mesh with obj_file's z-mirror (or any other mirror) baked into its vertices answers every
// query bit for bit as the object-space mesh behind the transform does: same t, point, normals
// (pointing the same way despite the flipped winding), uvs and tangents, and the exact mirror of
// its error bound (mirror_hit).
TEST(Mesh, BakedMirrorMatchesTransformedMesh) {
    const scene::Mesh m = smooth_uv_sphere(12);
    Diagnostics diag;
    auto plain = render::make_mesh(m, diag);
    ASSERT_TRUE(plain);
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    std::uniform_int_distribution<size_t> pick(0, m.faces.size() - 1);
    for (Vec3 s : {Vec3(1, 1, -1), Vec3(-1, 1, 1), Vec3(1, -1, -1), Vec3(-1, -1, -1)}) {
        const Transform xf = Transform::scale(s);
        ASSERT_TRUE(render::bake_exact(xf));
        auto baked = render::make_mesh(m, diag, &xf);
        ASSERT_TRUE(baked);
        // The baked bounds are the mirrored object-space bounds.
        Bounds3 want = xf.bounds(plain->bounds()), got = baked->bounds();
        for (int k = 0; k < 3; ++k) {
            EXPECT_LE(want.lo[k], got.lo[k]);
            EXPECT_GE(want.hi[k], got.hi[k]);
        }
        int hits = 0, occluded = 0, inside = 0;
        for (int i = 0; i < 6000; ++i) {
            // Rays from inside and outside, aimed at vertices, edges and faces, some stopped
            // short (occlusion) and some along an axis.
            const scene::MeshFace& f = m.faces[pick(rng)];
            const Vec3 a = m.positions[f.v[0]], b = m.positions[f.v[1]];
            Vec3 target = i % 3 == 0 ? a : (i % 3 == 1 ? a + (b - a) * 0.5 : a + (b - a) * 0.37);
            Vec3 o(u(rng), u(rng), u(rng));
            if (i % 2) o = o * 3;
            Vec3 d = target - o;
            if (i % 50 == 0) d = Vec3(0, 0, i % 100 == 0 ? 1 : -1);
            const double tmax = i % 5 == 0 ? 0.7 : kInfinity;
            // World-space ray and the object-space one ObjectNode would build.
            const Vec3 wo = xf.point(o), wd = xf.vector(d);
            const Ray local{xf.inverse_point(wo), xf.inverse_vector(wd), kInfinity};
            const Ray world{wo, wd, kInfinity};
            LocalHit h0, h1;
            const bool f0 = plain->intersect(local, tmax, &h0);
            const bool f1 = baked->intersect(world, tmax, &h1);
            ASSERT_EQ(f0, f1) << i;
            if (f0) {
                ++hits;
                mirror_hit(xf, &h0);
                expect_same_bits(h0, h1);
            }
            const bool o0 = plain->occludes(local, tmax), o1 = baked->occludes(world, tmax);
            EXPECT_EQ(o0, o1) << i;
            occluded += o1;
            render::HitList all0, all1;
            plain->intersect_all(local, tmax, &all0);
            baked->intersect_all(world, tmax, &all1);
            ASSERT_EQ(all0.size(), all1.size()) << i;
            // In the same order too: the baked BVH is the object-space one mirrored.
            for (size_t k = 0; k < all0.size(); ++k) {
                mirror_hit(xf, &all0[k]);
                expect_same_bits(all0[k], all1[k]);
            }
            const bool in0 = plain->inside(o), in1 = baked->inside(wo);
            EXPECT_EQ(in0, in1) << i;
            inside += in1;
        }
        // The test means something: plenty of hits, misses, occlusions and inside points.
        EXPECT_GT(hits, 3000);
        EXPECT_GT(occluded, 2000);
        EXPECT_GT(inside, 300);
        EXPECT_LT(inside, 5500);
    }
    // Only pure mirrors bake: not a translation, a scale, a rotation or the identity.
    EXPECT_FALSE(render::bake_exact(Transform()));
    EXPECT_FALSE(render::bake_exact(Transform::scale(Vec3(1, 1, -1)).then(
        Transform::translate(Vec3(0, 0, 1)))));
    EXPECT_FALSE(render::bake_exact(Transform::scale(Vec3(2, 1, -1))));
    EXPECT_FALSE(render::bake_exact(Transform::rotate_axis(Vec3(0, 1, 0), 90)));
}

// An obj_file-style part (a mirrored mesh object) goes through ObjectNode baked, with the same
// hits as the node's own transform would give (material, inverse and flags still applied).
TEST(Mesh, BakedMeshNodeMatchesTransformedNode) {
    scene::Scene sc;
    sc.meshes.push_back(smooth_uv_sphere(8));
    scene::Object o;
    o.shape = scene::MeshRef{0};
    o.transform = Transform::scale(Vec3(1, 1, -1));
    o.material = 5;
    o.inverse = true;
    Diagnostics diag;
    auto node = render::ObjectNode::build(o, sc, diag);
    ASSERT_TRUE(node);
    scene::Object plain_o = o;
    plain_o.transform = Transform();
    plain_o.inverse = false;
    auto plain = render::ObjectNode::build(plain_o, sc, diag);
    ASSERT_TRUE(plain);
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> u(-2, 2);
    int hits = 0;
    for (int i = 0; i < 2000; ++i) {
        Vec3 o0(u(rng), u(rng), u(rng)), d(u(rng), u(rng), u(rng));
        const Transform& xf = o.transform;
        LocalHit h0, h1;
        bool f0 = plain->intersect(Ray{o0, d, kInfinity}, kInfinity, false, &h0);
        bool f1 = node->intersect(Ray{xf.point(o0), xf.vector(d), kInfinity}, kInfinity, false,
                                  &h1);
        ASSERT_EQ(f0, f1);
        if (!f0) continue;
        ++hits;
        mirror_hit(xf, &h0);
        h0.ng = -h0.ng;  // inverse
        h0.n = -h0.n;
        expect_same_bits(h0, h1);
        EXPECT_EQ(node->inside(xf.point(o0)), !plain->inside(o0));
    }
    EXPECT_GT(hits, 200);
}

}  // namespace
}  // namespace glint
