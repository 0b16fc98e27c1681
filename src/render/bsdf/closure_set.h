// Several BSDFs at one shading point, each with its own weight and shading normal: what a
// Blender node graph leaves (a Mix Shader of a Diffuse and a Glossy, a bumped Principled), and
// a single BSDF for everything else. As in Cycles (kernel/integrator/shader_eval.h), a sample
// picks one closure by its sample weight, and evaluation and pdf sum over all of them, so MIS
// with light sampling sees the whole mixture. Directions are world space.
#pragma once

#include "core/fixed_list.h"
#include "render/bsdf/bsdf.h"
#include "render/bsdf/bssrdf.h"
#include "render/bsdf/lobe.h"

namespace glint::render {

struct ClosureSample {
    Vec3 wi;           // world space, unit
    Color weight;      // sum of f |cos| over the closures / mixture pdf (delta: the lobe's)
    double pdf = 0;    // mixture pdf; for a delta lobe its discrete probability
    bool delta = false;
    bool reflected = true;  // wi on wo's side of the chosen closure's normal
    bool straight = false;  // a delta lobe that continued wo unchanged (index-matched)
    bool diffuse = false;   // the sampled lobe is diffuse (Cycles' LABEL_DIFFUSE)
    double roughness2 = kInfinity;  // BsdfSample::roughness2 of the sampled lobe
    // A BSSRDF was picked instead of a BSDF (no direction: the path walks under the surface);
    // `weight` is its weight over the probability of the pick.
    const Bssrdf* bssrdf = nullptr;
};

class ClosureSet {
public:
    static constexpr int kMax = 16;

    // `ng` the geometric normal, `wo` towards the viewer; each closure's normal is bent where
    // it must be (valid_reflection_normal) as Cycles bends it.
    ClosureSet(const Vec3& ng, const Vec3& wo) : ng_(ng), wo_(wo) {}

    // Adds `bsdf` scaled by `weight` around the unit normal `n`; `sample_weight` its share of
    // the samples (Cycles: the average of the weight). Closures past kMax are dropped.
    // `tangent` (optional, world space) orients an anisotropic lobe's x axis.
    void add(const Bsdf& bsdf, const Color& weight, const Vec3& n, double sample_weight,
             const Vec3* tangent = nullptr);
    // A single lobe; its share is also scaled by the lobe's view-dependent sample_scale().
    void add(const Lobe& lobe, const Color& weight, const Vec3& n, double sample_weight,
             const Vec3* tangent = nullptr);
    // The smooth shading normal before bump (world, on the outside like the closures'):
    // diffuse lobes whose normal differs from it fade where light grazes, as Cycles 3.4 does
    // (bump_shadowing_term, after Chiang et al. 2019). Set before adding closures.
    void set_smooth_normal(const Vec3& ns) {
        ns_ = ns;
        has_ns_ = true;
    }
    // A BSSRDF (set up, its normal on the outside like add()'s) beside the BSDFs: it takes its
    // share of the samples (Cycles counts it in the mixture's pdf) but adds nothing to eval().
    // At most kMaxBssrdf are kept.
    static constexpr int kMaxBssrdf = 4;
    void add(const Bssrdf& bssrdf);
    int count() const { return items_.size() + bssrdfs_.size(); }
    bool all_delta() const;
    bool has_bssrdf() const { return !bssrdfs_.empty(); }
    // The chance that sample() picks a delta lobe (a mirror, a smooth refraction).
    double delta_probability() const;

    // Sum over the closures of weight f |cos wi| (about each closure's normal), and the
    // mixture pdf of sample() for wi.
    Color eval(const Vec3& wi, double* pdf) const;
    bool sample(double u1, double u2, ClosureSample* out) const;

private:
    struct Item {
        bool is_lobe = false;
        Bsdf bsdf;
        Lobe lobe;
        Color weight;
        Frame frame;
        bool bumped = false;  // its normal is not the smooth one: the shadowing term applies
        Vec3 wo;  // local
        double share = 0;
    };
    Item* push(const Vec3& n, double sample_weight, const Vec3* tangent);

    double shadowing(const Item& it, const Vec3& wi) const;

    Vec3 ng_, wo_;
    Vec3 ns_;
    bool has_ns_ = false;
    FixedList<Item, kMax> items_;
    FixedList<Bssrdf, kMaxBssrdf> bssrdfs_;
    double total_ = 0;
};

}  // namespace glint::render
