#include "render/lights/light_tree.h"

#include <algorithm>
#include <cmath>

#include "render/sampling/sampler.h"
#include "render/sampling/warp.h"

namespace glint::render {
namespace {

constexpr int kBuckets = 12;

double angle_between(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(dot(a, b), -1.0, 1.0));
}

// The orientation measure M_Omega of a cone (Conty Estevez and Kulla, eq. 1): the solid angle
// its emission covers, weighted by the cosine falloff past theta_o.
double orientation_measure(double theta_o, double theta_e) {
    const double theta_w = std::min(theta_o + theta_e, kPi);
    const double s = std::sin(theta_o), c = std::cos(theta_o);
    return 2 * kPi * (1 - c) +
           kPi / 2 * (2 * theta_w * s - std::cos(theta_o - 2 * theta_w) - 2 * theta_o * s + c);
}

// A box's size for the split cost: its surface area, plus its squared diagonal so that flat
// and point-like boxes are still told apart.
double box_measure(const Bounds3& b) {
    return b.empty() ? 0.0 : b.surface_area() + length_squared(b.diagonal());
}

LightTree::Bounds item_bounds(const LightTreeItem& it) {
    return {it.box, it.power, it.axis, it.theta_o, it.theta_e};
}

LightTree::Bounds merge(const LightTree::Bounds& a, const LightTree::Bounds& b) {
    if (!(a.power > 0)) return b;
    if (!(b.power > 0)) return a;
    LightTree::Bounds m;
    m.box = a.box;
    m.box.extend(b.box);
    m.power = a.power + b.power;
    union_cone(a.axis, a.theta_o, b.axis, b.theta_o, &m.axis, &m.theta_o);
    m.theta_e = std::max(a.theta_e, b.theta_e);
    return m;
}

double split_cost(const LightTree::Bounds& b) {
    return b.power > 0 ? b.power * orientation_measure(b.theta_o, b.theta_e) * box_measure(b.box)
                       : 0.0;
}

}  // namespace

void union_cone(const Vec3& a_axis, double a_theta_o, const Vec3& b_axis, double b_theta_o,
                Vec3* axis, double* theta_o) {
    Vec3 wa = a_axis, wb = b_axis;
    double ta = a_theta_o, tb = b_theta_o;
    if (tb > ta) {
        std::swap(wa, wb);
        std::swap(ta, tb);
    }
    const double theta_d = angle_between(wa, wb);
    if (std::min(theta_d + tb, kPi) <= ta) {  // b lies inside a
        *axis = wa;
        *theta_o = ta;
        return;
    }
    const double to = (ta + theta_d + tb) / 2;
    if (to >= kPi) {
        *axis = wa;
        *theta_o = kPi;
        return;
    }
    // Turn a's axis towards b's by to - ta.
    const double turn = to - ta;
    Vec3 perp = wb - wa * dot(wa, wb);
    if (!(length_squared(perp) > 1e-24)) {
        Vec3 t;
        tangents(wa, &perp, &t);
    }
    perp = normalize(perp);
    *axis = normalize(wa * std::cos(turn) + perp * std::sin(turn));
    // The union touches both cones exactly; a hair more keeps it a bound after the rounding
    // of acos near 1 (about 1e-8 rad).
    *theta_o = std::min(kPi, to + 1e-6);
}

double LightTree::importance(const Bounds& b, const Vec3& p) {
    if (!(b.power > 0)) return 0;
    const Vec3 d = p - b.box.centroid();
    const double d2 = length_squared(d);
    const double r2 = 0.25 * length_squared(b.box.diagonal());
    double cos_term = 1;
    if (b.theta_o < kPi && d2 > r2) {
        // The smallest angle between a direction the node may emit along and the direction
        // to p: the angle to the axis, less the normals' spread and the box's angular size.
        const double dist = std::sqrt(d2);
        const double theta = angle_between(b.axis, d / dist);
        const double theta_b = std::asin(std::min(1.0, std::sqrt(r2 / d2)));
        // (Less a hair for the rounding of acos near 1, so the bound stays a bound.)
        const double theta_p = std::max(0.0, theta - b.theta_o - theta_b - 1e-6);
        if (theta_p >= b.theta_e) return 0;
        cos_term = std::cos(theta_p);
    }
    // Inside the box's bounding sphere distance says nothing: its radius stands for it.
    return b.power * cos_term / std::max(d2, r2);
}

LightTree::LightTree(const std::vector<LightTreeItem>& items, bool spatial)
    : items_(items), spatial_(spatial) {
    leaf_of_.assign(items_.size(), -1);
    std::vector<int> order;
    for (int i = 0; i < static_cast<int>(items_.size()); ++i)
        if (items_[i].power > 0 && std::isfinite(items_[i].power) && !items_[i].box.empty() &&
            !items_[i].box.is_infinite())
            order.push_back(i);
    if (order.empty()) return;
    nodes_.reserve(2 * order.size());
    build(order, 0, static_cast<int>(order.size()), -1, 1);
}

int LightTree::build(std::vector<int>& order, int begin, int end, int parent, int level) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    nodes_[index].parent = parent;
    depth_ = std::max(depth_, level);
    Bounds all;
    Bounds3 centroids;
    for (int k = begin; k < end; ++k) {
        all = merge(all, item_bounds(items_[order[k]]));
        centroids.extend(items_[order[k]].box.centroid());
    }
    nodes_[index].bounds = all;
    if (end - begin == 1) {
        nodes_[index].item = order[begin];
        leaf_of_[order[begin]] = index;
        return index;
    }
    // The split: the bucket boundary along the centroids' longest axis with the lowest
    // surface-area-orientation cost (Conty Estevez and Kulla's SAOH); the middle of the list
    // when the centroids coincide or every boundary leaves one side empty.
    const Vec3 extent = centroids.diagonal();
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const double lo = centroids.lo[axis], width = extent[axis];
    int mid = (begin + end) / 2;
    if (width > 0) {
        auto bucket = [&](int item) {
            const double at = items_[item].box.centroid()[axis] - lo;
            const int b = static_cast<int>(kBuckets * at / width);
            return std::clamp(b, 0, kBuckets - 1);
        };
        Bounds buckets[kBuckets];
        int counts[kBuckets] = {};
        for (int k = begin; k < end; ++k) {
            const int b = bucket(order[k]);
            buckets[b] = merge(buckets[b], item_bounds(items_[order[k]]));
            ++counts[b];
        }
        double best = HUGE_VAL;
        int best_split = -1;
        for (int s = 1; s < kBuckets; ++s) {
            Bounds left, right;
            int nl = 0, nr = 0;
            for (int b = 0; b < s; ++b) {
                left = merge(left, buckets[b]);
                nl += counts[b];
            }
            for (int b = s; b < kBuckets; ++b) {
                right = merge(right, buckets[b]);
                nr += counts[b];
            }
            if (nl == 0 || nr == 0) continue;
            const double cost = split_cost(left) + split_cost(right);
            if (cost < best) {
                best = cost;
                best_split = s;
            }
        }
        if (best_split > 0) {
            auto it = std::stable_partition(order.begin() + begin, order.begin() + end,
                                            [&](int item) { return bucket(item) < best_split; });
            mid = static_cast<int>(it - order.begin());
        }
    }
    const int left = build(order, begin, mid, index, level + 1);
    const int right = build(order, mid, end, index, level + 1);
    nodes_[index].child[0] = left;
    nodes_[index].child[1] = right;
    return index;
}

double LightTree::left_probability(const Node& node, const Vec3& p) const {
    const Bounds& l = nodes_[node.child[0]].bounds;
    const Bounds& r = nodes_[node.child[1]].bounds;
    const double il = spatial_ ? importance(l, p) : l.power;
    const double ir = spatial_ ? importance(r, p) : r.power;
    const double sum = il + ir;
    // Neither child can be told apart (or both bounds say nothing reaches p): an even split,
    // which keeps every item reachable.
    if (!(sum > 0) || !std::isfinite(sum)) return 0.5;
    return il / sum;
}

int LightTree::sample(const Vec3& p, double* u, double* prob) const {
    *prob = 0;
    if (nodes_.empty()) return -1;
    double pick = 1;
    int node = 0;
    while (nodes_[node].child[0] >= 0) {
        const Node& n = nodes_[node];
        const double pl = left_probability(n, p);
        if (*u < pl) {
            *u = std::min(*u / pl, kOneMinusEpsilon);
            pick *= pl;
            node = n.child[0];
        } else {
            *u = std::min((*u - pl) / (1 - pl), kOneMinusEpsilon);
            pick *= 1 - pl;
            node = n.child[1];
        }
    }
    *prob = pick;
    return nodes_[node].item;
}

double LightTree::pdf(const Vec3& p, int item) const {
    if (item < 0 || item >= static_cast<int>(leaf_of_.size()) || leaf_of_[item] < 0) return 0;
    double pick = 1;
    int node = leaf_of_[item];
    while (nodes_[node].parent >= 0) {
        const Node& parent = nodes_[nodes_[node].parent];
        const double pl = left_probability(parent, p);
        pick *= parent.child[0] == node ? pl : 1 - pl;
        node = nodes_[node].parent;
    }
    return pick;
}

}  // namespace glint::render
