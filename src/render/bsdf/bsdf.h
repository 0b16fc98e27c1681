// BSDFs of the path tracer, evaluated in a local shading frame (z = shading normal, pointing
// out of the solid). Directions point away from the surface: wo towards the viewer, wi towards
// the light. eval() returns f (without the cosine), pdf() the solid-angle density sample()
// uses; sample() returns the throughput weight f * |cos wi| / pdf directly, which stays exact
// for delta lobes. Plain values, no allocation: one is built per hit on the stack.
//
// Models: Lambert; the modified Phong BRDF (Lafortune & Willems 1994); a Principled-lite BSDF (scene::Pbr): a Lambert base, a GGX reflection
// lobe with Schlick Fresnel (F0 = 0.08 * specular for dielectrics, the base color for metals)
// sampled by visible normals (Heitz 2018), and a rough dielectric (Walter et al. 2007) for
// transmission, all mixed by metallic and transmission as Blender's Principled BSDF mixes them.
// Smooth surfaces (roughness below ~0.03, alpha below 1e-3) become delta lobes; so does an
// index-matched (IOR 1) transmission of any roughness: light passes straight through.
#pragma once

#include "core/math.h"

namespace glint::render {

// An orthonormal basis around a unit normal (Duff et al. 2017).
struct Frame {
    Vec3 s, t, n;
    static Frame from_normal(const Vec3& n) {
        const double sign = std::copysign(1.0, n.z);
        const double a = -1.0 / (sign + n.z);
        const double b = n.x * n.y * a;
        return {Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3(b, sign + n.y * n.y * a, -n.y), n};
    }
    Vec3 to_local(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vec3 to_world(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

struct PrincipledParams {
    Color base{0.8, 0.8, 0.8};
    double metallic = 0;
    double roughness = 0.5;
    double specular = 0.5;  // dielectric F0 = 0.08 * specular
    double ior = 1.45;
    double transmission = 0;
};

struct BsdfSample {
    Vec3 wi;
    Color weight;  // f * |cos wi| / pdf
    double pdf = 0;  // for delta lobes: the discrete probability (not usable for MIS)
    bool delta = false;
};

// Fresnel reflectance of a dielectric interface; cos_i < 0 means arriving from inside.
// `eta` is the interior over the exterior index of refraction.
double fresnel_dielectric(double cos_i, double eta);

// GGX (Trowbridge-Reitz) isotropic microfacet distribution.
struct Ggx {
    double alpha = 0.25;
    double d(const Vec3& wm) const;
    double lambda(const Vec3& w) const;
    double g1(const Vec3& w) const { return 1.0 / (1.0 + lambda(w)); }
    double g(const Vec3& wo, const Vec3& wi) const { return 1.0 / (1.0 + lambda(wo) + lambda(wi)); }
    // Density of visible normals seen from w (integrates to 1 over wm).
    double pdf_visible(const Vec3& w, const Vec3& wm) const;
    // Visible-normal sample (Heitz 2018) for w on either side; returns wm with wm.z > 0.
    Vec3 sample_visible(const Vec3& w, double u1, double u2) const;
};

class Bsdf {
public:
    static Bsdf lambert(const Color& albedo);
    static Bsdf principled(const PrincipledParams& p);
    // The modified Phong BRDF (Lafortune & Willems 1994): kd / pi + ks (n + 2) / (2 pi) cos^n a,
    // a the angle between wi and the mirror direction of wo; energy-conserving when kd + ks <= 1.
    // The glossy lobe is sampled exactly (pdf (n + 1) / (2 pi) cos^n a).
    static Bsdf phong(const Color& kd, const Color& ks, double exponent);

    Color eval(const Vec3& wo, const Vec3& wi) const;
    double pdf(const Vec3& wo, const Vec3& wi) const;
    // `u_lobe` picks a lobe, (u1, u2) the direction. Returns false when no direction results.
    bool sample(const Vec3& wo, double u_lobe, double u1, double u2, BsdfSample* out) const;
    // True when every lobe is a delta (then light sampling is pointless).
    bool all_delta() const {
        return w_diffuse_ == 0 && w_phong_ == 0 && (w_spec_ == 0 || spec_delta_) &&
               (w_trans_ == 0 || trans_delta_);
    }

private:
    // Lobe selection probabilities for wo (up to normalization).
    void lobe_probs(const Vec3& wo, double* pd, double* ps, double* pt, double* pp) const;
    Color spec_fresnel(double cos_h) const;

    Color diffuse_color_;  // albedo of the Lambert lobe (already weighted)
    Color spec_color_;     // F0 of the reflection lobe
    Color trans_tint_;     // tint of the dielectric lobe
    double w_diffuse_ = 0, w_spec_ = 0, w_trans_ = 0;
    double diffuse_fresnel_f0_ = 0;  // the dielectric F0 the diffuse lobe gives way to
    bool diffuse_fresnel_ = false;   // whether the diffuse lobe gives way to the reflection
    Color phong_ks_;  // modified Phong glossy lobe (w_phong_ = 1 when present)
    double phong_n_ = 0;
    double w_phong_ = 0;
    Ggx ggx_;
    bool spec_delta_ = false;
    // The dielectric lobe is a delta when smooth, and also when index-matched (eta = 1): then
    // no microfacet bends or reflects light, whatever the roughness, and the rough model's
    // half vector (wi + wo) would vanish.
    bool trans_delta_ = false;
    double eta_ = 1.5;
};

}  // namespace glint::render
