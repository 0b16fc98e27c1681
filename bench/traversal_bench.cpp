// Ray traversal: glint's triangle-mesh primitive (its BVH and watertight triangle test, the path
// every mesh2 and OBJ face takes) against Embree 3 on the same triangles and the same rays, one
// thread each. Closest hit and any hit (shadow rays); coherent rays (a 1024x1024 pinhole camera
// in 8x8 tiles, as the renderer traces) and incoherent rays (2M, origins uniform in the mesh's
// box, directions uniform on the sphere); the coherent rays' closest hits also for the rays that
// hit the mesh and those that miss it apart (benchmark arguments 2 and 3), which cost very
// differently. Embree both in its default mode and in its robust (watertight) one, which is the
// guarantee glint's test gives. Also the build time and the bytes per triangle.
//
//   build/bench/traversal_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only
//   GLINT_BENCH_TRIS=100000 build/bench/traversal_bench     (default 1,000,000 triangles)
//
// items_per_second is rays per second. Embree is compared only where CMake found it
// (Debian: libembree-dev); without it the glint figures alone are built. Setup checks that
// both tracers agree on every ray's hit or miss and t, and prints any disagreement.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "core/log.h"
#include "render/accel/huge_pages.h"
#include "render/shapes/mesh/mesh_prim.h"
#include "scene/mesh.h"

#ifdef GLINT_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace {

using glint::Vec3;

// A unit sphere with radial bumps, as a latitude/longitude grid: 2 * nu * (nv - 1)
// triangles. Vertices are floats so that Embree and glint test exactly the same triangles.
struct TestMesh {
    std::vector<float> xyz;  // 3 per vertex, plus one float of padding (Embree reads 16 bytes)
    std::vector<uint32_t> idx;
    size_t vertices() const { return (xyz.size() - 1) / 3; }
    size_t triangles() const { return idx.size() / 3; }
};

TestMesh make_bumpy_sphere(size_t target) {
    const size_t nv = std::max<size_t>(3, static_cast<size_t>(std::sqrt(target / 4.0) + 0.5));
    const size_t nu = 2 * nv;
    TestMesh m;
    auto push = [&](double x, double y, double z) {
        m.xyz.push_back(static_cast<float>(x));
        m.xyz.push_back(static_cast<float>(y));
        m.xyz.push_back(static_cast<float>(z));
    };
    auto radius = [](double th, double ph) {
        return 1 + 0.04 * std::sin(11 * th) * std::cos(9 * ph);
    };
    push(0, radius(0, 0), 0);  // north pole
    for (size_t j = 1; j < nv; ++j) {
        const double th = M_PI * static_cast<double>(j) / static_cast<double>(nv);
        for (size_t i = 0; i < nu; ++i) {
            const double ph = 2 * M_PI * static_cast<double>(i) / static_cast<double>(nu);
            const double r = radius(th, ph);
            push(r * std::sin(th) * std::cos(ph), r * std::cos(th), r * std::sin(th) * std::sin(ph));
        }
    }
    push(0, -radius(M_PI, 0), 0);  // south pole
    const auto south = static_cast<uint32_t>(m.xyz.size() / 3 - 1);
    auto at = [&](size_t ring, size_t i) {
        return static_cast<uint32_t>(1 + (ring - 1) * nu + i % nu);
    };
    auto tri = [&](uint32_t a, uint32_t b, uint32_t c) { m.idx.insert(m.idx.end(), {a, b, c}); };
    for (size_t i = 0; i < nu; ++i) tri(0, at(1, i + 1), at(1, i));
    for (size_t j = 1; j + 1 < nv; ++j)
        for (size_t i = 0; i < nu; ++i) {
            tri(at(j, i), at(j, i + 1), at(j + 1, i + 1));
            tri(at(j, i), at(j + 1, i + 1), at(j + 1, i));
        }
    for (size_t i = 0; i < nu; ++i) tri(at(nv - 1, i), at(nv - 1, i + 1), south);
    m.xyz.push_back(0);
    return m;
}

struct RaySet {
    std::vector<float> o, d;  // 3 per ray
    size_t size() const { return o.size() / 3; }
};

// 1024 x 1024 pinhole rays, 40 degree field of view, from above and in front of the sphere,
// which fills most of the frame. Ordered by 8x8 tiles, each tile as four 4x4 blocks, so that
// 16 consecutive rays form one Embree packet and the single-ray loops see the renderer's order.
RaySet coherent_rays() {
    constexpr int kRes = 1024;
    const Vec3 eye{0.7, 1.8, 3.2};
    const Vec3 fw = glint::normalize(Vec3{0, 0, 0} - eye);
    const Vec3 right = glint::normalize(glint::cross(fw, Vec3{0, 1, 0}));
    const Vec3 up = glint::cross(right, fw);
    const double h = std::tan(20.0 * M_PI / 180.0);
    RaySet s;
    for (int ty = 0; ty < kRes; ty += 8)
        for (int tx = 0; tx < kRes; tx += 8)
            for (int q = 0; q < 4; ++q)
                for (int k = 0; k < 16; ++k) {
                    const int x = tx + (q % 2) * 4 + k % 4, y = ty + (q / 2) * 4 + k / 4;
                    const double u = (2 * (x + 0.5) / kRes - 1) * h, v = (1 - 2 * (y + 0.5) / kRes) * h;
                    const Vec3 d = glint::normalize(fw + right * u + up * v);
                    for (int a = 0; a < 3; ++a) {
                        s.o.push_back(static_cast<float>(eye[a]));
                        s.d.push_back(static_cast<float>(d[a]));
                    }
                }
    return s;
}

// 2M rays from points uniform in the mesh's box towards directions uniform on the sphere.
RaySet incoherent_rays() {
    constexpr size_t kCount = 2'000'000;
    uint64_t state = 0x9e3779b97f4a7c15ULL;
    auto uniform = [&] {  // splitmix64, top 24 bits
        uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z ^= z >> 31;
        return static_cast<double>(z >> 40) / 16777216.0;
    };
    RaySet s;
    for (size_t i = 0; i < kCount; ++i) {
        for (int a = 0; a < 3; ++a) s.o.push_back(static_cast<float>(-1.04 + 2.08 * uniform()));
        const double z = 1 - 2 * uniform(), phi = 2 * M_PI * uniform();
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        s.d.push_back(static_cast<float>(r * std::cos(phi)));
        s.d.push_back(static_cast<float>(r * std::sin(phi)));
        s.d.push_back(static_cast<float>(z));
    }
    return s;
}

size_t triangle_target() {
    const char* env = std::getenv("GLINT_BENCH_TRIS");
    const long n = env ? std::atol(env) : 1'000'000;
    return static_cast<size_t>(std::max(100L, n));
}

const TestMesh& test_mesh() {
    static const TestMesh m = make_bumpy_sphere(triangle_target());
    return m;
}
// The ray sets a benchmark's argument names: the coherent set, the incoherent set, and the
// coherent set's rays that hit the mesh and those that miss it (split by glint's query, which
// Embree agrees with but for a handful of rays through shared edges).
enum Set { kCoherent = 0, kIncoherent = 1, kCoherentHit = 2, kCoherentMiss = 3 };
RaySet hits_or_misses(const RaySet& rays, bool hits);
const RaySet& ray_set(int which) {
    static const RaySet coherent = coherent_rays();
    static const RaySet incoherent = incoherent_rays();
    switch (which) {
        case kCoherentHit: {
            static const RaySet hit = hits_or_misses(coherent, true);
            return hit;
        }
        case kCoherentMiss: {
            static const RaySet miss = hits_or_misses(coherent, false);
            return miss;
        }
        default:
            return which == kCoherent ? coherent : incoherent;
    }
}

glint::render::Ray glint_ray(const RaySet& s, size_t i) {
    return {{s.o[3 * i], s.o[3 * i + 1], s.o[3 * i + 2]},
            {s.d[3 * i], s.d[3 * i + 1], s.d[3 * i + 2]},
            glint::kInfinity};
}

glint::scene::Mesh glint_mesh(const TestMesh& m) {
    glint::scene::Mesh g;
    for (size_t v = 0; v < m.vertices(); ++v)
        g.positions.push_back({m.xyz[3 * v], m.xyz[3 * v + 1], m.xyz[3 * v + 2]});
    for (size_t t = 0; t < m.triangles(); ++t) {
        glint::scene::MeshFace f;
        for (int k = 0; k < 3; ++k) f.v[k] = static_cast<int>(m.idx[3 * t + k]);
        g.faces.push_back(f);
    }
    return g;
}

// Bytes in use, for the memory a build keeps: glibc's heap and the huge-page mappings glint
// makes for large BVH and triangle arrays (huge_pages.h), which malloc does not see.
size_t heap_in_use() {
    return mallinfo2().uordblks + mallinfo2().hblkhd + glint::render::huge_page_bytes().load();
}

struct GlintScene {
    std::unique_ptr<glint::render::Primitive> prim;
    size_t bytes = 0;  // everything the primitive holds: its copy of the mesh, triangles, BVH
};

GlintScene build_glint(const glint::scene::Mesh& mesh) {
    glint::Diagnostics diag;
    GlintScene s;
    const size_t before = heap_in_use();
    s.prim = glint::render::make_mesh(mesh, diag);
    s.bytes = heap_in_use() - before;
    return s;
}

const GlintScene& glint_scene() {
    static const GlintScene s = build_glint(glint_mesh(test_mesh()));
    return s;
}

const char* set_name(int which) {
    static const char* const kNames[] = {"coherent", "incoherent", "coherent, hits",
                                         "coherent, misses"};
    return kNames[which];
}

RaySet hits_or_misses(const RaySet& rays, bool hits) {
    const auto& prim = *glint_scene().prim;
    RaySet out;
    for (size_t i = 0; i < rays.size(); ++i) {
        glint::render::LocalHit h;
        if (prim.intersect(glint_ray(rays, i), glint::kInfinity, &h) != hits) continue;
        out.o.insert(out.o.end(), rays.o.begin() + 3 * i, rays.o.begin() + 3 * i + 3);
        out.d.insert(out.d.end(), rays.d.begin() + 3 * i, rays.d.begin() + 3 * i + 3);
    }
    return out;
}

// Rays per second (items) and the fraction of rays that hit, for a benchmark that traced every
// ray of `rays` per iteration.
void report(benchmark::State& state, const RaySet& rays, const char* label, size_t hits) {
    state.SetLabel(label);
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * rays.size()));
    state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(rays.size());
}

// Traces ray set state.range(0) one ray at a time: hit(i) says whether ray i hit.
template <class Hit>
void trace_one_by_one(benchmark::State& state, Hit&& hit) {
    const int which = static_cast<int>(state.range(0));
    const RaySet& rays = ray_set(which);
    size_t hits = 0;
    for (auto _ : state) {
        hits = 0;
        for (size_t i = 0; i < rays.size(); ++i) hits += hit(rays, i);
    }
    report(state, rays, set_name(which), hits);
}

void BM_GlintBuild(benchmark::State& state) {
    const glint::scene::Mesh mesh = glint_mesh(test_mesh());
    size_t bytes = 0;
    for (auto _ : state) {
        GlintScene s = build_glint(mesh);
        bytes = s.bytes;
        benchmark::DoNotOptimize(s.prim.get());
    }
    const double tris = static_cast<double>(test_mesh().triangles());
    state.counters["triangles"] = tris;
    state.counters["bytes_per_tri"] = static_cast<double>(bytes) / tris;
}
BENCHMARK(BM_GlintBuild)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_GlintClosest(benchmark::State& state) {
    const auto& prim = *glint_scene().prim;
    glint::render::LocalHit h;
    trace_one_by_one(state, [&](const RaySet& rays, size_t i) {
        return prim.intersect(glint_ray(rays, i), glint::kInfinity, &h);
    });
}
BENCHMARK(BM_GlintClosest)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_GlintOccluded(benchmark::State& state) {
    const auto& prim = *glint_scene().prim;
    trace_one_by_one(state, [&](const RaySet& rays, size_t i) {
        return prim.occludes(glint_ray(rays, i), glint::kInfinity);
    });
}
BENCHMARK(BM_GlintOccluded)->Arg(1)->Unit(benchmark::kMillisecond);

// The BVH query alone (mesh_kernels.h: the walk and the watertight test, giving t, the
// barycentrics, the face and its corners), the counterpart of rtcIntersect1 and rtcOccluded1.
// The primitive's queries above add the move into the mesh's frame and, for a hit, the record
// the renderer shades from (the point with its error bound, the unit normal, the material),
// which Embree leaves to its caller.
glint::render::MeshQuery glint_query() {
    const auto q = glint::render::mesh_query(*glint_scene().prim);
    if (!q) {
        std::fprintf(stderr, "traversal_bench: the mesh primitive has no query view\n");
        std::exit(1);
    }
    return *q;
}

glint::render::Ray query_ray(const glint::render::MeshQuery& q, const RaySet& rays, size_t i) {
    glint::render::Ray r = glint_ray(rays, i);
    r.origin = r.origin - q.origin;
    return r;
}

void BM_GlintQueryClosest(benchmark::State& state) {
    const glint::render::MeshQuery q = glint_query();
    const glint::render::MeshKernels& k = glint::render::mesh_kernels();
    glint::render::MeshHit h;
    trace_one_by_one(state, [&](const RaySet& rays, size_t i) {
        return k.closest(*q.view, query_ray(q, rays, i), glint::kInfinity, &h);
    });
}
BENCHMARK(BM_GlintQueryClosest)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

void BM_GlintQueryOccluded(benchmark::State& state) {
    const glint::render::MeshQuery q = glint_query();
    const glint::render::MeshKernels& k = glint::render::mesh_kernels();
    trace_one_by_one(state, [&](const RaySet& rays, size_t i) {
        return k.any(*q.view, query_ray(q, rays, i), glint::kInfinity);
    });
}
BENCHMARK(BM_GlintQueryOccluded)->Arg(1)->Unit(benchmark::kMillisecond);

#ifdef GLINT_HAVE_EMBREE

// One Embree device on one thread (its own build threads too), medium build quality (its
// default), the mesh's arrays shared rather than copied. Robust: RTC_SCENE_FLAG_ROBUST, Embree's
// watertight mode (no ray slips through a shared edge), the guarantee glint's test gives.
struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    size_t bvh_bytes = 0;
    bool robust = false;
    explicit EmbreeScene(bool robust_ = false) : robust(robust_) {
        device = rtcNewDevice("threads=1");
        rtcSetDeviceMemoryMonitorFunction(
            device,
            [](void* user, ssize_t bytes, bool) {
                *static_cast<size_t*>(user) += static_cast<size_t>(bytes);
                return true;
            },
            &bvh_bytes);
    }
    ~EmbreeScene() {
        if (scene) rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
    void build(const TestMesh& m) {
        if (scene) rtcReleaseScene(scene);
        bvh_bytes = 0;
        scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
        if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, m.xyz.data(),
                                   0, 3 * sizeof(float), m.vertices());
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m.idx.data(), 0,
                                   3 * sizeof(uint32_t), m.triangles());
        rtcCommitGeometry(g);
        rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        rtcCommitScene(scene);
    }
    // The BVH and the shared vertex and index arrays.
    size_t bytes(const TestMesh& m) const {
        return bvh_bytes + m.xyz.size() * sizeof(float) + m.idx.size() * sizeof(uint32_t);
    }
};

EmbreeScene& embree_scene(bool robust = false) {
    static EmbreeScene fast, watertight(true);
    EmbreeScene& s = robust ? watertight : fast;
    if (!s.scene) s.build(test_mesh());
    return s;
}

RTCRayHit embree_ray(const RaySet& s, size_t i) {
    RTCRayHit rh{};
    rh.ray.org_x = s.o[3 * i];
    rh.ray.org_y = s.o[3 * i + 1];
    rh.ray.org_z = s.o[3 * i + 2];
    rh.ray.dir_x = s.d[3 * i];
    rh.ray.dir_y = s.d[3 * i + 1];
    rh.ray.dir_z = s.d[3 * i + 2];
    rh.ray.tnear = 0;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

void BM_EmbreeBuild(benchmark::State& state) {
    EmbreeScene s;
    for (auto _ : state) s.build(test_mesh());
    const double tris = static_cast<double>(test_mesh().triangles());
    state.counters["triangles"] = tris;
    state.counters["bytes_per_tri"] = static_cast<double>(s.bytes(test_mesh())) / tris;
}
BENCHMARK(BM_EmbreeBuild)->Unit(benchmark::kMillisecond)->Iterations(1);

void embree_closest(benchmark::State& state, bool robust) {
    RTCScene scene = embree_scene(robust).scene;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    trace_one_by_one(state, [&](const RaySet& rays, size_t i) {
        RTCRayHit rh = embree_ray(rays, i);
        rtcIntersect1(scene, &ctx, &rh);
        return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    });
}
void BM_EmbreeClosest(benchmark::State& state) { embree_closest(state, false); }
BENCHMARK(BM_EmbreeClosest)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
// The same queries in Embree's robust mode.
void BM_EmbreeRobustClosest(benchmark::State& state) { embree_closest(state, true); }
BENCHMARK(BM_EmbreeRobustClosest)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

// 16-wide packets of 4x4 pixels: Embree's fastest mode for camera rays.
void BM_EmbreeClosest16(benchmark::State& state) {
    const RaySet& rays = ray_set(0);
    RTCScene scene = embree_scene().scene;
    size_t hits = 0;
    alignas(64) int valid[16];
    for (int& v : valid) v = -1;
    for (auto _ : state) {
        hits = 0;
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        alignas(64) RTCRayHit16 p;
        for (size_t base = 0; base < rays.size(); base += 16) {
            for (int k = 0; k < 16; ++k) {
                const size_t i = base + static_cast<size_t>(k);
                p.ray.org_x[k] = rays.o[3 * i];
                p.ray.org_y[k] = rays.o[3 * i + 1];
                p.ray.org_z[k] = rays.o[3 * i + 2];
                p.ray.dir_x[k] = rays.d[3 * i];
                p.ray.dir_y[k] = rays.d[3 * i + 1];
                p.ray.dir_z[k] = rays.d[3 * i + 2];
                p.ray.tnear[k] = 0;
                p.ray.tfar[k] = INFINITY;
                p.ray.mask[k] = ~0u;
                p.ray.time[k] = 0;
                p.ray.flags[k] = 0;
                p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
            }
            rtcIntersect16(valid, scene, &ctx, &p);
            for (int k = 0; k < 16; ++k) hits += p.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
        }
    }
    report(state, rays, "coherent", hits);
}
BENCHMARK(BM_EmbreeClosest16)->Unit(benchmark::kMillisecond);

void embree_occluded(benchmark::State& state, bool robust) {
    RTCScene scene = embree_scene(robust).scene;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    trace_one_by_one(state, [&](const RaySet& rays, size_t i) {
        RTCRay r = embree_ray(rays, i).ray;
        rtcOccluded1(scene, &ctx, &r);
        return r.tfar < 0;
    });
}
void BM_EmbreeOccluded(benchmark::State& state) { embree_occluded(state, false); }
BENCHMARK(BM_EmbreeOccluded)->Arg(1)->Unit(benchmark::kMillisecond);
void BM_EmbreeRobustOccluded(benchmark::State& state) { embree_occluded(state, true); }
BENCHMARK(BM_EmbreeRobustOccluded)->Arg(1)->Unit(benchmark::kMillisecond);

// Not timed: both tracers must find the same hit or miss, at the same distance (to 1e-4
// relative: Embree's float against glint's double arithmetic), for every ray of both sets.
// Disagreements are printed before the timings.
void check_agreement() {
    const auto& prim = *glint_scene().prim;
    RTCScene scene = embree_scene().scene;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (int which = 0; which < 2; ++which) {
        const RaySet& rays = ray_set(which);
        size_t differ = 0, edge = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            glint::render::LocalHit h;
            const bool g = prim.intersect(glint_ray(rays, i), glint::kInfinity, &h);
            RTCRayHit rh = embree_ray(rays, i);
            rtcIntersect1(scene, &ctx, &rh);
            const bool e = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            if (g != e) {
                ++edge;  // a ray through a shared edge or vertex: float vs double
            } else if (g && std::fabs(h.t - rh.ray.tfar) > 1e-4 * std::max(1.0, h.t)) {
                ++differ;
            }
        }
        std::printf("agreement, %s rays: %zu of %zu differ in t, %zu in hit or miss\n",
                    set_name(which), differ, rays.size(), edge);
    }
}

#endif  // GLINT_HAVE_EMBREE

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    std::printf("mesh: bumpy sphere, %zu triangles\n", test_mesh().triangles());
#ifdef GLINT_HAVE_EMBREE
    check_agreement();
#else
    std::printf("Embree not found at configure time: glint's figures only\n");
#endif
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
