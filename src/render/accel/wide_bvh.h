// A four-wide BVH for triangle meshes, made by collapsing the binary SAH tree (bvh.h): each node
// holds the boxes of up to four children side by side, so one SIMD slab test (mesh_kernels.inc)
// answers all four, and the tree is about half as deep. The binary tree's leaves stay the leaves,
// with their triangles contiguous in its order() sequence.
#pragma once

#include <cstdint>
#include <vector>

#include "render/accel/bvh.h"
#include "render/accel/huge_pages.h"

namespace glint::render {

// 128 bytes, two cache lines (aligned to them). Lane i is empty when count[i] == 0 and child[i] == kEmpty: its box
// is inverted (lo = +inf, hi = -inf), which no ray enters.
struct alignas(64) WideNode {
    static constexpr int32_t kEmpty = INT32_MIN;
    float box[6][4];   // [plane][lane]: lo x, lo y, lo z, hi x, hi y, hi z; floats rounded outwards
    int32_t child[4];  // >= 0: index of a node; < 0 (not kEmpty): leaf, ~child is its first primitive
    uint8_t count[4];  // primitives of a leaf child; 0 for a node
    uint8_t pad[12];
};
static_assert(sizeof(WideNode) == 128);

class WideBvh {
public:
    using Nodes = std::vector<WideNode, HugePageAllocator<WideNode>>;
    WideBvh() = default;
    // From a binary tree of more than one node; leaf primitives keep bvh.order() positions.
    explicit WideBvh(const Bvh& bvh);

    const Nodes& nodes() const { return nodes_; }
    int depth() const { return depth_; }
    // Traversal stack entries the deepest path can need: three siblings wait at each level.
    static constexpr int kMaxDepth = 84;
    static constexpr int kStackSize = 3 * kMaxDepth + 4;

private:
    int emit(const Bvh& bvh, int binary_node, int depth);

    Nodes nodes_;
    int depth_ = 0;
};

}  // namespace glint::render
