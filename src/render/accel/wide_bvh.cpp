#include "render/accel/wide_bvh.h"

#include <algorithm>
#include <limits>

#include "core/error.h"

namespace glint::render {
namespace {

double half_area(const Bvh::Node& n) {
    const double dx = n.box[1][0] - n.box[0][0], dy = n.box[1][1] - n.box[0][1],
                 dz = n.box[1][2] - n.box[0][2];
    return dx * dy + dy * dz + dz * dx;
}

// The plane clamping WideNode::kPlaneLimit describes; both only ever move a plane outwards.
float push_out_lo(float lo) {
    constexpr float kLimit = WideNode::kPlaneLimit;
    return lo < -kLimit ? -std::numeric_limits<float>::infinity() : std::min(lo, kLimit);
}
float push_out_hi(float hi) {
    constexpr float kLimit = WideNode::kPlaneLimit;
    return hi > kLimit ? std::numeric_limits<float>::infinity() : std::max(hi, -kLimit);
}

}  // namespace

WideBvh::WideBvh(const Bvh& bvh) {
    if (bvh.nodes().size() < 2) return;
    nodes_.reserve(bvh.nodes().size() / 2 + 1);
    emit(bvh, 0, 1);
    nodes_.shrink_to_fit();
}

int WideBvh::emit(const Bvh& bvh, int binary_node, int depth) {
    // Bvh stops splitting by SAH at depth 48 and halves by count below, so no mesh glint
    // accepts (--max-triangles) comes near this; the check keeps the traversal stack honest.
    if (depth > kMaxDepth)
        throw Error(ErrorKind::Render, {}, "internal error: mesh BVH deeper than the traversal stack");
    depth_ = std::max(depth_, depth);
    const auto& bn = bvh.nodes();
    // Up to eight children: open the largest interior child until there are eight.
    constexpr int kWidth = WideNode::kWidth;
    int kids[kWidth] = {binary_node + 1, bn[binary_node].index};
    int n = 2;
    while (n < kWidth) {
        int pick = -1;
        for (int i = 0; i < n; ++i)
            if (bn[kids[i]].count == 0 && (pick < 0 || half_area(bn[kids[i]]) > half_area(bn[kids[pick]])))
                pick = i;
        if (pick < 0) break;
        const int opened = kids[pick];
        kids[pick] = opened + 1;
        kids[n++] = bn[opened].index;
    }
    const int self = static_cast<int>(nodes_.size());
    WideNode node{};
    for (int lane = 0; lane < kWidth; ++lane) {
        for (int a = 0; a < 3; ++a) {
            node.box[a][lane] = std::numeric_limits<float>::infinity();
            node.box[3 + a][lane] = -std::numeric_limits<float>::infinity();
        }
        node.ref[lane] = WideNode::leaf_ref(0, 0);
    }
    nodes_.push_back(node);
    for (int lane = 0; lane < n; ++lane) {
        const Bvh::Node& c = bn[kids[lane]];
        const int64_t ref =
            c.count > 0 ? WideNode::leaf_ref(c.index, c.count) : emit(bvh, kids[lane], depth + 1);
        WideNode& w = nodes_[self];  // emit() may have grown nodes_
        for (int a = 0; a < 3; ++a) {
            w.box[a][lane] = push_out_lo(c.box[0][a]);
            w.box[3 + a][lane] = push_out_hi(c.box[1][a]);
        }
        w.ref[lane] = ref;
    }
    return self;
}

}  // namespace glint::render
