// BSDFs of the path tracer, evaluated in a local shading frame (z = shading normal, pointing
// out of the solid). Directions point away from the surface: wo towards the viewer, wi towards
// the light. eval() returns f (without the cosine), pdf() the solid-angle density sample()
// uses; sample() returns the throughput weight f * |cos wi| / pdf directly, which stays exact
// for delta lobes. Plain values, no allocation: one is built per hit on the stack.
//
// Models: Lambert; the modified Phong BRDF (Lafortune & Willems 1994); and Blender 3.4's
// Principled BSDF as Cycles 3.4 builds it with the GGX distribution (not multiscatter), the
// lobes added without Fresnel layering (docs/pbr-mapping.md):
//   diffuse      base (1 - metallic)(1 - transmission) times Burley's diffuse with its
//                retro-reflection (Principled materials) or Lambert (POV-Ray, other MTL)
//   reflection   weight 1 - (1 - metallic) transmission; GGX D, separable Smith G1(o) G1(i),
//                Fresnel cspec0 + (1 - cspec0) FH with cspec0 = 0.08 specular (1 - metallic)
//                + base metallic and FH the dielectric Fresnel of the IOR that `specular`
//                implies (2 / (1 - sqrt(0.08 specular)) - 1), normalized to 0 at normal incidence
//   glass        weight (1 - metallic) transmission, split at the shading normal by the
//                dielectric Fresnel F(n . wo): F untinted GGX reflection, base (1 - F) GGX
//                refraction (Walter et al. 2007), both without a per-microfacet Fresnel
// GGX lobes are sampled by visible normals (Heitz 2018). Smooth surfaces (roughness below
// ~0.03, alpha below 1e-3) become delta lobes; so does an index-matched (IOR 1) transmission
// of any roughness: light passes straight through.
#pragma once

#include "core/math.h"
#include "render/bsdf/microfacet.h"

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

// The diffuse lobe of the Principled model: Blender's Principled BSDF uses Burley's (Disney)
// diffuse with retro-reflection; POV-Ray's diffuse and Blender's Diffuse BSDF are Lambert.
enum class DiffuseModel { Lambert, Burley };

struct PrincipledParams {
    Color base{0.8, 0.8, 0.8};
    DiffuseModel diffuse_model = DiffuseModel::Burley;
    double metallic = 0;
    double roughness = 0.5;
    double specular = 0.5;  // dielectric F0 = 0.08 * specular (reflection lobe only)
    double ior = 1.45;  // of the transmission (glass) lobe
    double transmission = 0;
    // A modified Phong lobe (Lafortune & Willems 1994) added to the others: POV-Ray's `phong`
    // highlight, which is the same cos^n of the angle to the mirror direction. Off when black.
    Color phong_ks{0, 0, 0};
    double phong_exponent = 0;
    // Blender's Principled BSDF beyond the above (0: off). Specular tint pulls the dielectric
    // reflection towards the base colour's hue; anisotropic stretches the reflection lobe
    // along the tangent of the frame it is evaluated in (alpha_x = r^2 / aspect, alpha_y =
    // r^2 aspect, aspect = sqrt(1 - 0.9 anisotropic)).
    double specular_tint = 0;
    double anisotropic = 0;
    // The refraction lobe's roughness; negative: the same as `roughness`.
    double transmission_roughness = -1;
    // The glass lobes' distribution (Blender's Glass BSDF defaults to Beckmann).
    Microfacet::Kind glass_distribution = Microfacet::Kind::GGX;
    // Off: no reflection lobe (the caller adds Multiscatter GGX's in its place, with
    // specular_cspec0() and specular_eta()).
    bool specular_lobe = true;
    // Off: no glass lobes (the caller adds Multiscatter GGX glass in their place); the other
    // lobes keep the weights that `transmission` gives them.
    bool glass_lobes = true;
    // Off: no diffuse lobe (a subsurface BSSRDF takes its place, render/bsdf/bssrdf.h).
    bool diffuse_lobe = true;
};

struct BsdfSample {
    Vec3 wi;
    Color weight;  // f * |cos wi| / pdf
    double pdf = 0;  // for delta lobes: the discrete probability (not usable for MIS)
    bool delta = false;
    bool diffuse = false;  // drawn from a diffuse lobe
    // A transmission's lobe: its alpha_x alpha_y (Cycles' bsdf_get_specular_roughness_squared,
    // 0 for a smooth one); infinite for every other lobe.
    double roughness2 = kInfinity;
};

class Bsdf {
public:
    static Bsdf lambert(const Color& albedo);
    static Bsdf principled(const PrincipledParams& p);
    // The modified Phong BRDF (Lafortune & Willems 1994): kd / pi + ks (n + 2) / (2 pi) cos^n a,
    // a the angle between wi and the mirror direction of wo; energy-conserving when kd + ks <= 1.
    // The glossy lobe is sampled exactly (pdf (n + 1) / (2 pi) cos^n a).
    static Bsdf phong(const Color& kd, const Color& ks, double exponent);

    // The reflection lobe's Fresnel colour at normal incidence (Cycles' cspec0) and the IOR
    // its Fresnel interpolation uses.
    Color specular_cspec0() const;
    double specular_eta() const;

    // `diffuse_scale` scales the diffuse lobe alone (Cycles' bump shadowing term).
    Color eval(const Vec3& wo, const Vec3& wi, double diffuse_scale = 1) const;
    double pdf(const Vec3& wo, const Vec3& wi) const;
    // (u1, u2) in [0, 1)^2: u1 picks a lobe by the lobe probabilities, then, rescaled to
    // [0, 1) within the picked lobe's share, samples the direction with u2. Using one 2D
    // point for both, as Cycles does (surface_shader_bsdf_bssrdf_pick), keeps the
    // stratification of the sampler's points within each lobe; a separate random number for
    // the pick left each lobe an unstratified subset of them (on a Principled surface under
    // a sky, 5-7x the variance of direct light). Returns false when no direction results.
    bool sample(const Vec3& wo, double u1, double u2, BsdfSample* out) const;
    // True when it has no lobe at all (nothing to add to a closure set).
    bool empty() const {
        return w_diffuse_ == 0 && w_spec_ == 0 && w_trans_ == 0 && w_phong_ == 0;
    }
    // The chance that sample() picks a delta lobe for `wo`.
    double delta_probability(const Vec3& wo) const;
    // True when every lobe is a delta (then light sampling is pointless).
    bool all_delta() const {
        return w_diffuse_ == 0 && w_phong_ == 0 && (w_spec_ == 0 || spec_delta_) &&
               (w_trans_ == 0 || (refl_delta_ && trans_delta_));
    }

private:
    // Lobe selection probabilities for wo (up to normalization): diffuse, reflection, glass
    // reflection, glass refraction, Phong.
    struct LobeProbs {
        double d = 0, s = 0, gr = 0, gt = 0, p = 0;
        double sum() const { return d + s + gr + gt + p; }
    };
    LobeProbs lobe_probs(const Vec3& wo) const;
    // Cycles' interpolated Fresnel of the reflection lobe at cos(wi, wm).
    Color spec_fresnel(double cos_h) const;
    // The glass reflection's tint (specular tint) at cos(wi, wm), interpolated as spec_fresnel.
    Color glass_reflection_color(double cos_h) const;
    // The glass lobe's split at the shading normal: F(n . wo) (wo as given, either side).
    double glass_fresnel(const Vec3& wo) const;
    double refraction_share(double F) const;
    double diffuse_shape(const Vec3& o, const Vec3& i) const;  // f * pi / albedo, same side

    Color diffuse_color_;  // albedo of the diffuse lobe (already weighted)
    bool burley_ = false;  // Burley's diffuse instead of Lambert
    double roughness_ = 0;  // Principled roughness (Burley's retro-reflection)
    Color spec_color_;     // cspec0 of the reflection lobe
    double spec_ior_ = 1.5;  // IOR implied by `specular`
    double spec_f0_ = 0.04;  // its Fresnel at normal incidence
    Color trans_tint_;     // tint of the refraction lobe (the base color)
    Color glass_tint_{1, 1, 1};  // cspec0 of the glass reflection (specular tint)
    double w_diffuse_ = 0, w_spec_ = 0, w_trans_ = 0;
    Color phong_ks_;  // modified Phong glossy lobe (w_phong_ = 1 when present)
    double phong_n_ = 0;
    double w_phong_ = 0;
    Microfacet spec_;       // the reflection lobe
    Microfacet glass_refl_;  // the glass lobe's reflection and refraction
    Microfacet glass_refr_;
    bool spec_delta_ = false;
    bool refl_delta_ = false;  // the glass reflection is a mirror
    // The refraction is a delta when smooth, and also when index-matched (eta = 1): then
    // no microfacet bends or reflects light, whatever the roughness, and the rough model's
    // half vector (wi + wo) would vanish.
    bool trans_delta_ = false;
    double eta_ = 1.5;
};

}  // namespace glint::render
