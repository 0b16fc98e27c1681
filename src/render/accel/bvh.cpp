#include "render/accel/bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint::render {

// The binary tree the SAH build makes before it is collapsed into the 4-wide one. Interior:
// `index` is the second child (the first follows the node), count == 0. Leaf: `index` is the
// first entry of the primitive order, count > 0.
struct BvhBinaryNode {
    float box[2][3];  // lo, hi
    int32_t index;
    uint16_t count;
};

namespace {

constexpr int kBins = 16;
// Deeper trees would overflow the traversal stack; past this depth splits are by count.
constexpr int kMaxSahDepth = 48;

double half_area(const Bounds3& b) {
    if (b.empty()) return 0;
    Vec3 d = b.diagonal();
    return d.x * d.y + d.y * d.z + d.z * d.x;
}

float half_area(const BvhBinaryNode& n) {
    const float dx = n.box[1][0] - n.box[0][0], dy = n.box[1][1] - n.box[0][1],
                dz = n.box[1][2] - n.box[0][2];
    return dx * dy + dy * dz + dz * dx;
}

class BinaryBuilder {
public:
    BinaryBuilder(const std::vector<Bounds3>& bounds, const std::vector<Vec3>& centroids,
                  int max_leaf)
        : bounds_(bounds), centroids_(centroids), max_leaf_(max_leaf) {}
    int build(std::vector<int>& ids, int begin, int end, int depth);
    std::vector<BvhBinaryNode> nodes;

private:
    const std::vector<Bounds3>& bounds_;
    const std::vector<Vec3>& centroids_;
    int max_leaf_;
};

}  // namespace

Bvh::Bvh(const std::vector<Bounds3>& prim_bounds, int max_leaf) {
    std::vector<int> ids;
    std::vector<Vec3> centroids(prim_bounds.size());
    for (size_t i = 0; i < prim_bounds.size(); ++i) {
        const Bounds3& b = prim_bounds[i];
        if (b.empty() || b.is_infinite()) continue;
        ids.push_back(static_cast<int>(i));
        centroids[i] = b.centroid();
    }
    if (ids.empty()) return;
    BinaryBuilder builder(prim_bounds, centroids, std::clamp(max_leaf, 1, 255));
    builder.nodes.reserve(2 * ids.size() / static_cast<size_t>(std::clamp(max_leaf, 1, 255)) + 1);
    builder.build(ids, 0, static_cast<int>(ids.size()), 1);
    order_ = std::move(ids);
    nodes_.reserve(builder.nodes.size() / 3 + 1);
    collapse(builder.nodes, 0, 1);
}

// Makes the 4-wide node for binary node `b` and its subtree: b's two children, then, while
// fewer than four, the inner child with the largest box replaced by its own two children.
// A binary tree that is a single leaf becomes a root with one leaf child.
int Bvh::collapse(const std::vector<BvhBinaryNode>& bin, int b, int depth) {
    depth_ = std::max(depth_, depth);
    const int self = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    {
        Node& n = nodes_[self];
        for (int k = 0; k < 4; ++k) {
            for (int a = 0; a < 3; ++a) {
                n.box[0][a][k] = std::numeric_limits<float>::infinity();
                n.box[1][a][k] = -std::numeric_limits<float>::infinity();
            }
            n.index[k] = -1;
            n.count[k] = 0;
        }
        n.valid = 0;
    }
    int kids[4], m = 0;
    if (bin[b].count > 0) {
        kids[m++] = b;
    } else {
        kids[m++] = b + 1;
        kids[m++] = bin[b].index;
        while (m < 4) {
            int open = -1;
            float best = -1;
            for (int k = 0; k < m; ++k)
                if (bin[kids[k]].count == 0 && half_area(bin[kids[k]]) > best) {
                    best = half_area(bin[kids[k]]);
                    open = k;
                }
            if (open < 0) break;
            const int c = kids[open];
            for (int k = m; k > open + 1; --k) kids[k] = kids[k - 1];
            kids[open] = c + 1;
            kids[open + 1] = bin[c].index;
            ++m;
        }
    }
    for (int k = 0; k < m; ++k) {
        const BvhBinaryNode& c = bin[kids[k]];
        int index = c.index;
        if (c.count == 0) index = collapse(bin, kids[k], depth + 1);
        Node& n = nodes_[self];  // collapse() may have moved the nodes
        for (int a = 0; a < 3; ++a) {
            n.box[0][a][k] = c.box[0][a];
            n.box[1][a][k] = c.box[1][a];
        }
        n.index[k] = index;
        n.count[k] = c.count;
        n.valid = static_cast<uint8_t>(n.valid | (1 << k));
    }
    return self;
}

Bounds3 Bvh::bounds() const {
    Bounds3 b;
    if (nodes_.empty()) return b;
    const Node& n = nodes_[0];
    for (int k = 0; k < 4; ++k) {
        if (!(n.valid & (1 << k))) continue;
        b.extend(Bounds3{{n.box[0][0][k], n.box[0][1][k], n.box[0][2][k]},
                         {n.box[1][0][k], n.box[1][1][k], n.box[1][2][k]}});
    }
    return b;
}

int BinaryBuilder::build(std::vector<int>& ids, int begin, int end, int depth) {
    const std::vector<Bounds3>& bounds = bounds_;
    const std::vector<Vec3>& centroids = centroids_;
    const int max_leaf = max_leaf_;
    std::vector<BvhBinaryNode>& nodes_ = nodes;
    int self = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Bounds3 box, cbox;
    for (int i = begin; i < end; ++i) {
        box.extend(bounds[ids[i]]);
        cbox.extend(centroids[ids[i]]);
    }
    auto set_leaf = [&]() {
        BvhBinaryNode& n = nodes_[self];
        n.index = begin;
        n.count = static_cast<uint16_t>(end - begin);
    };
    for (int a = 0; a < 3; ++a) {
        nodes_[self].box[0][a] = float_down(box.lo[a]);
        nodes_[self].box[1][a] = float_up(box.hi[a]);
    }
    int count = end - begin;
    if (count <= max_leaf) {
        set_leaf();
        return self;
    }
    int axis = 0;
    Vec3 ext = cbox.diagonal();
    if (ext.y > ext[axis]) axis = 1;
    if (ext.z > ext[axis]) axis = 2;

    int mid = -1;
    if (ext[axis] > 0 && depth < kMaxSahDepth) {
        // Binned SAH: cost of each of the kBins - 1 split planes along the widest centroid axis.
        struct Bin {
            Bounds3 b;
            int n = 0;
        } bins[kBins];
        double scale = kBins / ext[axis];
        auto bin_of = [&](int id) {
            int k = static_cast<int>((centroids[id][axis] - cbox.lo[axis]) * scale);
            return std::clamp(k, 0, kBins - 1);
        };
        for (int i = begin; i < end; ++i) {
            Bin& bin = bins[bin_of(ids[i])];
            bin.b.extend(bounds[ids[i]]);
            ++bin.n;
        }
        double left_area[kBins];
        int left_n[kBins];
        Bounds3 acc;
        int n = 0;
        for (int k = 0; k < kBins; ++k) {
            acc.extend(bins[k].b);
            n += bins[k].n;
            left_area[k] = half_area(acc);
            left_n[k] = n;
        }
        double best = kInfinity;
        int best_k = -1;
        acc = Bounds3();
        n = 0;
        for (int k = kBins - 1; k > 0; --k) {
            acc.extend(bins[k].b);
            n += bins[k].n;
            double cost = left_area[k - 1] * left_n[k - 1] + half_area(acc) * n;
            if (cost < best) {
                best = cost;
                best_k = k;
            }
        }
        double leaf_cost = half_area(box) * count;
        // Traversal costs about one primitive test per node (relative cost 1).
        if (count <= max_leaf * 4 && count <= 255 && leaf_cost <= best + half_area(box)) {
            set_leaf();
            return self;
        }
        if (best_k > 0) {
            auto it = std::partition(ids.begin() + begin, ids.begin() + end,
                                     [&](int id) { return bin_of(id) < best_k; });
            mid = static_cast<int>(it - ids.begin());
            if (mid == begin || mid == end) mid = -1;
        }
    }
    if (mid < 0) {
        // All centroids together (or too deep): split by count, keeping the order stable so
        // the tree is deterministic.
        mid = begin + count / 2;
        std::nth_element(ids.begin() + begin, ids.begin() + mid, ids.begin() + end, [&](int a,
                                                                                      int b) {
            if (centroids[a][axis] != centroids[b][axis])
                return centroids[a][axis] < centroids[b][axis];
            return a < b;
        });
    }
    build(ids, begin, mid, depth + 1);
    int second = build(ids, mid, end, depth + 1);
    BvhBinaryNode& n = nodes_[self];
    n.index = second;
    n.count = 0;
    return self;
}

}  // namespace glint::render
