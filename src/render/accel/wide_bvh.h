// An eight-wide BVH for triangle meshes and the scene's objects, made by collapsing the binary
// SAH tree (bvh.h): each node holds the boxes of up to eight children side by side, so one SIMD
// slab test in single precision (mesh_kernels.inc) answers all eight, and the tree is about a
// third as deep as the binary one. Which binary nodes become wide nodes, which are opened into
// their parent's lanes and which subtrees become one leaf is chosen for the least SAH cost
// (the dynamic programme of Ylitie, Karras and Laine, "Efficient incoherent ray traversal on
// GPUs through compressed wide BVHs", 2017), so a leaf is always a run of the binary tree's
// order() sequence.
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
    static constexpr int64_t leaf_first(int64_t ref) { return (-ref - 1) >> 8; }
    static constexpr int leaf_count(int64_t ref) { return static_cast<int>((-ref - 1) & 255); }
    float box[6][kWidth];  // [plane][lane]: lo x, lo y, lo z, hi x, hi y, hi z
    int64_t ref[kWidth];
};
static_assert(sizeof(WideNode) == 256);

class WideBvh {
public:
    using Nodes = std::vector<WideNode, HugePageAllocator<WideNode>>;
    // The SAH prices, in units of one primitive test: a leaf of n primitives costs its area
    // times ceil(n / block) tests (the mesh kernels test four triangles at once), a wide node
    // its area times `node`. A subtree of up to `max_leaf` primitives may become one leaf
    // (at most 255, WideNode's encoding); 0 keeps the binary tree's leaves as they are.
    struct Costs {
        int block = 1;
        int max_leaf = 0;
        double node = 1.0;
    };

    WideBvh() = default;
    // From a binary tree of more than one node; leaf primitives keep bvh.order() positions.
    explicit WideBvh(const Bvh& bvh) : WideBvh(bvh, Costs{}) {}
    WideBvh(const Bvh& bvh, const Costs& costs);

    const Nodes& nodes() const { return nodes_; }
    int depth() const { return depth_; }
    // The largest magnitude of any finite box plane (0 for an empty tree): what the box
    // test's fast form (mesh_kernels.inc, BoxRay) bounds its rounding by.
    float reach() const { return reach_; }
    // Calls leaf(first, count) for every leaf of the tree: runs of order() that together
    // cover it once.
    template <class Leaf>
    void for_each_leaf(Leaf&& leaf) const {
        for (const WideNode& n : nodes_)
            for (int64_t ref : n.ref)
                if (ref < 0 && WideNode::leaf_count(ref) > 0)
                    leaf(static_cast<int>(WideNode::leaf_first(ref)), WideNode::leaf_count(ref));
    }
    // Traversal stack entries the deepest path can need: seven siblings wait at each level.
    static constexpr int kMaxDepth = 84;
    static constexpr int kStackSize = (WideNode::kWidth - 1) * kMaxDepth + 4;

private:
    struct Plan;
    int emit(const Bvh& bvh, const Plan& plan, int binary_node, int depth);

    Nodes nodes_;
    int depth_ = 0;
    float reach_ = 0;
};

}  // namespace glint::render
