#include "render/bsdf/closure_set.h"

#include <algorithm>
#include <cmath>

#include "render/bsdf/shading_normal.h"

namespace glint::render {

ClosureSet::Item* ClosureSet::push(const Vec3& n, double sample_weight, const Vec3* tangent) {
    if (items_.full() || !(sample_weight > 0)) return nullptr;
    Item& it = items_.emplace_back();
    const Vec3 nv = valid_reflection_normal(ng_, wo_, n);
    it.frame = Frame::from_normal(nv);
    if (tangent) {
        // x along the tangent projected into the surface (Cycles' make_orthonormals_tangent).
        const Vec3 t = *tangent - nv * dot(nv, *tangent);
        if (length_squared(t) > 1e-20) {
            const Vec3 x = normalize(t);
            it.frame = Frame{x, cross(nv, x), nv};
        }
    }
    it.wo = it.frame.to_local(wo_);
    it.share = sample_weight;
    // (The graph hands normals over in single precision: equal within its rounding.)
    it.bumped = has_ns_ && length_squared(nv - ns_) > 1e-10;
    return &it;
}

void ClosureSet::add(const Bsdf& bsdf, const Color& weight, const Vec3& n, double sample_weight,
                     const Vec3* tangent) {
    Item* it = push(n, sample_weight, tangent);
    if (!it) return;
    it->is_lobe = false;
    it->bsdf = bsdf;
    it->weight = weight;
    total_ += it->share;
}

void ClosureSet::add(const Lobe& lobe, const Color& weight, const Vec3& n, double sample_weight,
                     const Vec3* tangent) {
    Item* it = push(n, sample_weight, tangent);
    if (!it) return;
    it->share *= lobe.sample_scale(it->wo);
    if (!(it->share > 0)) {
        items_.pop_back();
        return;
    }
    it->is_lobe = true;
    it->lobe = lobe;
    it->weight = weight;
    total_ += it->share;
}

void ClosureSet::add(const Bssrdf& bssrdf) {
    const double share = bssrdf.sample_weight();
    if (bssrdfs_.full() || !(share > 0)) return;
    Bssrdf& b = bssrdfs_.emplace_back();
    b = bssrdf;
    // Bent like the BSDFs' normals, then turned to the viewer's side.
    const Vec3 nv = valid_reflection_normal(ng_, wo_, bssrdf.n);
    b.n = dot(ng_, wo_) >= 0 ? nv : -nv;
    total_ += share;
}

double ClosureSet::shadowing(const Item& it, const Vec3& wi) const {
    if (!it.bumped) return 1;
    const Vec3& n = it.frame.n;
    const double cos_ni = dot(n, wi);
    const Vec3 ns = cos_ni < 0 ? -ns_ : ns_;
    const double d = cos_ni * dot(ns, n);
    const double g = d != 0 ? dot(ns, wi) / d : 0.0;
    if (g >= 1) return 1;
    if (g < 0) return 0;
    return -g * g * g + g * g + g;  // smooth towards 1 at g = 1
}

bool ClosureSet::all_delta() const {
    for (int i = 0; i < items_.size(); ++i)
        if (items_[i].is_lobe ? !items_[i].lobe.delta() : !items_[i].bsdf.all_delta())
            return false;
    return true;
}

double ClosureSet::delta_probability() const {
    if (!(total_ > 0)) return 0;
    double p = 0;
    for (int i = 0; i < items_.size(); ++i) {
        const Item& it = items_[i];
        const double pick = it.share / total_;
        if (it.is_lobe)
            p += it.lobe.delta() ? pick : 0.0;
        else
            p += pick * it.bsdf.delta_probability(it.wo);
    }
    return std::clamp(p, 0.0, 1.0);
}

Color ClosureSet::eval(const Vec3& wi, double* pdf) const {
    Color f;
    double p = 0;
    for (int i = 0; i < items_.size(); ++i) {
        const Item& it = items_[i];
        const Vec3 w = it.frame.to_local(wi);
        if (it.is_lobe) {
            double pl;
            Color fi = it.lobe.eval(it.wo, w, &pl);
            if (it.lobe.diffuse()) fi *= shadowing(it, wi);
            if (!fi.is_black()) f += it.weight * fi;
            p += it.share / total_ * pl;
            continue;
        }
        const Color fi = it.bsdf.eval(it.wo, w, shadowing(it, wi));
        if (!fi.is_black()) f += it.weight * fi * std::fabs(w.z);
        p += it.share / total_ * it.bsdf.pdf(it.wo, w);
    }
    *pdf = p;
    return f;
}

bool ClosureSet::sample(double u1, double u2, ClosureSample* out) const {
    if (count() == 0) return false;
    // The closure by its share; u1 rescaled within it keeps the sampler's stratification.
    // The BSSRDFs come after the BSDFs.
    double u = u1 * total_;
    double bsdf_total = total_;
    if (bssrdfs_.size() > 0) {  // (only then: BSDF samples are the hot path)
        bsdf_total = 0;
        for (int i = 0; i < items_.size(); ++i) bsdf_total += items_[i].share;
    }
    if (bssrdfs_.size() > 0 && (u >= bsdf_total || items_.size() == 0)) {
        u -= bsdf_total;
        int b = 0;
        while (b < bssrdfs_.size() - 1 && u >= bssrdfs_[b].sample_weight())
            u -= bssrdfs_[b++].sample_weight();
        out->bssrdf = &bssrdfs_[b];
        out->weight = bssrdfs_[b].weight * (total_ / bssrdfs_[b].sample_weight());
        out->pdf = 0;
        out->diffuse = true;
        return true;
    }
    out->bssrdf = nullptr;
    int k = 0;
    while (k < items_.size() - 1 && u >= items_[k].share) u -= items_[k++].share;
    const Item& it = items_[k];
    const double uk = std::min(u / it.share, 0x1.fffffffffffffp-1);
    BsdfSample bs;
    if (!(it.is_lobe ? it.lobe.sample(it.wo, uk, u2, &bs) : it.bsdf.sample(it.wo, uk, u2, &bs)))
        return false;
    out->wi = normalize(it.frame.to_world(bs.wi));
    out->delta = bs.delta;
    out->diffuse = bs.diffuse;
    out->roughness2 = bs.roughness2;
    out->reflected = bs.wi.z * it.wo.z > 0;
    out->straight = bs.delta && bs.wi.x == -it.wo.x && bs.wi.y == -it.wo.y && bs.wi.z == -it.wo.z;
    const double pick = it.share / total_;
    if (count() == 1 && !(it.bumped && bs.diffuse)) {
        out->weight = it.weight * bs.weight;
        out->pdf = bs.pdf;
        return true;
    }
    if (bs.delta) {
        out->weight = it.weight * bs.weight * (1 / pick);
        out->pdf = bs.pdf * pick;
        return true;
    }
    // The whole mixture at the sampled direction (delta lobes add nothing there).
    double pdf = 0;
    const Color f = eval(out->wi, &pdf);
    if (!(pdf > 0)) return false;
    out->weight = f * (1 / pdf);
    out->pdf = pdf;
    return true;
}

}  // namespace glint::render
