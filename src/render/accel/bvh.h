// Bounding volume hierarchy over primitives given by their bounds: binned SAH build (Wald 2007,
// "On fast construction of SAH-based bounding volume hierarchies") of a binary tree, collapsed
// into a 4-wide one whose four child boxes a ray tests at once (SSE), children visited nearest
// first. Used for the top-level objects (geometry.cpp) and for each mesh's triangles.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "core/float.h"
#include "core/math.h"
#include "render/ray.h"

namespace glint::render {

// Nearest floats below / above a double: float boxes that enclose double ones, float ray data
// that errs on the safe side. Per ray, so stepping is done on the bits (std::nextafter is a
// library call).
inline float float_step(float f, bool up) {
    if (f == 0) return up ? std::numeric_limits<float>::denorm_min()
                          : -std::numeric_limits<float>::denorm_min();
    if (std::isnan(f)) return f;
    if (std::isinf(f))  // beyond the largest float, or back to it
        return (f > 0) == up ? f : std::copysign(std::numeric_limits<float>::max(), f);
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    // Away from zero when the step goes the way of the sign, towards it otherwise.
    bits = ((f > 0) == up) ? bits + 1 : bits - 1;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}
inline float float_down(double v) {
    const float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? float_step(f, false) : f;
}
inline float float_up(double v) {
    const float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? float_step(f, true) : f;
}

struct BvhBinaryNode;  // the build's binary tree (bvh.cpp)

class Bvh {
public:
    // A node of the 4-wide tree, two cache lines: the children's boxes as floats rounded
    // outwards (so they still enclose the double-precision primitives), laid out axis by axis so
    // that one SSE register holds one plane of all four. A child is an inner node (count 0,
    // index: its node), a leaf (count > 0, index: its first entry of order()) or an empty slot
    // (not in `valid`; its box is empty).
    struct alignas(64) Node {
        float box[2][3][4];  // [lo, hi][axis][child]
        int32_t index[4];
        uint16_t count[4];
        uint8_t valid;  // bit k: child k exists
    };

    Bvh() = default;
    // Primitives with empty or non-finite bounds are left out.
    explicit Bvh(const std::vector<Bounds3>& prim_bounds, int max_leaf = 4);

    bool empty() const { return nodes_.empty(); }
    const std::vector<Node>& nodes() const { return nodes_; }
    const std::vector<int>& order() const { return order_; }
    // Levels of the 4-wide tree (a single leaf: 1).
    int depth() const { return depth_; }
    // The whole tree is one leaf: its primitives are all of order().
    bool single_leaf() const { return nodes_.size() == 1 && nodes_[0].valid == 1 && nodes_[0].count[0] > 0; }
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
        const RayBoxData rb(ray);
        // A child still to visit (count 0: an inner node), with the distance at which the ray
        // enters its box: one entered beyond tmax (lowered since it was pushed) is dropped.
        struct Entry {
            int32_t index;
            uint32_t count;
            float tnear;
        };
        Entry stack[kStackSize];
        int sp = 0;
        float tmax_f = float_up(tmax);
        Entry cur{0, 0, 0};  // the root
        for (;;) {
            if (cur.count == 0) {
                // An inner node: its hit children, the nearest next and the rest on the stack
                // farthest first; equal distances in slot order (the lower slot first).
                const Node& n = nodes_[static_cast<size_t>(cur.index)];
                alignas(16) float tn[4];
                int mask = hit_boxes(n, rb, tmax_f, tn) & n.valid;
                if (mask != 0) {
                    int slots[4], m = 0;
                    while (mask) {
                        const int k = __builtin_ctz(static_cast<unsigned>(mask));
                        mask &= mask - 1;
                        int j = m++;
                        while (j > 0 && tn[slots[j - 1]] < tn[k]) {
                            slots[j] = slots[j - 1];
                            --j;
                        }
                        slots[j] = k;
                    }
                    // slots[] runs from farthest to nearest.
                    for (int i = 0; i < m - 1; ++i) {
                        const int k = slots[i];
                        stack[sp++] = {n.index[k], n.count[k], tn[k]};
                    }
                    const int k = slots[m - 1];
                    cur = {n.index[k], n.count[k], tn[k]};
                    continue;
                }
            } else {
                for (uint32_t i = 0; i < cur.count; ++i)
                    if (visit(order_[static_cast<size_t>(cur.index) + i], tmax)) return true;
                tmax_f = float_up(tmax);
            }
            do {
                if (sp == 0) return false;
                cur = stack[--sp];
            } while (cur.tnear > tmax_f);
        }
    }

private:
    // The binary SAH tree stops splitting by area at depth 48 and splits by count below, so it
    // is at most about 48 + log2(n) deep; each 4-wide level pushes at most 4 entries.
    static constexpr int kStackSize = 4 * 96;

    // The ray in float, rounded so that the float slab distances err outwards: near planes use
    // an origin rounded towards making the distance smaller, far planes one rounded the other
    // way, and far distances are widened by 2 gamma(3) in float (pbrt-v4, 6.1.2) for the
    // rounding of the subtraction, the product and the reciprocal.
    struct RayBoxData {
        explicit RayBoxData(const Ray& ray) {
            constexpr double kEps = 0x1p-24;  // float's unit roundoff
            constexpr double kWiden = 1 + 2 * (3 * kEps) / (1 - 3 * kEps);
            for (int a = 0; a < 3; ++a) {
                const float inv_f = static_cast<float>(1 / ray.dir[a]);
                const bool neg = std::signbit(inv_f);
                near_side[a] = neg ? 1 : 0;
                const float o_near = neg ? float_down(ray.origin[a]) : float_up(ray.origin[a]);
                const float o_far = neg ? float_up(ray.origin[a]) : float_down(ray.origin[a]);
                const double wide = static_cast<double>(inv_f) * kWiden;
                const float inv_far = neg ? float_down(wide) : float_up(wide);
                set(on[a], o_near);
                set(of[a], o_far);
                set(inv[a], inv_f);
                set(invf[a], inv_far);
            }
        }
#if defined(__SSE2__)
        static void set(__m128& r, float v) { r = _mm_set1_ps(v); }
        __m128 on[3], of[3], inv[3], invf[3];
#else
        static void set(float (&r)[4], float v) { r[0] = r[1] = r[2] = r[3] = v; }
        float on[3][4], of[3][4], inv[3][4], invf[3][4];
#endif
        int near_side[3];  // 0: the near plane is lo (direction >= +0), 1: hi
    };

    // Slab test of the four children; returns the mask of boxes entered within [0, tmax] and
    // writes the entry distances. A zero direction component gives +-inf, or NaN for an origin
    // on the slab plane, which the min/max ignore (they return their second operand on NaN).
    static int hit_boxes(const Node& n, const RayBoxData& r, float tmax, float* tn_out) {
#if defined(__SSE2__)
        __m128 t0 = _mm_setzero_ps();
        __m128 t1 = _mm_set1_ps(tmax);
        for (int a = 0; a < 3; ++a) {
            const __m128 nearp = _mm_load_ps(n.box[r.near_side[a]][a]);
            const __m128 farp = _mm_load_ps(n.box[1 - r.near_side[a]][a]);
            t0 = _mm_max_ps(_mm_mul_ps(_mm_sub_ps(nearp, r.on[a]), r.inv[a]), t0);
            t1 = _mm_min_ps(_mm_mul_ps(_mm_sub_ps(farp, r.of[a]), r.invf[a]), t1);
        }
        _mm_store_ps(tn_out, t0);
        return _mm_movemask_ps(_mm_cmple_ps(t0, t1));
#else
        int mask = 0;
        for (int k = 0; k < 4; ++k) {
            float t0 = 0, t1 = tmax;
            for (int a = 0; a < 3; ++a) {
                const float tn = (n.box[r.near_side[a]][a][k] - r.on[a][k]) * r.inv[a][k];
                const float tf = (n.box[1 - r.near_side[a]][a][k] - r.of[a][k]) * r.invf[a][k];
                t0 = tn > t0 ? tn : t0;
                t1 = tf < t1 ? tf : t1;
            }
            tn_out[k] = t0;
            mask |= (t0 <= t1) << k;
        }
        return mask;
#endif
    }

    int collapse(const std::vector<BvhBinaryNode>& bin, int b, int depth);

    std::vector<Node> nodes_;
    std::vector<int> order_;
    int depth_ = 0;
};

}  // namespace glint::render
