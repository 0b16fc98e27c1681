// An eight-wide BVH for triangle meshes and the scene's objects, made by collapsing the binary
// SAH tree (bvh.h): each node holds the boxes of up to eight children side by side, so one SIMD
// slab test in single precision (mesh_kernels.inc) answers all eight, and the tree is about a
// third as deep as the binary one. The binary tree's leaves stay the leaves, with their
// primitives contiguous in its order() sequence.
#pragma once

#include <cstdint>
#include <vector>

#include "render/accel/bvh.h"
#include "render/accel/huge_pages.h"

namespace glint::render {

// 256 bytes, four cache lines (aligned to them): the boxes in the first three, the children's
// references in the last.
struct alignas(64) WideNode {
    static constexpr int kWidth = 8;
    // Box planes are floats rounded outwards, then pushed out to an infinity past +-kPlaneLimit
    // (or, for a box wholly beyond it, in to the limit): so a plane minus a clamped ray origin
    // never overflows to the wrong infinity in the float slab test.
    static constexpr float kPlaneLimit = 1e38f;
    // A lane's child: >= 0, a node's index; < 0, a leaf as -(first * 256 + count) - 1, with
    // `first` its first primitive. An empty lane is a leaf of no primitives (-1) whose box is
    // inverted (lo = +inf, hi = -inf): no ray enters it but one whose origin lies past the
    // float range on every axis (the slab test's inf - inf leaves those planes out), and that
    // one finds nothing there.
    static constexpr int64_t leaf_ref(int64_t first, int count) { return -(first * 256 + count) - 1; }
    float box[6][kWidth];  // [plane][lane]: lo x, lo y, lo z, hi x, hi y, hi z
    int64_t ref[kWidth];
};
static_assert(sizeof(WideNode) == 256);

class WideBvh {
public:
    using Nodes = std::vector<WideNode, HugePageAllocator<WideNode>>;
    WideBvh() = default;
    // From a binary tree of more than one node; leaf primitives keep bvh.order() positions.
    explicit WideBvh(const Bvh& bvh);

    const Nodes& nodes() const { return nodes_; }
    int depth() const { return depth_; }
    // Traversal stack entries the deepest path can need: seven siblings wait at each level.
    static constexpr int kMaxDepth = 84;
    static constexpr int kStackSize = (WideNode::kWidth - 1) * kMaxDepth + 4;

private:
    int emit(const Bvh& bvh, int binary_node, int depth);

    Nodes nodes_;
    int depth_ = 0;
};

}  // namespace glint::render
