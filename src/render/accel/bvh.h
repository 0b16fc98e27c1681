// Bounding volume hierarchy over primitives given by their bounds: binned SAH build (Wald 2007,
// "On fast construction of SAH-based bounding volume hierarchies"), compact nodes, ordered
// traversal. Used for the top-level objects (geometry.cpp) and for each mesh's triangles.
#pragma once

#include <cstdint>
#include <vector>

#include "core/float.h"
#include "core/math.h"
#include "render/ray.h"

namespace glint::render {

class Bvh {
public:
    // Node: 32 bytes, two per cache line. Boxes are floats rounded outwards, so they still
    // enclose the double-precision primitives. Interior: `index` is the second child (the first
    // follows the node), count == 0. Leaf: `index` is the first entry of order(), count > 0.
    struct Node {
        float box[2][3];  // lo, hi
        int32_t index;
        uint16_t count;
        uint8_t axis;
    };

    Bvh() = default;
    // Primitives with empty or non-finite bounds are left out. `block`: primitives tested
    // together at the cost of one (the mesh kernels test four triangles at once), so the SAH
    // counts a leaf of n as ceil(n / block) tests (Embree's builders do the same), and a node
    // visit as one: a split must save more than that to be made.
    // `node_cost`: a node visit's cost in primitive tests (1 for triangles; far less for the
    // top level, where a primitive is a whole object behind a virtual call).
    explicit Bvh(const std::vector<Bounds3>& prim_bounds, int max_leaf = 4, int block = 1,
                 double node_cost = 1.0);

    bool empty() const { return nodes_.empty(); }
    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<int>& order() const { return order_; }
    int depth() const { return depth_; }
    // The whole tree is one leaf: its primitives are all of order().
    bool single_leaf() const { return nodes_.size() == 1; }
    // For callers that store their primitives in order() sequence (so a leaf's primitives are
    // contiguous in memory): afterwards the traversal passes positions in that sequence.
    void use_leaf_order() {
        for (size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    }
    Bounds3 bounds() const;

    // Visits the primitives whose boxes the ray enters within [0, tmax], nearer boxes first.
    // visit(prim, tmax) may lower tmax; returning true stops the traversal (any-hit queries).
    // Boxes entered at exactly tmax are still visited, so equal-t ties can be broken by index.
    template <class Visit>
    bool traverse(const Ray& ray, double& tmax, Visit&& visit) const {
        if (nodes_.empty()) return false;
        RayBoxData rb(ray);
        int stack[128];
        int sp = 0;
        int cur = 0;
        for (;;) {
            const Node& n = nodes_[cur];
            if (hit_box(n, rb, tmax)) {
                if (n.count > 0) {
                    for (int i = 0; i < n.count; ++i)
                        if (visit(order_[n.index + i], tmax)) return true;
                } else {
                    int first = cur + 1, second = n.index;
                    if (rb.first_far[n.axis]) std::swap(first, second);
                    stack[sp++] = second;
                    cur = first;
                    continue;
                }
            }
            if (sp == 0) break;
            cur = stack[--sp];
        }
        return false;
    }

private:
    struct RayBoxData {
        explicit RayBoxData(const Ray& ray) {
            for (int a = 0; a < 3; ++a) {
                o[a] = ray.origin[a];
                inv[a] = 1 / ray.dir[a];
                inv_far[a] = inv[a] * (1 + 2 * gamma(3));
                neg[a] = inv[a] < 0;
                near[a] = neg[a] * 3 + a;
                far[a] = (1 - neg[a]) * 3 + a;
                first_far[a] = neg[a];
            }
        }
        double o[3];
        double inv[3];
        double inv_far[3];  // widened by 2 gamma(3) (pbrt-v4, 6.1.2): rounding never culls
        int neg[3];
        int near[3], far[3];  // offsets of the near and far planes in Node::box
        // Whether to visit the second child first: the direction is negative along the
        // split axis.
        int first_far[3];
    };

    // Slab test, near and far planes picked by the direction's sign. A zero direction component
    // gives +-inf, or NaN for an origin on the slab plane, which the comparisons ignore.
    static bool hit_box(const Node& n, const RayBoxData& r, double tmax) {
        const float* b = &n.box[0][0];
        double tn0 = (b[r.near[0]] - r.o[0]) * r.inv[0];
        double tf0 = (b[r.far[0]] - r.o[0]) * r.inv_far[0];
        double tn1 = (b[r.near[1]] - r.o[1]) * r.inv[1];
        double tf1 = (b[r.far[1]] - r.o[1]) * r.inv_far[1];
        double tn2 = (b[r.near[2]] - r.o[2]) * r.inv[2];
        double tf2 = (b[r.far[2]] - r.o[2]) * r.inv_far[2];
        double t0 = tn0 > 0 ? tn0 : 0;
        t0 = tn1 > t0 ? tn1 : t0;
        t0 = tn2 > t0 ? tn2 : t0;
        double t1 = tf0 < tmax ? tf0 : tmax;
        t1 = tf1 < t1 ? tf1 : t1;
        t1 = tf2 < t1 ? tf2 : t1;
        return t0 <= t1;
    }

    int build(std::vector<int>& ids, int begin, int end, const std::vector<Bounds3>& bounds,
              const std::vector<Vec3>& centroids, int max_leaf, int depth);
    int block_ = 1;
    double node_cost_ = 1.0;

    std::vector<Node> nodes_;
    std::vector<int> order_;
    int depth_ = 0;
};

}  // namespace glint::render
