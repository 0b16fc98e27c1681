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
        float lo[3];
        float hi[3];
        int32_t index;
        uint16_t count;
        uint8_t axis;
    };

    Bvh() = default;
    // Primitives with empty or non-finite bounds are left out.
    explicit Bvh(const std::vector<Bounds3>& prim_bounds, int max_leaf = 4);

    bool empty() const { return nodes_.empty(); }
    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<int>& order() const { return order_; }
    int depth() const { return depth_; }
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
                    if (rb.neg[n.axis]) std::swap(first, second);
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
        explicit RayBoxData(const Ray& ray) : o(ray.origin) {
            for (int a = 0; a < 3; ++a) {
                inv[a] = 1 / ray.dir[a];
                neg[a] = inv[a] < 0;
            }
        }
        Vec3 o;
        double inv[3];
        int neg[3];
    };

    // Slab test with the near/far planes chosen by the direction's sign (no swaps, no
    // branches). A zero direction component gives +-inf, or NaN for an origin on the slab plane,
    // which the comparisons ignore. tfar is widened by 2 gamma(3) (pbrt-v4, 6.1.2) so rounding
    // never culls a box the ray touches.
    static bool hit_box(const Node& n, const RayBoxData& r, double tmax) {
        double t0 = 0, t1 = tmax;
        for (int a = 0; a < 3; ++a) {
            double near = r.neg[a] ? n.hi[a] : n.lo[a];
            double far = r.neg[a] ? n.lo[a] : n.hi[a];
            double tn = (near - r.o[a]) * r.inv[a];
            double tf = (far - r.o[a]) * r.inv[a] * (1 + 2 * gamma(3));
            t0 = tn > t0 ? tn : t0;
            t1 = tf < t1 ? tf : t1;
        }
        return t0 <= t1;
    }

    int build(std::vector<int>& ids, int begin, int end, const std::vector<Bounds3>& bounds,
              const std::vector<Vec3>& centroids, int max_leaf, int depth);

    std::vector<Node> nodes_;
    std::vector<int> order_;
    int depth_ = 0;
};

}  // namespace glint::render
