// VALIDATION.md cases 4 (watertight meshes: 1e6 rays from inside aimed at vertices and edges),
// 5 (axis-aligned rays through box faces and edges), 6 (grazing and edge-on triangles),
// 8 (BVH stress: 1e5 primitives with one centroid, 1e6:1 slivers) and 9 (camera inside a
// sphere: hits within 4 ulp of the radius). These are properties of the shared geometry code,
// so they hold for the Whitted integrator and the path tracer alike. Each test prints
// "case N: <measured> (bound <bound>)" for tests/stability/make_report.sh.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>

#include "core/float.h"
#include "render/accel/bvh.h"
#include "render/prepare/geometry.h"
#include "render/shapes/mesh/mesh_prim.h"
#include "render/shapes/shapes.h"
#include "render/shapes/mesh/triangle.h"
#include "scene/features.h"
#include "stability_support.h"

namespace glint::stability {
namespace {

// A closed, slightly irregular UV sphere (poles closed by single vertices), so that its edges
// run in every direction.
scene::Mesh closed_sphere_mesh(int n) {
    scene::Mesh m;
    m.positions.push_back({0, 1, 0});
    for (int i = 1; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            const double th = kPi * i / n, ph = kPi * j / n + 0.013 * i;
            const double r = 1 + 0.05 * std::sin(3 * ph + i);
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
    const int south = static_cast<int>(m.positions.size()) - 1;
    for (int j = 0; j < 2 * n; ++j) {
        add(0, ring(1, j + 1), ring(1, j));
        add(south, ring(n - 1, j), ring(n - 1, j + 1));
        for (int i = 1; i < n - 1; ++i) {
            add(ring(i, j), ring(i, j + 1), ring(i + 1, j + 1));
            add(ring(i, j), ring(i + 1, j + 1), ring(i + 1, j));
        }
    }
    return m;
}

TEST(StabilityGeometry, Case4WatertightMeshDoesNotLeak) {
    const scene::Mesh mesh = closed_sphere_mesh(32);
    Diagnostics diag;
    const auto prim = render::make_mesh(mesh, diag);
    ASSERT_TRUE(prim);
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(-0.4, 0.4);
    std::uniform_int_distribution<size_t> pick(0, mesh.faces.size() - 1);
    constexpr long kRays = 1000000;
    long leaks = 0;
    for (long i = 0; i < kRays; ++i) {
        const scene::MeshFace& f = mesh.faces[pick(rng)];
        const Vec3 a = mesh.positions[f.v[i % 3]], b = mesh.positions[f.v[(i + 1) % 3]];
        // A vertex, an edge midpoint, or another point exactly on an edge.
        Vec3 target = a;
        if (i % 3 == 1) target = a + (b - a) * 0.5;
        if (i % 3 == 2) target = a + (b - a) * 0.3719;
        const Vec3 origin(u(rng), u(rng), u(rng));
        render::LocalHit hit;
        if (!prim->intersect(render::Ray{origin, target - origin, kInfinity}, kInfinity, &hit))
            ++leaks;
    }
    std::printf(
        "case 4: leaks = %ld of %ld rays from inside a closed %zu-triangle mesh aimed at "
        "vertices and edges (bound 0)\n",
        leaks, kRays, mesh.faces.size());
    EXPECT_EQ(leaks, 0);
}

TEST(StabilityGeometry, Case5AxisAlignedRaysThroughBoxFacesAndEdges) {
    // Rays along each axis (other direction components exactly 0) through the faces, along
    // the faces and along the edges of boxes of several sizes and offsets. Analytic count: 2
    // hits when the ray's line meets the closed box, else 0.
    long rays = 0, wrong = 0, nonfinite = 0;
    for (double scale : {1e-4, 1.0, 1e4}) {
        for (double offset : {0.0, 1e5}) {
            const Vec3 lo = Vec3(-1, -1, -1) * scale + Vec3(offset),
                       hi = Vec3(1, 1, 1) * scale + Vec3(offset);
            const auto prim = render::make_box(scene::Box{lo, hi});
            const double coords[] = {-2, -1, -0.5, 0, 0.5, 1, 2};
            for (int axis = 0; axis < 3; ++axis)
                for (double sign : {-1.0, 1.0})
                    for (double a : coords)
                        for (double b : coords) {
                            Vec3 o(offset), d;
                            o[axis] = offset - 5 * scale * sign;
                            o[(axis + 1) % 3] = offset + a * scale;
                            o[(axis + 2) % 3] = offset + b * scale;
                            d[axis] = sign;
                            // Exact in floating point: a, b are multiples of 0.5.
                            const bool inside_line = std::fabs(a) <= 1 && std::fabs(b) <= 1;
                            render::HitList hits;
                            prim->intersect_all(render::Ray{o, d, kInfinity}, kInfinity, &hits);
                            ++rays;
                            if (static_cast<int>(hits.size()) != (inside_line ? 2 : 0)) ++wrong;
                            for (const auto& h : hits)
                                if (!std::isfinite(h.t) || !is_finite(h.p) || !is_finite(h.ng))
                                    ++nonfinite;
                        }
        }
    }
    std::printf(
        "case 5: rays with the wrong hit count = %ld of %ld, non-finite hits = %ld "
        "(bound 0, 0)\n",
        wrong, rays, nonfinite);
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(nonfinite, 0);
}

TEST(StabilityGeometry, Case6GrazingAndEdgeOnTriangles) {
    // Rays crossing the plane of the triangle with d.n = 0, +-1e-7, +-1e-12, at points on the
    // edges, vertices and inside; and random nearly-in-plane rays.
    const Vec3 p[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    long rays = 0, hits = 0, bad = 0;
    auto check = [&](const render::Ray& r) {
        ++rays;
        render::RayShear s(r);
        render::TriangleHit th;
        if (!render::intersect_triangle(s, p[0], p[1], p[2], kInfinity, &th)) return;
        ++hits;
        double sum = 0;
        bool ok = std::isfinite(th.t) && th.t > 0;
        for (double b : th.b) {
            ok = ok && std::isfinite(b) && b >= 0 && b <= 1;
            sum += b;
        }
        if (!ok || std::fabs(sum - 1) > 1e-12) ++bad;
    };
    for (double dz : {0.0, 1e-7, -1e-7, 1e-12, -1e-12})
        for (double y0 : {0.0, 0.1, 0.5, 1.0})
            for (double x0 : {-1.0, 0.0}) {
                render::Ray r{{x0, y0, -dz}, {1, 0, dz}, kInfinity};
                check(r);
            }
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u(-1, 2), e(-1e-7, 1e-7);
    long edge_on_hits = 0;
    for (int i = 0; i < 100000; ++i) {
        const Vec3 target(u(rng), u(rng), 0);
        const Vec3 dir = normalize(Vec3(u(rng), u(rng), i % 2 ? e(rng) : 0.0));
        if (!is_finite(dir)) continue;
        const long before = hits;
        check(render::Ray{target - dir * 3, dir, kInfinity});
        if (dir.z == 0 && hits > before) ++edge_on_hits;
    }
    std::printf(
        "case 6: bad hits (NaN t or barycentric outside [0, 1]) = %ld of %ld hits, %ld "
        "rays; edge-on (d.n = 0) hits = %ld (bound 0, 0)\n",
        bad, hits, rays, edge_on_hits);
    EXPECT_EQ(bad, 0);
    EXPECT_EQ(edge_on_hits, 0);
    EXPECT_GT(hits, 0);
}

TEST(StabilityGeometry, Case8BvhStress) {
    constexpr double kMaxSeconds = 5.0;
    constexpr int kMaxDepth = 64;
    std::vector<Bounds3> same(100000);
    for (size_t i = 0; i < same.size(); ++i) {
        const double e = 1 + (i % 13) * 0.1;
        same[i] = {Vec3(-e), Vec3(e)};
    }
    auto t0 = std::chrono::steady_clock::now();
    const render::Bvh one(same);
    const double one_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Bounds3> slivers(100000);
    for (auto& b : slivers) {
        const Vec3 c(u(rng), u(rng), u(rng));
        b = {c, c + Vec3(1, 1e-6, 1e-6)};  // 1e6:1
    }
    t0 = std::chrono::steady_clock::now();
    const render::Bvh sl(slivers);
    const double sl_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf(
        "case 8: 1e5 boxes with one centroid: depth %d, build %.3f s; 1e5 slivers "
        "1e6:1: depth %d, build %.3f s (bound depth <= %d, build < %.0f s)\n",
        one.depth(), one_s, sl.depth(), sl_s, kMaxDepth, kMaxSeconds);
    EXPECT_LE(one.depth(), kMaxDepth);
    EXPECT_LE(sl.depth(), kMaxDepth);
    EXPECT_LT(one_s, kMaxSeconds);
    EXPECT_LT(sl_s, kMaxSeconds);
    EXPECT_EQ(one.order().size(), same.size());
    EXPECT_EQ(sl.order().size(), slivers.size());
}

TEST(StabilityGeometry, Case9CameraInsideASphere) {
    // Through the whole pipeline (build_geometry, object transforms): rays from the centre of
    // spheres of several radii and positions, plus a scaled unit sphere.
    std::mt19937_64 rng(9);
    std::normal_distribution<double> nd;
    long total = 0, bad = 0;
    double worst_ulps = 0;
    for (double r : {1e-4, 0.3, 1.0, 7.0, 1e4}) {
        for (Vec3 c : {Vec3(0, 0, 0), Vec3(0.5, -3, 2), Vec3(1e3, 1e3, -1e3)}) {
            scene::Scene s;
            s.materials.resize(1);
            scene::Object o;
            o.shape = scene::Sphere{c, r};
            s.objects.push_back(o);
            Diagnostics diag;
            const auto geometry = render::build_geometry(s, scene::analyze(s), diag);
            const double ulp = next_up(r) - r;
            for (int i = 0; i < 4000; ++i) {
                const Vec3 d = normalize(Vec3(nd(rng), nd(rng), nd(rng)));
                render::Hit h;
                ++total;
                if (!geometry->intersect(render::Ray{c, d, kInfinity}, &h)) {
                    ++bad;
                    continue;
                }
                const double ulps = std::fabs(h.t - r) / ulp;
                worst_ulps = std::max(worst_ulps, ulps);
                if (!(ulps <= 4)) ++bad;
            }
        }
    }
    std::printf(
        "case 9: rays from the centre off by more than 4 ulp of the radius (or missing) "
        "= %ld of %ld; worst %.2f ulp (bound 0, <= 4 ulp)\n",
        bad, total, worst_ulps);
    EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace glint::stability
