#include "render/bsdf/bsdf.h"

#include <algorithm>
#include <cmath>

namespace glint::render {
namespace {

constexpr double kInvPi = 1.0 / kPi;
// Below this GGX alpha the specular lobes are treated as perfectly smooth.
constexpr double kDeltaAlpha = 1e-3;
// An interface whose relative IOR is this close to 1 bends light by less than ~1e-6 rad at any
// roughness: its transmission is treated as a straight pass-through.
constexpr double kIndexMatched = 1e-6;

double average(const Color& c) { return (c.r + c.g + c.b) * (1.0 / 3.0); }
double schlick_weight(double cos) {
    const double m = std::clamp(1.0 - cos, 0.0, 1.0);
    return (m * m) * (m * m) * m;
}
Vec3 cosine_hemisphere(double u1, double u2) {
    // Concentric disk mapping (Shirley-Chiu), lifted to the hemisphere.
    const double a = 2 * u1 - 1, b = 2 * u2 - 1;
    double r, phi;
    if (a == 0 && b == 0) return {0, 0, 1};
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = (kPi / 4) * (b / a);
    } else {
        r = b;
        phi = kPi / 2 - (kPi / 4) * (a / b);
    }
    const double x = r * std::cos(phi), y = r * std::sin(phi);
    return {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))};
}

// The IOR Cycles derives from Principled's `specular` for its reflection lobe: the dielectric
// whose F0 is 0.08 specular. Kept below the F0 of 1, where it would be infinite.
double specular_ior(double specular) {
    const double r = std::sqrt(std::clamp(0.08 * specular, 0.0, 0.999999));
    return 2.0 / (1.0 - r) - 1.0;
}

// Cosine of the angle between wi and the mirror direction of wo about z, and the lobe value.
double phong_cos(const Vec3& wo, const Vec3& wi) {
    return std::max(0.0, 2 * wo.z * wi.z - dot(wo, wi));
}
double phong_pow(double c, double n) { return c > 0 ? std::pow(c, n) : (n == 0 ? 1.0 : 0.0); }

}  // namespace

Bsdf Bsdf::lambert(const Color& albedo) {
    Bsdf b;
    b.diffuse_color_ = albedo;
    b.w_diffuse_ = 1;
    return b;
}

Bsdf Bsdf::phong(const Color& kd, const Color& ks, double exponent) {
    Bsdf b;
    b.diffuse_color_ = kd;
    b.w_diffuse_ = average(kd) > 0 ? 1 : 0;
    b.phong_ks_ = ks;
    b.phong_n_ = std::max(0.0, exponent);
    b.w_phong_ = average(ks) > 0 ? 1 : 0;
    return b;
}

Bsdf Bsdf::principled(const PrincipledParams& p) {
    Bsdf b;
    const double m = std::clamp(p.metallic, 0.0, 1.0);
    const double tr = std::clamp(p.transmission, 0.0, 1.0);
    const double t = tr * (1 - m);
    const double r = std::clamp(p.roughness, 0.0, 1.0);
    b.roughness_ = r;
    const double aspect = std::sqrt(std::max(0.0, 1 - 0.9 * std::clamp(p.anisotropic, 0.0, 1.0)));
    b.spec_ = Microfacet{Microfacet::Kind::GGX, std::clamp(r * r / aspect, 1e-4, 1.0),
                         std::max(r * r * aspect, 1e-4)};
    b.spec_delta_ = r * r / aspect < kDeltaAlpha;
    b.glass_refl_ = Microfacet{p.glass_distribution, std::max(r * r, 1e-4), std::max(r * r, 1e-4)};
    b.refl_delta_ = r * r < kDeltaAlpha;
    const double rt = p.transmission_roughness < 0 ? r
                                                   : std::clamp(p.transmission_roughness, 0.0, 1.0);
    b.glass_refr_ = Microfacet{p.glass_distribution, std::max(rt * rt, 1e-4),
                               std::max(rt * rt, 1e-4)};
    b.w_diffuse_ = (1 - m) * (1 - tr);
    b.diffuse_color_ = p.base * b.w_diffuse_;
    b.burley_ = p.diffuse_model == DiffuseModel::Burley;
    if (!(average(b.diffuse_color_) > 0) || !p.diffuse_lobe) b.w_diffuse_ = 0;
    // Cycles: cspec0 = 0.08 specular tint (1 - metallic) + base metallic, clamped to [0, 1],
    // tint = lerp(1, base / luminance(base), specular_tint) with Cycles' rough luminance, and
    // the interpolation's IOR from `specular`.
    const double spec = std::max(0.0, p.specular);
    const double st = p.specular_tint;
    Color tint(1, 1, 1);
    if (st != 0) {
        const double lum = 0.3 * p.base.r + 0.6 * p.base.g + 0.1 * p.base.b;
        const Color hue = lum > 0 ? p.base * (1 / lum) : Color(1, 1, 1);
        tint = Color(1 - st) + hue * st;
        b.glass_tint_ = p.base * st + Color(1 - st);
    }
    const Color cs = tint * (0.08 * spec) * (1 - m) + p.base * m;
    b.spec_color_ = Color(std::clamp(cs.r, 0.0, 1.0), std::clamp(cs.g, 0.0, 1.0),
                          std::clamp(cs.b, 0.0, 1.0));
    b.spec_ior_ = specular_ior(spec);
    b.spec_f0_ = fresnel_dielectric(1.0, b.spec_ior_);
    // No reflection lobe without specular and metallic, as in Cycles (POV-Ray's plain diffuse
    // surfaces are pure Lambert).
    b.w_spec_ = (spec > 1e-5 || m > 1e-5) && p.specular_lobe ? 1 - t : 0.0;
    b.w_trans_ = p.glass_lobes ? t : 0.0;
    b.trans_tint_ = p.base;
    b.eta_ = p.ior > 0 ? p.ior : 1.45;
    b.trans_delta_ = rt * rt < kDeltaAlpha || std::fabs(b.eta_ - 1) < kIndexMatched;
    if (average(p.phong_ks) > 0) {
        b.phong_ks_ = p.phong_ks;
        b.phong_n_ = std::max(0.0, p.phong_exponent);
        b.w_phong_ = 1;
    }
    return b;
}

Color Bsdf::specular_cspec0() const { return spec_color_; }
double Bsdf::specular_eta() const { return spec_ior_; }

Color Bsdf::spec_fresnel(double cos_h) const {
    if (spec_f0_ >= 1) return Color(1);
    const double fh = std::clamp(
        (fresnel_dielectric(std::fabs(cos_h), spec_ior_) - spec_f0_) / (1 - spec_f0_), 0.0, 1.0);
    return spec_color_ * (1 - fh) + Color(fh);
}

Color Bsdf::glass_reflection_color(double cos_h) const {
    if (glass_tint_.r == 1 && glass_tint_.g == 1 && glass_tint_.b == 1) return Color(1, 1, 1);
    const double f0 = fresnel_dielectric(1.0, eta_);
    if (f0 >= 1) return Color(1, 1, 1);
    const double fh =
        std::clamp((fresnel_dielectric(std::fabs(cos_h), eta_) - f0) / (1 - f0), 0.0, 1.0);
    return glass_tint_ * (1 - fh) + Color(fh);
}

double Bsdf::glass_fresnel(const Vec3& wo) const {
    if (std::fabs(eta_ - 1) < kIndexMatched) return 0;
    return fresnel_dielectric(wo.z, eta_);
}

// Cycles keeps a rough refraction lobe of at least 1e-4 under total internal reflection at
// the shading normal (a microfacet may still refract); a smooth one cannot.
double Bsdf::refraction_share(double F) const {
    return trans_delta_ ? 1 - F : std::max(1e-4, 1 - F);
}

double Bsdf::diffuse_shape(const Vec3& o, const Vec3& i) const {
    if (!burley_) return 1;
    // Burley 2015: the Lambert part (1 - FV / 2)(1 - FL / 2) and the retro-reflection
    // RR (FL + FV + FL FV (RR - 1)), RR = roughness 2 cos^2(theta_d) = roughness (1 + wo . wi).
    const double fv = schlick_weight(o.z), fl = schlick_weight(i.z);
    const double rr = roughness_ * (1 + dot(o, i));
    return (1 - 0.5 * fv) * (1 - 0.5 * fl) + rr * (fl + fv + fl * fv * (rr - 1));
}

Bsdf::LobeProbs Bsdf::lobe_probs(const Vec3& wo) const {
    // Cycles' sample weights: each lobe's weight, the reflection's by its Fresnel at n . wo.
    LobeProbs l;
    const double c = std::fabs(wo.z);
    if (w_diffuse_ > 0) l.d = average(diffuse_color_);
    if (w_spec_ > 0) l.s = w_spec_ * std::max(average(spec_fresnel(c)), 1e-3);
    if (w_trans_ > 0) {
        const double F = glass_fresnel(wo);
        l.gr = w_trans_ * F;
        l.gt = average(trans_tint_) > 0 ? w_trans_ * average(trans_tint_) * refraction_share(F)
                                        : 0.0;
    }
    if (w_phong_ > 0) l.p = average(phong_ks_);
    return l;
}

double Bsdf::delta_probability(const Vec3& wo) const {
    if (wo.z == 0) return 0;
    const LobeProbs l = lobe_probs(wo);
    const double sum = l.sum();
    if (!(sum > 0)) return 0;
    double d = spec_delta_ ? l.s : 0.0;
    if (refl_delta_) d += l.gr;
    if (trans_delta_ || std::fabs(eta_ - 1) < kIndexMatched) d += l.gt;
    return d / sum;
}

Color Bsdf::eval(const Vec3& wo, const Vec3& wi, double diffuse_scale) const {
    Color f;
    const double s = wo.z < 0 ? -1.0 : 1.0;
    const Vec3 o(wo.x, wo.y, wo.z * s), i(wi.x, wi.y, wi.z * s);
    const bool same_side = o.z > 0 && i.z > 0;
    if (w_diffuse_ > 0 && same_side)
        f += diffuse_color_ * (kInvPi * diffuse_shape(o, i) * diffuse_scale);
    if (w_phong_ > 0 && same_side)
        f += phong_ks_ * ((phong_n_ + 2) / (2 * kPi) * phong_pow(phong_cos(o, i), phong_n_));
    if (w_spec_ > 0 && same_side && !spec_delta_) {
        double pdf;
        const double g = microfacet_reflection(spec_, o, i, &pdf);
        f += spec_fresnel(dot(i, normalize(o + i))) * (w_spec_ * g);
    }
    if (w_trans_ > 0 && o.z > 0 && i.z != 0 && !(i.z > 0 ? refl_delta_ : trans_delta_)) {
        const double F = glass_fresnel(wo);
        double pdf;
        if (i.z > 0) {
            f += glass_reflection_color(dot(i, normalize(o + i))) *
                 (w_trans_ * F * microfacet_reflection(glass_refl_, o, i, &pdf));
        } else {
            const double etap = wo.z > 0 ? eta_ : 1.0 / eta_;
            f += trans_tint_ *
                 (w_trans_ * refraction_share(F) * microfacet_refraction(glass_refr_, etap, o, i, &pdf));
        }
    }
    return f;
}

double Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    const LobeProbs l = lobe_probs(wo);
    const double sum = l.sum();
    if (!(sum > 0)) return 0;
    const double s = wo.z < 0 ? -1.0 : 1.0;
    const Vec3 o(wo.x, wo.y, wo.z * s), i(wi.x, wi.y, wi.z * s);
    const bool same_side = o.z > 0 && i.z > 0;
    double pdf = 0;
    if (l.d > 0 && same_side) pdf += l.d * i.z * kInvPi;
    if (l.p > 0 && same_side)
        pdf += l.p * (phong_n_ + 1) / (2 * kPi) * phong_pow(phong_cos(o, i), phong_n_);
    double p;
    if (same_side && l.s > 0 && !spec_delta_) {
        microfacet_reflection(spec_, o, i, &p);
        pdf += l.s * p;
    }
    if (same_side && l.gr > 0 && !refl_delta_) {
        microfacet_reflection(glass_refl_, o, i, &p);
        pdf += l.gr * p;
    }
    if (l.gt > 0 && !trans_delta_ && o.z > 0 && i.z < 0) {
        microfacet_refraction(glass_refr_, wo.z > 0 ? eta_ : 1.0 / eta_, o, i, &p);
        pdf += l.gt * p;
    }
    return pdf / sum;
}

bool Bsdf::sample(const Vec3& wo, double u1, double u2, BsdfSample* out) const {
    if (wo.z == 0) return false;
    const LobeProbs l = lobe_probs(wo);
    const double sum = l.sum();
    if (!(sum > 0)) return false;
    const double s = wo.z < 0 ? -1.0 : 1.0;
    const Vec3 o(wo.x, wo.y, wo.z * s);
    const double u = u1 * sum;
    // u1 rescaled to [0, 1) within the share [lo, lo + width) of sum that picked the lobe.
    auto rescaled = [&](double lo, double width) {
        return width > 0 ? std::clamp((u - lo) / width, 0.0, 0x1.fffffffffffffp-1) : 0.0;
    };
    auto delta = [&](const Vec3& wi_local, const Color& weight, double p) {
        out->wi = Vec3(wi_local.x, wi_local.y, wi_local.z * s);
        out->weight = weight / p;
        out->pdf = p;
        out->delta = true;
        return true;
    };
    Vec3 i;
    out->diffuse = u < l.d;
    out->roughness2 = kInfinity;
    if (u < l.d) {
        i = cosine_hemisphere(rescaled(0, l.d), u2);
    } else if (u < l.d + l.s) {
        if (spec_delta_) return delta(Vec3(-o.x, -o.y, o.z), spec_fresnel(o.z) * w_spec_, l.s / sum);
        i = reflect(o, spec_.sample_normal(o, rescaled(l.d, l.s), u2));
        if (i.z <= 0) return false;
    } else if (u < l.d + l.s + l.gr) {
        if (refl_delta_)
            return delta(Vec3(-o.x, -o.y, o.z),
                         glass_reflection_color(o.z) * (w_trans_ * glass_fresnel(wo)), l.gr / sum);
        i = reflect(o, glass_refl_.sample_normal(o, rescaled(l.d + l.s, l.gr), u2));
        if (i.z <= 0) return false;
    } else if (u < l.d + l.s + l.gr + l.gt) {
        const double etap = wo.z > 0 ? eta_ : 1.0 / eta_;
        const double share = refraction_share(glass_fresnel(wo));
        out->roughness2 = trans_delta_ || std::fabs(eta_ - 1) < kIndexMatched
                              ? 0.0
                              : glass_refr_.alpha_x * glass_refr_.alpha_y;
        if (std::fabs(eta_ - 1) < kIndexMatched)  // straight on: an IOR 1 object leaves no trace
            return delta(-o, trans_tint_ * (w_trans_ * share), l.gt / sum);
        const Vec3 wm = trans_delta_ ? Vec3(0, 0, 1)
                                     : glass_refr_.sample_normal(o, rescaled(l.d + l.s + l.gr, l.gt), u2);
        if (dot(o, wm) <= 0) return false;
        if (!refract(o, wm, etap, &i) || i.z >= 0) return false;
        if (trans_delta_) return delta(i, trans_tint_ * (w_trans_ * share), l.gt / sum);
    } else {
        // Phong lobe: cos^n around the mirror direction.
        const Vec3 r(-o.x, -o.y, o.z);
        const double cos_a = std::pow(rescaled(l.d + l.s + l.gr + l.gt, l.p), 1.0 / (phong_n_ + 1));
        const double sin_a = std::sqrt(std::max(0.0, 1 - cos_a * cos_a));
        const double phi = 2 * kPi * u2;
        const Frame fr = Frame::from_normal(r);
        i = fr.to_world(Vec3(sin_a * std::cos(phi), sin_a * std::sin(phi), cos_a));
        if (i.z <= 0) return false;
    }
    const Vec3 wi(i.x, i.y, i.z * s);
    const double pdf = this->pdf(wo, wi);
    if (!(pdf > 0)) return false;
    out->wi = wi;
    out->pdf = pdf;
    out->weight = eval(wo, wi) * (std::fabs(wi.z) / pdf);
    out->delta = false;
    return true;
}

}  // namespace glint::render
