// The mesh kernels (render/shapes/mesh_kernels.h) and the mesh primitive on top of them: the
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
#include "render/shapes/mesh_kernels.h"
#include "render/shapes/mesh_prim.h"
#include "render/shapes/triangle.h"

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
TestMesh make_test_mesh(std::mt19937_64& rng, int n, double scale = 1) {
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
        for (const auto& node : bvh.nodes())
            if (node.count > 0) leaf(node.index, node.count);
        m.wide = WideBvh(bvh);
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

void check_against_brute_force(const MeshKernels& k, int triangles, uint64_t seed) {
    std::mt19937_64 rng(seed);
    const TestMesh m = make_test_mesh(rng, triangles);
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

// The box set-up rounds the ray's origin and reciprocals to floats on a chosen side four lanes
// at a time; each build must give exactly float_up and float_down, on values that round either
// way, on zeros of both signs, subnormals, the edges of the float range, infinities and NaN.
TEST(MeshKernels, VectorDirectedRoundingsMatchTheScalarOnes) {
    std::vector<const MeshKernels*> builds{&mesh_kernels_base()};
    if (mesh_kernels_avx2()) builds.push_back(mesh_kernels_avx2());
    const double fmax = std::numeric_limits<float>::max();
    const double fmin = std::numeric_limits<float>::min();
    const double fsub = std::numeric_limits<float>::denorm_min();
    std::vector<double> values = {0.0, -0.0, 1.0, -1.0, 1.0 / 3, -1.0 / 3, 0.1, -0.1,
                                  fmax, -fmax, std::nextafter(fmax, kInfinity),
                                  -std::nextafter(fmax, kInfinity), fmax * 2, -fmax * 2,
                                  fmin, -fmin, fmin / 3, -fmin / 3, fsub, -fsub, fsub / 4,
                                  -fsub / 4, 1e-300, -1e-300, 1e300, -1e300, kInfinity,
                                  -kInfinity, std::nan("")};
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> mant(-1, 1);
    for (int i = 0; i < 4000; ++i)
        values.push_back(std::ldexp(mant(rng), static_cast<int>(rng() % 320) - 160));
    while (values.size() % 4) values.push_back(0.5);
    for (const MeshKernels* k : builds) {
        for (size_t i = 0; i < values.size(); i += 4) {
            float up[4], down[4];
            k->round4(&values[i], up, down);
            for (int l = 0; l < 4; ++l) {
                const double v = values[i + l];
                const float want_up = float_up(v), want_down = float_down(v);
                EXPECT_EQ(std::memcmp(&up[l], &want_up, sizeof up[l]), 0)
                    << k->name << " up " << v << ": " << up[l] << " vs " << want_up;
                EXPECT_EQ(std::memcmp(&down[l], &want_down, sizeof down[l]), 0)
                    << k->name << " down " << v << ": " << down[l] << " vs " << want_down;
                if (!std::isnan(v)) {
                    EXPECT_LE(down[l], v) << k->name << " " << v;
                    EXPECT_GE(up[l], v) << k->name << " " << v;
                }
            }
        }
    }
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
