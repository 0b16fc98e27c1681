// The mesh kernels (render/shapes/mesh/mesh_kernels.h) and the mesh primitive on top of them: the
// AVX2 and the portable build give the same hits bit for bit, and both give the hits of a brute
// force over every triangle with the scalar watertight test, through the eight-wide BVH.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/float.h"
#include "core/log.h"
#include "render/accel/bvh.h"
#include "render/accel/wide_bvh.h"
#include "render/shapes/mesh/mesh_kernels.h"
#include "render/shapes/mesh/mesh_prim.h"
#include "render/shapes/mesh/triangle.h"

namespace glint::render {
namespace {

// A cloud of random triangles of mixed sizes, some sharing edges, laid out as MeshPrim does.
struct TestMesh {
    std::vector<std::array<Vec3, 3>> tri;  // float-exact corners, in leaf order
    std::vector<int> face;                 // tie-break index of each position
    std::vector<float> data;
    WideBvh wide;
    MeshView view;
};

// `scale` multiplies every coordinate (the extreme-scale tests).
TestMesh make_test_mesh(std::mt19937_64& rng, int n, double scale = 1,
                        const WideBvh::Costs& costs = kMeshCollapse) {
    std::uniform_real_distribution<double> u(-4, 4), s(0.01, 1.5);
    std::vector<std::array<Vec3, 3>> raw;
    auto f = [scale](double v) { return static_cast<double>(static_cast<float>(v * scale)); };
    for (int i = 0; i < n; ++i) {
        Vec3 c(u(rng), u(rng), u(rng));
        double k = s(rng);
        std::array<Vec3, 3> t;
        for (auto& p : t) p = {f(c.x + k * u(rng) / 4), f(c.y + k * u(rng) / 4), f(c.z + k * u(rng) / 4)};
        if (!(length_squared(cross(t[1] - t[0], t[2] - t[0])) > 0)) continue;
        raw.push_back(t);
        // Every third triangle gets a neighbour over its first edge: shared edges.
        if (i % 3 == 0)
            raw.push_back({t[1], t[0], Vec3(f(t[2].x / scale + 0.3), t[2].y, f(t[2].z / scale - 0.2))});
    }
    std::vector<Bounds3> boxes(raw.size());
    for (size_t i = 0; i < raw.size(); ++i)
        for (const Vec3& p : raw[i]) boxes[i].extend(p);
    Bvh bvh(boxes, 4, 4);
    TestMesh m;
    const auto& order = bvh.order();
    m.data.assign(10 * order.size() + 4, 0.0f);
    m.tri.resize(order.size());
    m.face.resize(order.size());
    auto leaf = [&](int first, int count) {
        float* l = m.data.data() + 10 * first;
        for (int j = 0; j < count; ++j) {
            const int src = order[first + j];
            m.tri[first + j] = raw[src];
            m.face[first + j] = src;
            for (int v = 0; v < 3; ++v)
                for (int a = 0; a < 3; ++a) l[(3 * v + a) * count + j] = static_cast<float>(raw[src][v][a]);
            const int32_t face = src;
            std::memcpy(l + 9 * count + j, &face, sizeof face);
        }
    };
    if (bvh.single_leaf()) {
        leaf(0, static_cast<int>(order.size()));
    } else {
        m.wide = WideBvh(bvh, costs);
        m.wide.for_each_leaf(leaf);
    }
    m.view.nodes = m.wide.nodes().empty() ? nullptr : m.wide.nodes().data();
    m.view.tris = m.data.data();
    m.view.count = static_cast<int>(order.size());
    return m;
}

// Half the rays aim at a point of a triangle: inside, on an edge or at a corner.
Ray random_ray(std::mt19937_64& rng, const TestMesh& m, double scale = 1) {
    std::uniform_real_distribution<double> u(-6 * scale, 6 * scale), b(0, 1);
    Vec3 o(u(rng), u(rng), u(rng)), target(u(rng) / 2, u(rng) / 2, u(rng) / 2);
    if (rng() % 2 == 0) {
        const auto& t = m.tri[rng() % m.tri.size()];
        double w[3] = {b(rng), b(rng), b(rng)};
        if (rng() % 4 == 0) w[rng() % 3] = 0;  // an edge
        if (rng() % 8 == 0) w[rng() % 3] = 0;  // perhaps a corner
        const double sum = w[0] + w[1] + w[2];
        if (sum > 0) target = (t[0] * w[0] + t[1] * w[1] + t[2] * w[2]) / sum;
    }
    Vec3 d = target - o;
    // Some rays along the axes (zero direction components) and some not normalized.
    if (rng() % 8 == 0) d = Vec3(0, 0, d.z);
    if (rng() % 8 == 1) d = Vec3(d.x, 0, 0);
    return {o, d * (0.5 + (rng() % 4)), kInfinity};
}

// The reference: every triangle with the scalar test, nearest t, equal t to the lower face.
bool brute_closest(const TestMesh& m, const Ray& ray, double tmax, int* index, TriangleHit* hit) {
    RayShear s(ray);
    bool found = false;
    for (size_t i = 0; i < m.tri.size(); ++i) {
        TriangleHit th;
        if (!intersect_triangle(s, m.tri[i][0], m.tri[i][1], m.tri[i][2], tmax, &th)) continue;
        if (found && !(th.t < hit->t || (th.t == hit->t && m.face[i] < m.face[*index]))) continue;
        *hit = th;
        *index = static_cast<int>(i);
        found = true;
    }
    return found;
}

int brute_count(const TestMesh& m, const Ray& ray, double tmax) {
    RayShear s(ray);
    int n = 0;
    for (const auto& t : m.tri) {
        TriangleHit th;
        n += intersect_triangle(s, t[0], t[1], t[2], tmax, &th);
    }
    return n;
}

void expect_same(const MeshHit& a, const MeshHit& b) {
    EXPECT_EQ(a.index, b.index);
    EXPECT_EQ(a.th.t, b.th.t);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(a.th.b[k], b.th.b[k]);
        EXPECT_EQ(a.p[k], b.p[k]);
    }
}

void check_against_brute_force(const MeshKernels& k, int triangles, uint64_t seed,
                               const WideBvh::Costs& costs = kMeshCollapse) {
    std::mt19937_64 rng(seed);
    const TestMesh m = make_test_mesh(rng, triangles, 1, costs);
    int hits = 0;
    for (int r = 0; r < 4000; ++r) {
        const Ray ray = random_ray(rng, m);
        const double tmax = r % 5 == 0 ? 0.5 : kInfinity;
        int want_i = -1;
        TriangleHit want;
        const bool want_hit = brute_closest(m, ray, tmax, &want_i, &want);
        MeshHit got;
        const bool got_hit = k.closest(m.view, ray, tmax, &got);
        ASSERT_EQ(got_hit, want_hit) << k.name << " ray " << r;
        EXPECT_EQ(k.any(m.view, ray, tmax), want_hit) << k.name << " ray " << r;
        int count = 0;
        k.all(m.view, ray, tmax, [](void* c, const MeshHit&) { ++*static_cast<int*>(c); }, &count);
        EXPECT_EQ(count, brute_count(m, ray, tmax)) << k.name << " ray " << r;
        if (!want_hit) continue;
        ++hits;
        EXPECT_EQ(got.index, want_i) << k.name << " ray " << r;
        EXPECT_EQ(got.th.t, want.t) << k.name << " ray " << r;
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(got.th.b[c], want.b[c]);
            EXPECT_EQ(got.p[c], m.tri[want_i][c]);
        }
    }
    EXPECT_GT(hits, 1000) << "the rays should hit often enough to test something";
}

TEST(MeshKernels, PortableBuildMatchesBruteForce) {
    for (int n : {1, 3, 7, 40, 3000}) check_against_brute_force(mesh_kernels_base(), n, 100 + n);
}

TEST(MeshKernels, Avx2BuildMatchesBruteForce) {
    const MeshKernels* avx2 = mesh_kernels_avx2();
    if (!avx2) GTEST_SKIP() << "this CPU has no AVX2";
    for (int n : {1, 3, 7, 40, 3000}) check_against_brute_force(*avx2, n, 100 + n);
}

// Leaves merged from whole subtrees (nodes priced high, so most small subtrees are merged):
// runs of up to 40 triangles, up to ten groups of four (the last perhaps partial), tested
// like any leaf.
TEST(MeshKernels, MergedLeavesMatchBruteForce) {
    const WideBvh::Costs merging{4, 40, 30.0};
    for (int n : {40, 3000}) check_against_brute_force(mesh_kernels_base(), n, 300 + n, merging);
    if (const MeshKernels* avx2 = mesh_kernels_avx2())
        for (int n : {40, 3000}) check_against_brute_force(*avx2, n, 300 + n, merging);
}

TEST(MeshKernels, BothBuildsGiveTheSameHitsBitForBit) {
    const MeshKernels* avx2 = mesh_kernels_avx2();
    if (!avx2) GTEST_SKIP() << "this CPU has no AVX2";
    std::mt19937_64 rng(7);
    const TestMesh m = make_test_mesh(rng, 20000);
    for (int r = 0; r < 20000; ++r) {
        const Ray ray = random_ray(rng, m);
        MeshHit a, b;
        const bool ha = mesh_kernels_base().closest(m.view, ray, kInfinity, &a);
        const bool hb = avx2->closest(m.view, ray, kInfinity, &b);
        ASSERT_EQ(ha, hb) << "ray " << r;
        if (ha) expect_same(a, b);
    }
}

// The box test runs in single precision and must never cull a box the exact ray enters: at
// any scale of the scene, from origins far beyond the mesh, with direction components whose
// reciprocals overflow or underflow a float, and along axes through box planes. Each closest
// and any-hit answer is the brute force's over every triangle.
TEST(MeshKernels, FloatBoxTestNeverCullsAHitAtAnyScale) {
    std::vector<const MeshKernels*> builds{&mesh_kernels_base()};
    if (mesh_kernels_avx2()) builds.push_back(mesh_kernels_avx2());
    int hits = 0;
    for (double scale : {1e-30, 1e-8, 1.0, 1e8, 1e33}) {
        std::mt19937_64 rng(static_cast<uint64_t>(std::log2(scale) + 200));
        const TestMesh m = make_test_mesh(rng, 400, scale);
        for (int r = 0; r < 3000; ++r) {
            Ray ray = random_ray(rng, m, scale);
            switch (r % 6) {
                case 1:  // from far back along the ray, up to 1e36 times the mesh's size
                    ray.origin = ray.origin - ray.dir * std::ldexp(1.0, static_cast<int>(rng() % 120));
                    break;
                case 2:  // reciprocals beyond the float range
                    ray.dir = ray.dir * 1e-42;
                    break;
                case 3:  // reciprocals that underflow a float
                    ray.dir = ray.dir * 1e270;
                    break;
                case 4:  // one tiny component: 1 / dir overflows along one axis only
                    ray.dir[static_cast<int>(rng() % 3)] *= 1e-300;
                    break;
                case 5:  // an origin on a vertex's plane, with no motion across it
                    if (ray.dir.x != 0) {
                        ray.origin.x = m.tri[rng() % m.tri.size()][0].x;
                        ray.dir.x = 0;
                    }
                    break;
                default:
                    break;
            }
            if (!(length_squared(ray.dir) > 0) || !std::isfinite(length_squared(ray.dir))) continue;
            int want_i = -1;
            TriangleHit want;
            const bool want_hit = brute_closest(m, ray, kInfinity, &want_i, &want);
            hits += want_hit;
            for (const MeshKernels* k : builds) {
                MeshHit got;
                ASSERT_EQ(k->closest(m.view, ray, kInfinity, &got), want_hit)
                    << k->name << " scale " << scale << " ray " << r;
                EXPECT_EQ(k->any(m.view, ray, kInfinity), want_hit)
                    << k->name << " scale " << scale << " ray " << r;
                if (want_hit) {
                    EXPECT_EQ(got.index, want_i) << k->name << " scale " << scale << " ray " << r;
                    EXPECT_EQ(got.th.t, want.t) << k->name << " scale " << scale << " ray " << r;
                }
            }
        }
    }
    EXPECT_GT(hits, 3000) << "the rays should hit often enough to test something";
}

// The float slab test against boxes built around a point the exact ray passes through, at
// t_hit: the box must be entered, no later than t_hit, whatever the scale of the scene, the
// distance of the origin, the length of the direction (reciprocals that overflow a float or
// fall among its subnormals), zero or tiny components, and a tmax just past t_hit. The other
// lanes hold empty boxes or random ones.
TEST(MeshKernels, BoxTestEntersEveryBoxTheRayPassesThrough) {
    std::vector<const MeshKernels*> builds{&mesh_kernels_base()};
    if (mesh_kernels_avx2()) builds.push_back(mesh_kernels_avx2());
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1), pos(0.001, 1);
    auto pow10 = [&](int lo, int hi) { return std::pow(10.0, lo + static_cast<int>(rng() % (hi - lo + 1))); };
    int checked = 0;
    for (int i = 0; i < 60000; ++i) {
        const double scale = pow10(-30, 30);
        Ray ray;
        ray.origin = Vec3{u(rng), u(rng), u(rng)} * scale * pow10(0, 6);
        ray.dir = Vec3{u(rng), u(rng), u(rng)};
        switch (i % 5) {
            case 1: ray.dir = ray.dir * pow10(-39, 39); break;  // reciprocals out of float range
            case 2: ray.dir[static_cast<int>(rng() % 3)] = 0; break;
            case 3: ray.dir[static_cast<int>(rng() % 3)] *= 1e-300; break;
            default: break;
        }
        if (!(length_squared(ray.dir) > 0)) continue;
        // The point at t_hit, and a box about it whose half-sizes cover its rounding error.
        const double t_hit = scale * pos(rng) / length(ray.dir);
        const Vec3 q = ray.origin + ray.dir * t_hit;
        WideNode node;
        std::uniform_int_distribution<int> lane_of(0, 7);
        const int lane = lane_of(rng);
        for (int l = 0; l < 8; ++l) {
            for (int a = 0; a < 3; ++a) {
                double lo = kInfinity, hi = -kInfinity;  // empty
                if (l == lane) {
                    const double err = 0x1p-50 * (std::fabs(ray.origin[a]) + std::fabs(ray.dir[a] * t_hit));
                    const double r = std::max(err, scale * pos(rng) * pow10(-9, 0));
                    lo = q[a] - r;
                    hi = q[a] + r;
                } else if (rng() % 2) {
                    const double c = u(rng) * scale * 4;
                    lo = c - scale * pos(rng);
                    hi = c + scale * pos(rng);
                }
                node.box[a][l] = float_down(lo);
                node.box[3 + a][l] = float_up(hi);
            }
        }
        bool skip = false;
        for (int a = 0; a < 6; ++a) skip = skip || !(std::fabs(node.box[a][lane]) < 1e37f);
        if (skip) continue;  // past the plane limit, where boxes are pushed out to infinity
        const double tmax = rng() % 2 ? kInfinity : t_hit * (1 + 1e-12);
        for (const MeshKernels* k : builds) {
            float t_enter[8];
            const int mask = k->enter_boxes(node, ray, tmax, t_enter);
            ASSERT_TRUE(mask >> lane & 1)
                << k->name << " case " << i << " scale " << scale << " origin " << ray.origin.x
                << " " << ray.origin.y << " " << ray.origin.z << " dir " << ray.dir.x << " "
                << ray.dir.y << " " << ray.dir.z;
            EXPECT_LE(t_enter[lane], t_hit) << k->name << " case " << i;
        }
        ++checked;
    }
    EXPECT_GT(checked, 40000);
}

// Equal t everywhere: coplanar copies of one triangle under different face indices. The lower
// face wins whichever leaf or lane it lands in.
TEST(MeshKernels, EqualTGoesToTheLowerFace) {
    scene::Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 37; ++i) {
        scene::MeshFace f;
        f.v = {0, 1, 2};
        f.material = 36 - i;  // material tells which face answered
        mesh.faces.push_back(f);
    }
    Diagnostics diag;
    auto prim = make_mesh(mesh, diag);
    ASSERT_TRUE(prim);
    LocalHit h;
    ASSERT_TRUE(prim->intersect({{0.2, 0.2, -1}, {0, 0, 1}, kInfinity}, kInfinity, &h));
    EXPECT_EQ(h.material, 36);  // face 0's
}

// A mesh far from the origin keeps its detail: the vertices are floats relative to the mesh's
// centre, so a tiny triangle 1e5 units out is hit where the double-precision test says.
TEST(MeshKernels, FarMeshKeepsItsPrecision) {
    scene::Mesh mesh;
    const Vec3 at(1e5, -2e5, 3e5);
    mesh.positions = {at, at + Vec3(1e-4, 0, 0), at + Vec3(0, 1e-4, 0)};
    scene::MeshFace f;
    f.v = {0, 1, 2};
    mesh.faces.push_back(f);
    Diagnostics diag;
    auto prim = make_mesh(mesh, diag);
    ASSERT_TRUE(prim);
    LocalHit h;
    const Vec3 target = at + Vec3(0.25e-4, 0.25e-4, 0);
    ASSERT_TRUE(prim->intersect({target - Vec3(0, 0, 1), {0, 0, 1}, kInfinity}, kInfinity, &h));
    EXPECT_NEAR(h.t, 1.0, 1e-9);
    EXPECT_LT(length(h.p - target), 1e-9);
    EXPECT_LE(std::fabs(h.p.z - at.z), h.p_error.z);
    // Just outside its hypotenuse: a miss, not a float-rounded hit.
    const Vec3 outside = at + Vec3(0.5001e-4, 0.5001e-4, 0);
    EXPECT_FALSE(prim->intersect({outside - Vec3(0, 0, 1), {0, 0, 1}, kInfinity}, kInfinity, &h));
}

}  // namespace
}  // namespace glint::render
