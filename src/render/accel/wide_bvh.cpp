#include "render/accel/wide_bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace glint::render {
namespace {

constexpr int kWidth = WideNode::kWidth;

// In double, and held finite: a box past the float range (a plane at infinity, and perhaps a
// zero extent beside it, inf * 0) would otherwise turn the costs into infinities or NaN.
double half_area(const Bvh::Node& n) {
    const double dx = static_cast<double>(n.box[1][0]) - n.box[0][0],
                 dy = static_cast<double>(n.box[1][1]) - n.box[0][1],
                 dz = static_cast<double>(n.box[1][2]) - n.box[0][2];
    const double area = dx * dy + dy * dz + dz * dx;
    constexpr double kHuge = 1e300;
    return area < kHuge ? area : kHuge;  // NaN too
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

// For each binary node n, what its subtree costs when it may fill up to i lanes of the wide
// node above it, i = 1 .. 8, and how. One lane: n becomes a leaf or a wide node of its own,
// whichever is cheaper. More lanes: either that, or n's two children share the lanes (k to
// the first, i - k to the second), n itself never stored. Costs are relative to the root's
// area, in floats: they only rank choices.
struct WideBvh::Plan {
    std::vector<std::array<float, kWidth>> cost;  // [n][i - 1]
    // [n][i - 1]: 0 where n takes one lane, else the lanes its first child gets.
    std::vector<std::array<uint8_t, kWidth>> split;
    std::vector<uint8_t> wide_split;  // n as a wide node: the lanes its first child gets
    std::vector<uint8_t> as_leaf;     // n in one lane: a leaf (1) or a wide node (0)
    std::vector<int> first, count;    // n's run of order()
};

WideBvh::WideBvh(const Bvh& bvh, const Costs& costs) {
    const auto& bn = bvh.nodes();
    if (bn.size() < 2) return;
    const size_t n_nodes = bn.size();
    const int block = std::max(costs.block, 1);
    const int max_leaf = std::clamp(costs.max_leaf, 0, 255);
    const double root_area = half_area(bn[0]);
    const double unit = root_area > 0 ? 1 / root_area : 1;
    constexpr float kNever = std::numeric_limits<float>::infinity();

    Plan plan;
    plan.cost.resize(n_nodes);
    plan.split.resize(n_nodes);
    plan.wide_split.assign(n_nodes, 0);
    plan.as_leaf.assign(n_nodes, 0);
    plan.first.resize(n_nodes);
    plan.count.resize(n_nodes);
    // Children follow their parent in bn (the first at n + 1, the second at bn[n].index), so
    // walking backwards meets every child before its parent.
    for (size_t k = n_nodes; k-- > 0;) {
        const Bvh::Node& node = bn[k];
        const double area = half_area(node) * unit;
        auto& cost = plan.cost[k];
        auto& split = plan.split[k];
        split.fill(0);
        if (node.count > 0) {
            plan.first[k] = node.index;
            plan.count[k] = node.count;
            plan.as_leaf[k] = 1;
            cost.fill(static_cast<float>(area * ((node.count + block - 1) / block)));
            continue;
        }
        const size_t a = k + 1, b = static_cast<size_t>(node.index);
        plan.first[k] = plan.first[a];
        plan.count[k] = plan.count[a] + plan.count[b];
        // shared[i - 1]: the least cost of the two children in i lanes between them. A split
        // is always recorded (one lane to the first child until a cheaper one is found), so
        // the lanes handed out never add up to more than eight.
        float shared[kWidth];
        uint8_t shared_k[kWidth] = {};
        shared[0] = kNever;
        for (int i = 2; i <= kWidth; ++i) {
            shared[i - 1] = kNever;
            shared_k[i - 1] = 1;
            for (int j = 1; j < i; ++j) {
                const float c = plan.cost[a][j - 1] + plan.cost[b][i - j - 1];
                if (c < shared[i - 1]) {
                    shared[i - 1] = c;
                    shared_k[i - 1] = static_cast<uint8_t>(j);
                }
            }
        }
        const int count = plan.count[k];
        const float leaf = count <= max_leaf
                               ? static_cast<float>(area * ((count + block - 1) / block))
                               : kNever;
        const float wide = static_cast<float>(costs.node * area) + shared[kWidth - 1];
        plan.wide_split[k] = shared_k[kWidth - 1];
        plan.as_leaf[k] = leaf <= wide;
        cost[0] = std::min(leaf, wide);
        for (int i = 2; i <= kWidth; ++i) {
            if (cost[0] <= shared[i - 1]) {
                cost[i - 1] = cost[0];
            } else {
                cost[i - 1] = shared[i - 1];
                split[i - 1] = shared_k[i - 1];
            }
        }
    }
    // Only the choices are kept from here on.
    plan.cost = {};
    nodes_.reserve(n_nodes / 4 + 1);
    emit(bvh, plan, 0, 1);
    nodes_.shrink_to_fit();
    for (const WideNode& node : nodes_)
        for (const auto& row : node.box)
            for (float p : row)
                if (std::fabs(p) < std::numeric_limits<float>::infinity())
                    reach_ = std::max(reach_, std::fabs(p));
}

int WideBvh::emit(const Bvh& bvh, const Plan& plan, int binary_node, int depth) {
    // Bvh stops splitting by SAH at depth 48 and halves by count below, so no mesh glint
    // accepts (--max-triangles) comes near this; the check keeps the traversal stack honest.
    if (depth > kMaxDepth)
        throw Error(ErrorKind::Render, {}, "internal error: mesh BVH deeper than the traversal stack");
    depth_ = std::max(depth_, depth);
    const auto& bn = bvh.nodes();
    // The binary nodes that fill this node's lanes, in the binary tree's order.
    int kids[kWidth];
    int n = 0;
    auto gather = [&](auto& self, int node, int lanes) -> void {
        const int k = lanes > 1 ? plan.split[node][lanes - 1] : 0;
        if (k == 0) {
            kids[n++] = node;
            return;
        }
        self(self, node + 1, k);
        self(self, bn[node].index, lanes - k);
    };
    const int k = plan.wide_split[binary_node];
    gather(gather, binary_node + 1, k);
    gather(gather, bn[binary_node].index, kWidth - k);

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
        const int c = kids[lane];
        const int64_t ref = plan.as_leaf[c] ? WideNode::leaf_ref(plan.first[c], plan.count[c])
                                            : emit(bvh, plan, c, depth + 1);
        WideNode& w = nodes_[self];  // emit() may have grown nodes_
        const Bvh::Node& box = bn[c];
        for (int a = 0; a < 3; ++a) {
            w.box[a][lane] = push_out_lo(box.box[0][a]);
            w.box[3 + a][lane] = push_out_hi(box.box[1][a]);
        }
        w.ref[lane] = ref;
    }
    return self;
}

}  // namespace glint::render
