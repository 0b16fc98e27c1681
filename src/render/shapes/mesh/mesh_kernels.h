// The inner loops of mesh intersection: the eight-wide BVH's slab tests, eight boxes at a time
// in single precision and conservative, and the watertight triangle test, four at a time in
// double precision. Built twice from mesh_kernels.inc, for AVX2 with FMA and for any x86-64,
// with the triangle test's operations in the same order, so both give the same hits bit for
// bit (the box test's fused multiply-adds may round its entry distances differently, which
// may change the order of the walk, but it is conservative either way: closest() and any()
// answer alike, all() gives the same hits, perhaps in another order); mesh_kernels() picks
// one for this CPU once. Used by MeshPrim (mesh_prim.cpp) and measured by
// bench/traversal_bench.
#pragma once

#include <limits>

#include "render/accel/wide_bvh.h"
#include "render/ray.h"
#include "render/shapes/mesh/triangle.h"

namespace glint::render {

// A mesh as the kernels see it: triangles in BVH leaf order, each leaf's laid out by component
// so that four neighbours load as one vector. For a leaf of n triangles from position f,
// tris[10f + k n + j] is component k (= 3 vertex + axis) of triangle f + j for k < 9, and for
// k = 9 the bits of its face index as an int32 (what breaks equal-t ties: the lower wins; kept
// beside the corners, not in an array of its own, to save a cache miss per hit). Then 4 floats
// of padding that partial loads may read.
struct MeshView {
    const WideNode* nodes = nullptr;  // null: the whole mesh is one leaf
    const float* tris = nullptr;
    int count = 0;  // triangles
    // The nodes' WideBvh::reach(); infinite (unknown) keeps the box test to its exact form.
    float reach = std::numeric_limits<float>::infinity();
};

// How a mesh's binary SAH tree (built with leaves of up to 16, four triangles a test) is
// collapsed into the kernels' eight-wide one: a node visit priced as one and a half
// four-triangle tests, subtrees of up to 16 triangles merged into one leaf where that costs
// less. Against the greedy collapse before it (open the largest child until eight, which left
// a third of the nodes with two lanes on traversal_bench's 1M mesh) 47.9 bytes a triangle
// instead of 54.1, and 1.05x, 1.14x, 1.20x the speed of coherent, incoherent closest-hit and
// any-hit queries (4 alternating runs; a price of one: 1.07x, 1.17x, 1.06x in 49.2 bytes;
// two: 1.12x, 1.04x, 1.15x in 47.3). In cache the count of instructions hardly moves (2% fewer
// on the 10k mesh): the gain is fewer nodes to fetch.
inline constexpr WideBvh::Costs kMeshCollapse{4, 16, 1.5};

struct MeshHit {
    int index = -1;  // position in leaf order
    TriangleHit th;
    Vec3 p[3];       // the triangle's vertices
};

// Receives each hit of all(): position, hit and vertices.
using MeshHitSink = void (*)(void* ctx, const MeshHit& hit);
// Receives each leaf a walk() reaches: its first primitive (a position in the BVH's order())
// and count; may lower *tmax; returning true ends the walk.
using WideLeafFn = bool (*)(void* ctx, int first, int count, double* tmax);

struct MeshKernels {
    // Nearest hit with 0 < t < tmax; equal t goes to the lower face.
    bool (*closest)(const MeshView& mesh, const Ray& ray, double tmax, MeshHit* hit);
    // Any hit with 0 < t < tmax.
    bool (*any)(const MeshView& mesh, const Ray& ray, double tmax);
    // Every hit with 0 < t < tmax, in no particular order.
    void (*all)(const MeshView& mesh, const Ray& ray, double tmax, MeshHitSink sink, void* ctx);
    // The eight-wide tree alone, nearest box first, for primitives other than triangles (the
    // scene's objects): leaf() for every leaf the ray enters within *tmax. With no nodes, one
    // leaf of all `count` primitives; `reach` is the tree's WideBvh::reach(). Returns whether
    // a leaf ended it.
    bool (*walk)(const WideNode* nodes, int count, float reach, const Ray& ray, double* tmax,
                 WideLeafFn leaf, void* ctx);
    // For tests: the slab test of one node's eight boxes, as the walks run it: the lanes the
    // ray enters within [0, tmax], as bits, and where it enters them.
    int (*enter_boxes)(const WideNode& node, const Ray& ray, double tmax, float t_enter[8]);
    const char* name;
};

// The kernels for this CPU: AVX2 where it has it.
const MeshKernels& mesh_kernels();
// Each build by name (tests compare them); avx2 is null on a CPU without AVX2.
const MeshKernels& mesh_kernels_base();
const MeshKernels* mesh_kernels_avx2();

}  // namespace glint::render
