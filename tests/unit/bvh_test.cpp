// The SAH BVH: identical hits to brute force on random scenes and rays, and bounded depth and
// build time for VALIDATION.md case 8 (many primitives with one centroid, slivers).
#include <gtest/gtest.h>

#include <chrono>
#include <climits>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "geom_test_util.h"
#include "render/accel/bvh.h"
#include "render/accel/wide_bvh.h"

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

std::vector<Bounds3> random_boxes(std::mt19937_64& rng, int n) {
    std::uniform_real_distribution<double> u(-10, 10), r(0.01, 0.6);
    std::vector<Bounds3> boxes(n);
    for (auto& b : boxes) {
        const Vec3 c(u(rng), u(rng), u(rng)), e(r(rng), r(rng), r(rng));
        b = {c - e, c + e};
    }
    return boxes;
}

// The box of a wide node's lane, as doubles.
Bounds3 lane_box(const render::WideNode& n, int lane) {
    return {Vec3(n.box[0][lane], n.box[1][lane], n.box[2][lane]),
            Vec3(n.box[3][lane], n.box[4][lane], n.box[5][lane])};
}

bool contains(const Bounds3& outer, const Bounds3& inner) {
    for (int a = 0; a < 3; ++a)
        if (!(outer.lo[a] <= inner.lo[a] && inner.hi[a] <= outer.hi[a])) return false;
    return true;
}

// Checks one collapsed tree: its leaves cover order() once, none holds more than `max_count`,
// every lane's box holds what lies below it, and each node has two lanes or more. Returns
// the primitives under `node`, as a box and a count.
std::pair<Bounds3, int> check_wide(const render::WideBvh& w, const render::Bvh& bvh,
                                   const std::vector<Bounds3>& boxes, int node, int max_count,
                                   std::vector<int>& seen) {
    const render::WideNode& n = w.nodes()[node];
    Bounds3 all;
    int count = 0, lanes = 0;
    for (int lane = 0; lane < render::WideNode::kWidth; ++lane) {
        const int64_t ref = n.ref[lane];
        Bounds3 below;
        int below_count = 0;
        if (ref >= 0) {
            EXPECT_GT(ref, node) << "children follow their parent";
            std::tie(below, below_count) = check_wide(w, bvh, boxes, static_cast<int>(ref), max_count, seen);
        } else {
            const int64_t first = render::WideNode::leaf_first(ref);
            below_count = render::WideNode::leaf_count(ref);
            EXPECT_LE(below_count, max_count);
            for (int i = 0; i < below_count; ++i) {
                ++seen[first + i];
                below.extend(boxes[bvh.order()[first + i]]);
            }
        }
        if (below_count == 0) continue;
        ++lanes;
        EXPECT_TRUE(contains(lane_box(n, lane), below)) << "node " << node << " lane " << lane;
        all.extend(below);
        count += below_count;
    }
    EXPECT_GE(lanes, 2) << "node " << node;
    return {all, count};
}

// Collapsing to the eight-wide tree, with and without leaves merged: every primitive in
// exactly one leaf, boxes that hold their subtrees, leaves no larger than allowed; unmerged,
// the leaves are the binary tree's own.
TEST(WideBvh, CollapseKeepsEveryPrimitiveOnceInsideItsBoxes) {
    std::mt19937_64 rng(21);
    const std::vector<Bounds3> boxes = random_boxes(rng, 20000);
    const render::Bvh bvh(boxes, 4, 4);
    std::map<int, int> binary_leaves;
    int binary_max = 0;
    for (const auto& n : bvh.nodes())
        if (n.count > 0) {
            binary_leaves[n.index] = n.count;
            binary_max = std::max<int>(binary_max, n.count);
        }
    for (const render::WideBvh::Costs costs : {render::WideBvh::Costs{4, 0, 1.0},
                                               render::WideBvh::Costs{4, 16, 1.5},
                                               render::WideBvh::Costs{4, 40, 30.0}}) {
        const render::WideBvh w(bvh, costs);
        ASSERT_FALSE(w.nodes().empty());
        std::vector<int> seen(bvh.order().size(), 0);
        const auto [box, count] =
            check_wide(w, bvh, boxes, 0, std::max(binary_max, costs.max_leaf), seen);
        EXPECT_EQ(count, static_cast<int>(bvh.order().size()));
        for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "primitive " << i;
        std::map<int, int> leaves;
        w.for_each_leaf([&](int first, int n) { leaves[first] = n; });
        if (costs.max_leaf == 0) EXPECT_EQ(leaves, binary_leaves);
        else EXPECT_LT(leaves.size(), binary_leaves.size()) << "some leaves should merge";
    }
}

// Boxes past the float range (rounded out to infinite planes, some with a zero extent beside
// them, whose area in float arithmetic is inf * 0): every primitive is still in exactly one
// leaf, and every node holds two lanes or more.
TEST(WideBvh, CollapseSurvivesBoxesPastTheFloatRange) {
    std::mt19937_64 rng(23);
    std::vector<Bounds3> boxes = random_boxes(rng, 3000);
    for (size_t i = 0; i < boxes.size(); i += 7) {
        const double big = i % 2 ? 1e300 : 1e39;
        boxes[i].hi.x = big;
        if (i % 5 == 0) boxes[i].lo.z = -big;
    }
    // A cluster of flat boxes reaching to infinity along x: subtrees of them have an area of
    // inf * 0 in float arithmetic.
    for (int i = 0; i < 64; ++i)
        boxes.push_back({Vec3(20 + i * 0.01, 0.5, 5), Vec3(1e39, 0.5, 5.0 + i * 1e-3)});
    const render::Bvh bvh(boxes, 4, 4);
    for (const render::WideBvh::Costs costs : {render::WideBvh::Costs{1, 0, 1.0},
                                               render::WideBvh::Costs{4, 16, 1.5}}) {
        const render::WideBvh w(bvh, costs);
        ASSERT_FALSE(w.nodes().empty());
        std::vector<int> seen(bvh.order().size(), 0);
        int under = 0;
        w.for_each_leaf([&](int first, int n) {
            under += n;
            for (int i = 0; i < n; ++i) ++seen[first + i];
        });
        EXPECT_EQ(under, static_cast<int>(bvh.order().size()));
        for (size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "primitive " << i;
        for (const auto& n : w.nodes()) {
            int lanes = 0;
            for (int64_t ref : n.ref) lanes += ref >= 0 || render::WideNode::leaf_count(ref) > 0;
            EXPECT_GE(lanes, 2);
        }
    }
}

// Where a node visit costs far more than a test, every subtree small enough to be one leaf
// is one: no wide node below the root holds `max_leaf` primitives or fewer.
TEST(WideBvh, ExpensiveNodesMergeEverySmallSubtree) {
    std::mt19937_64 rng(22);
    const std::vector<Bounds3> boxes = random_boxes(rng, 5000);
    const render::Bvh bvh(boxes, 4, 4);
    constexpr int kMaxLeaf = 24;
    const render::WideBvh w(bvh, {4, kMaxLeaf, 1e6});
    std::vector<int> seen(bvh.order().size(), 0);
    std::vector<int> under(w.nodes().size(), 0);
    // Nodes follow their parents, so counting backwards sees children first.
    for (size_t k = w.nodes().size(); k-- > 0;)
        for (int64_t ref : w.nodes()[k].ref)
            under[k] += ref >= 0 ? under[ref] : render::WideNode::leaf_count(ref);
    EXPECT_EQ(under[0], static_cast<int>(bvh.order().size()));
    for (size_t k = 1; k < w.nodes().size(); ++k) EXPECT_GT(under[k], kMaxLeaf) << "node " << k;
    // And the fewer nodes, the fewer visits: the tree is far smaller than the unmerged one.
    const render::WideBvh unmerged(bvh, {4, 0, 1.0});
    EXPECT_LT(w.nodes().size() * 2, unmerged.nodes().size());
}

}  // namespace
}  // namespace glint
