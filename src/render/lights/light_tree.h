// A light tree (Conty Estevez and Kulla 2018, "Importance Sampling of Many Lights with Adaptive
// Tree Splitting"; the tree Cycles 3.5 samples its lights with): a binary tree over emitters,
// each node bounding its emitters' positions (a box), emission directions (a cone: axis,
// spread theta_o of the normals, theta_e of the emission around them) and total power. From a
// shading point, each step down picks a child in proportion to an importance that bounds what
// the child's emitters can deliver there (power over squared distance, times the cosine left
// after the cone and the box's angular size are taken off), so near, bright, facing emitters
// are picked often and far or turned-away ones rarely. The probability of reaching an emitter
// is recomputed by pdf() along the same path, so MIS weights stay exact, and an importance is
// zero only where every emitter under the node emits nothing towards the point, so sampling
// stays unbiased.
//
// Built once per render, read-only while rendering (thread-safe), deterministic: the same
// emitters give the same tree.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"

namespace glint::render {

struct LightTreeItem {
    Bounds3 box;            // where the emitter lies
    double power = 0;       // relative emitted power (> 0)
    Vec3 axis{0, 0, 1};     // mean emission direction (unit)
    double theta_o = kPi;   // half-angle of the normals' cone around axis (pi: every direction)
    double theta_e = 0;     // how far past a normal it emits (pi / 2: a Lambertian surface)
};

class LightTree {
public:
    LightTree() = default;
    // Items with power <= 0 or an empty box are kept out (never picked). Not `spatial`: each
    // step goes by the children's power alone, so an item's chance is its share of the power
    // wherever the point is (for comparisons).
    explicit LightTree(const std::vector<LightTreeItem>& items, bool spatial = true);

    bool empty() const { return nodes_.empty(); }

    // Picks an item for the point p with u in [0, 1): returns its index (-1 when empty) and its
    // probability in *prob; *u is rescaled to [0, 1) for reuse.
    int sample(const Vec3& p, double* u, double* prob) const;
    // The probability sample() picks `item` from p (0 when it never can).
    double pdf(const Vec3& p, int item) const;

    // Importance of a node's bounds seen from p (exposed for tests).
    struct Bounds {
        Bounds3 box;
        double power = 0;
        Vec3 axis{0, 0, 1};
        double theta_o = 0, theta_e = 0;
    };
    static double importance(const Bounds& b, const Vec3& p);

    int node_count() const { return static_cast<int>(nodes_.size()); }
    int depth() const { return depth_; }

private:
    struct Node {
        Bounds bounds;
        int child[2] = {-1, -1};  // both -1: a leaf
        int item = -1;            // a leaf's item
        int parent = -1;
    };
    int build(std::vector<int>& order, int begin, int end, int parent, int level);
    // The chance of stepping from `node` to its first child at p.
    double left_probability(const Node& node, const Vec3& p) const;

    std::vector<LightTreeItem> items_;
    std::vector<Node> nodes_;
    std::vector<int> leaf_of_;  // item -> its leaf node, -1 when kept out
    int depth_ = 0;
    bool spatial_ = true;
};

// The cone bounding two cones (axis, theta_o) with their theta_e the larger of the two
// (Conty Estevez and Kulla, Algorithm 1).
void union_cone(const Vec3& a_axis, double a_theta_o, const Vec3& b_axis, double b_theta_o,
                Vec3* axis, double* theta_o);

}  // namespace glint::render
