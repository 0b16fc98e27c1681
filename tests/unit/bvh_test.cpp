// The SAH BVH: identical hits to brute force on random scenes and rays, and bounded depth and
// build time for VALIDATION.md case 8 (many primitives with one centroid, slivers).
#include <gtest/gtest.h>

#include <chrono>
#include <climits>
#include <random>

#include "geom_test_util.h"
#include "render/accel/bvh.h"

namespace glint {
namespace {

using render::Hit;

scene::Scene random_scene(std::mt19937_64& rng, int n) {
    std::uniform_real_distribution<double> u(-10, 10), r(0.05, 1.5);
    std::vector<scene::Object> objs;
    for (int i = 0; i < n; ++i) {
        Vec3 c(u(rng), u(rng), u(rng));
        int m = i % 4;
        switch (i % 5) {
            case 0: objs.push_back(test::object(scene::Sphere{c, r(rng)}, {}, m)); break;
            case 1: {
                Vec3 e(r(rng), r(rng), r(rng));
                objs.push_back(test::object(scene::Box{c - e, c + e}, {}, m));
                break;
            }
            case 2:
                objs.push_back(test::object(
                    scene::Triangle{{c, c + Vec3(r(rng), 0, r(rng)), c + Vec3(0, r(rng), r(rng))}},
                    {}, m));
                break;
            case 3:
                objs.push_back(test::object(scene::Torus{r(rng), 0.2, false},
                                            Transform::rotate_xyz_degrees({u(rng) * 9, 0, 0})
                                                .then(Transform::translate(c)),
                                            m));
                break;
            default:
                objs.push_back(test::object(
                    scene::Cylinder{c, c + Vec3(r(rng), r(rng), 0), r(rng) * 0.5, false}, {}, m));
        }
    }
    // One unbounded object and two coplanar duplicates to exercise the tie rule.
    objs.push_back(test::object(scene::Plane{{0, 1, 0}, -12}, {}, 1));
    objs.push_back(test::object(scene::Sphere{{0, 0, 0}, 2}, {}, 2));
    objs.push_back(test::object(scene::Sphere{{0, 0, 0}, 2}, {}, 3));
    return test::scene_of(objs);
}

// Brute force: each object as its own geometry, the closest hit, ties to the lower index.
bool brute_force(const std::vector<std::unique_ptr<render::Geometry>>& singles,
                 const render::Ray& ray, Hit* best) {
    bool found = false;
    for (size_t i = 0; i < singles.size(); ++i) {
        Hit h;
        if (singles[i]->intersect(ray, &h) && (!found || h.t < best->t)) {
            *best = h;
            best->object = static_cast<int>(i);
            found = true;
        }
    }
    return found;
}

void check_against_brute_force(int objects, uint64_t seed, int rays, int min_hits) {
    std::mt19937_64 rng(seed);
    scene::Scene s = random_scene(rng, objects);
    auto g = test::build(s);
    std::vector<std::unique_ptr<render::Geometry>> singles;
    for (const auto& o : s.objects) singles.push_back(test::build(test::scene_of({o})));
    std::uniform_real_distribution<double> u(-15, 15);
    std::normal_distribution<double> nd;
    int hits = 0, mismatches = 0, occl_mismatch = 0;
    for (int i = 0; i < rays; ++i) {
        render::Ray r{{u(rng), u(rng), u(rng)}, {nd(rng), nd(rng), nd(rng)}, kInfinity};
        if (i % 7 == 0) r.dir = {0, 0, 1};          // zero components
        if (i % 11 == 0) r.origin = {0, 0, -15};   // through the duplicate spheres
        if (i % 3 == 0) r.tmax = std::fabs(u(rng));
        Hit a, b;
        bool fa = g->intersect(r, &a), fb = brute_force(singles, r, &b);
        if (fa != fb) {
            ++mismatches;
            continue;
        }
        if (g->occluded(r) != fb) ++occl_mismatch;
        if (!fa) continue;
        ++hits;
        if (a.t != b.t || a.object != b.object || !(a.p == b.p) || !(a.ng == b.ng) ||
            a.material != b.material)
            ++mismatches;
    }
    EXPECT_EQ(mismatches, 0) << objects << " objects";
    EXPECT_EQ(occl_mismatch, 0) << objects << " objects";
    EXPECT_GT(hits, min_hits) << objects << " objects";
}

TEST(Bvh, IdenticalToBruteForce) { check_against_brute_force(300, 11, 20000, 5000); }

// Past some 8,000 nodes the scene's objects are walked in the eight-wide tree (geometry.cpp).
TEST(Bvh, WideSceneTreeIdenticalToBruteForce) { check_against_brute_force(20000, 12, 800, 400); }

// A union of many children (searched through its own BVH) gives the same hits as the same
// children placed as separate top-level objects.
TEST(Bvh, LargeUnionMatchesFlatObjects) {
    std::mt19937_64 rng(21);
    scene::Scene flat = random_scene(rng, 200);
    scene::Csg u;
    u.op = scene::CsgOp::Union;
    u.children = flat.objects;
    for (size_t i = 0; i < u.children.size(); i += 3) u.children[i].material = -1;  // inherit
    for (size_t i = 0; i < flat.objects.size(); i += 3) flat.objects[i].material = 1;
    Transform xf = Transform::rotate_xyz_degrees({10, 20, 30}).then(Transform::translate({1, 2, 3}));
    scene::Object uo = test::object(u, xf, 1);
    for (auto& o : flat.objects) o.transform = o.transform.then(xf);
    auto g_union = test::build(test::scene_of({uo}));
    auto g_flat = test::build(flat);
    std::uniform_real_distribution<double> uu(-15, 15);
    std::normal_distribution<double> nd;
    int hits = 0, mismatches = 0;
    for (int i = 0; i < 20000; ++i) {
        render::Ray r{{uu(rng), uu(rng), uu(rng)}, {nd(rng), nd(rng), nd(rng)}, kInfinity};
        if (i % 3 == 0) r.tmax = std::fabs(uu(rng));
        Hit a, b;
        bool fa = g_union->intersect(r, &a), fb = g_flat->intersect(r, &b);
        if (fa != fb || g_union->occluded(r) != fb) {
            ++mismatches;
            continue;
        }
        if (!fa) continue;
        ++hits;
        if (std::fabs(a.t - b.t) > 1e-12 * (1 + b.t) || a.material != b.material ||
            length(a.ng - b.ng) > 1e-9)
            ++mismatches;
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(hits, 5000);
}

TEST(Bvh, DuplicateObjectsTieToLowerIndex) {
    // Many copies of one sphere among distant clutter: the first copy always wins.
    std::vector<scene::Object> objs;
    for (int i = 0; i < 40; ++i)
        objs.push_back(test::object(scene::Sphere{{100.0 + 3 * i, 0, 0}, 1}, {}, 1));
    size_t first = objs.size();
    for (int i = 0; i < 9; ++i) objs.push_back(test::object(scene::Sphere{{0, 0, 0}, 2}, {}, 2));
    auto g = test::build(test::scene_of(objs));
    std::mt19937_64 rng(12);
    std::normal_distribution<double> nd;
    for (int i = 0; i < 200; ++i) {
        Vec3 d = normalize(Vec3(nd(rng), nd(rng), nd(rng)));
        Hit h;
        ASSERT_TRUE(g->intersect({d * -10, d, kInfinity}, &h));
        EXPECT_EQ(h.object, static_cast<int>(first));
    }
}

// VALIDATION.md case 8: 1e5 primitives with one centroid, and 1e6:1 slivers.
TEST(Bvh, StressOneCentroidAndSlivers) {
    std::vector<Bounds3> same(100000);
    for (size_t i = 0; i < same.size(); ++i) {
        double e = 1 + (i % 13) * 0.1;
        same[i] = {Vec3(-e), Vec3(e)};
    }
    auto t0 = std::chrono::steady_clock::now();
    render::Bvh a(same);
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LE(a.depth(), 64);
    EXPECT_LT(secs, 5.0);
    EXPECT_EQ(a.order().size(), same.size());

    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Bounds3> slivers(100000);
    for (auto& b : slivers) {
        Vec3 c(u(rng), u(rng), u(rng));
        b = {c, c + Vec3(1, 1e-6, 1e-6)};
    }
    t0 = std::chrono::steady_clock::now();
    render::Bvh s(slivers);
    secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LE(s.depth(), 64);
    EXPECT_LT(secs, 5.0);
    std::printf("bvh: one-centroid depth %d, sliver depth %d, %zu nodes\n", a.depth(), s.depth(),
                s.nodes().size());
    // Every primitive is reachable: a ray through each sliver's centre visits it.
    int missed = 0;
    for (int i = 0; i < 1000; ++i) {
        const Bounds3& b = slivers[i];
        render::Ray r{b.centroid() - Vec3(0, 0, 1), {0, 0, 1}, kInfinity};
        bool seen = false;
        double tmax = r.tmax;
        s.traverse(r, tmax, [&](int p, double&) {
            seen = seen || p == i;
            return false;
        });
        missed += !seen;
    }
    EXPECT_EQ(missed, 0);
}

TEST(Bvh, SkipsEmptyAndInfiniteBounds) {
    std::vector<Bounds3> b = {{Vec3(0), Vec3(1)}, Bounds3{}, {Vec3(-kInfinity), Vec3(kInfinity)}};
    render::Bvh bvh(b);
    EXPECT_EQ(bvh.order().size(), 1u);
    render::Bvh none(std::vector<Bounds3>{});
    double tmax = kInfinity;
    EXPECT_FALSE(none.traverse({{0, 0, 0}, {1, 0, 0}, kInfinity}, tmax,
                               [](int, double&) { return true; }));
}

}  // namespace
}  // namespace glint
