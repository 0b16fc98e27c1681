#include "render/accel/bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint::render {
namespace {

constexpr int kBins = 16;
// Deeper trees would overflow the traversal stack; past this depth splits are by count.
constexpr int kMaxSahDepth = 48;

double half_area(const Bounds3& b) {
    if (b.empty()) return 0;
    Vec3 d = b.diagonal();
    return d.x * d.y + d.y * d.z + d.z * d.x;
}

}  // namespace

Bvh::Bvh(const std::vector<Bounds3>& prim_bounds, int max_leaf, int block, double node_cost)
    : block_(std::max(block, 1)), node_cost_(node_cost) {
    std::vector<int> ids;
    std::vector<Vec3> centroids(prim_bounds.size());
    for (size_t i = 0; i < prim_bounds.size(); ++i) {
        const Bounds3& b = prim_bounds[i];
        if (b.empty() || b.is_infinite()) continue;
        ids.push_back(static_cast<int>(i));
        centroids[i] = b.centroid();
    }
    if (ids.empty()) return;
    nodes_.reserve(2 * ids.size());
    build(ids, 0, static_cast<int>(ids.size()), prim_bounds, centroids,
          std::clamp(max_leaf, 1, 255), 1);
    order_ = std::move(ids);
    nodes_.shrink_to_fit();  // reserved for the worst case (2n), usually about n / 2
}

Bounds3 Bvh::bounds() const {
    Bounds3 b;
    if (nodes_.empty()) return b;
    const auto& box = nodes_[0].box;
    b.lo = {box[0][0], box[0][1], box[0][2]};
    b.hi = {box[1][0], box[1][1], box[1][2]};
    return b;
}

int Bvh::build(std::vector<int>& ids, int begin, int end, const std::vector<Bounds3>& bounds,
               const std::vector<Vec3>& centroids, int max_leaf, int depth) {
    depth_ = std::max(depth_, depth);
    int self = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    Bounds3 box, cbox;
    for (int i = begin; i < end; ++i) {
        box.extend(bounds[ids[i]]);
        cbox.extend(centroids[ids[i]]);
    }
    auto set_leaf = [&]() {
        Node& n = nodes_[self];
        n.index = begin;
        n.count = static_cast<uint16_t>(end - begin);
        n.axis = 0;
    };
    for (int a = 0; a < 3; ++a) {
        nodes_[self].box[0][a] = float_down(box.lo[a]);
        nodes_[self].box[1][a] = float_up(box.hi[a]);
    }
    auto blocks = [this](int n) { return (n + block_ - 1) / block_; };
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
            double cost = left_area[k - 1] * blocks(left_n[k - 1]) + half_area(acc) * blocks(n);
            if (cost < best) {
                best = cost;
                best_k = k;
            }
        }
        double leaf_cost = half_area(box) * blocks(count);
        if (count <= max_leaf * 4 && count <= 255 &&
            leaf_cost <= best + node_cost_ * half_area(box)) {
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
    build(ids, begin, mid, bounds, centroids, max_leaf, depth + 1);
    int second = build(ids, mid, end, bounds, centroids, max_leaf, depth + 1);
    Node& n = nodes_[self];
    n.index = second;
    n.count = 0;
    n.axis = static_cast<uint8_t>(axis);
    return self;
}

}  // namespace glint::render
