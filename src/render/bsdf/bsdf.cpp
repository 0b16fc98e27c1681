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
double sqr(double v) { return v * v; }
double schlick_weight(double cos) {
    const double m = std::clamp(1.0 - cos, 0.0, 1.0);
    return (m * m) * (m * m) * m;
}
Vec3 reflect(const Vec3& wo, const Vec3& n) { return -wo + n * (2.0 * dot(wo, n)); }

// Refraction of wi through a surface with normal n; eta = inside over outside index.
bool refract(const Vec3& wi, Vec3 n, double eta, double* etap, Vec3* wt) {
    double cos_i = dot(n, wi);
    if (cos_i < 0) {
        eta = 1.0 / eta;
        cos_i = -cos_i;
        n = -n;
    }
    const double sin2_t = std::max(0.0, 1.0 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0) return false;
    const double cos_t = std::sqrt(1.0 - sin2_t);
    *wt = -wi / eta + n * (cos_i / eta - cos_t);
    *etap = eta;
    return true;
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

// The GGX microfacet refraction of a glass lobe without its Fresnel factor (Walter et al. 2007,
// in the form Cycles evaluates: radiance is not scaled by 1 / eta^2), for o.z > 0 > i.z in the
// frame flipped to wo's side; etap: the index on i's side over o's. Returns f and the pdf of
// refracting a visible normal sampled from o.
double refraction_eval(const Ggx& ggx, double etap, const Vec3& o, const Vec3& i, double* pdf) {
    *pdf = 0;
    Vec3 wm = i * etap + o;
    if (!(length_squared(wm) > 0)) return 0;
    wm = normalize(wm);
    if (wm.z < 0) wm = -wm;
    // Microfacets seen from behind by either direction contribute nothing.
    const double om = dot(o, wm), im = dot(i, wm);
    if (om <= 0 || im >= 0) return 0;
    const double denom = sqr(im + om / etap);
    if (!(denom > 0)) return 0;
    *pdf = ggx.pdf_visible(o, wm) * std::fabs(im) / denom;
    return ggx.d(wm) * ggx.g(o, i) * std::fabs(im * om / (i.z * o.z * denom));
}

// GGX reflection without Fresnel: f and the pdf of reflecting a visible normal sampled from o.
double reflection_eval(const Ggx& ggx, const Vec3& o, const Vec3& i, double* pdf) {
    const Vec3 wm = normalize(o + i);
    *pdf = ggx.pdf_visible(o, wm) / (4 * dot(o, wm));
    return ggx.d(wm) * ggx.g(o, i) / (4 * o.z * i.z);
}

// Cosine of the angle between wi and the mirror direction of wo about z, and the lobe value.
double phong_cos(const Vec3& wo, const Vec3& wi) {
    return std::max(0.0, 2 * wo.z * wi.z - dot(wo, wi));
}
double phong_pow(double c, double n) { return c > 0 ? std::pow(c, n) : (n == 0 ? 1.0 : 0.0); }

}  // namespace

double fresnel_dielectric(double cos_i, double eta) {
    cos_i = std::clamp(cos_i, -1.0, 1.0);
    if (cos_i < 0) {
        eta = 1.0 / eta;
        cos_i = -cos_i;
    }
    const double sin2_t = (1 - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1) return 1;
    const double cos_t = std::sqrt(std::max(0.0, 1 - sin2_t));
    const double r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const double r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return (r_parl * r_parl + r_perp * r_perp) / 2;
}

double Ggx::d(const Vec3& wm) const {
    const double cos2 = wm.z * wm.z;
    if (cos2 <= 0) return 0;
    const double a2 = alpha * alpha;
    const double t = cos2 * (a2 - 1) + 1;
    return a2 / (kPi * t * t);
}

double Ggx::lambda(const Vec3& w) const {
    const double cos2 = w.z * w.z;
    if (cos2 <= 0) return 1e30;
    const double tan2 = std::max(0.0, 1 - cos2) / cos2;
    return (std::sqrt(1 + alpha * alpha * tan2) - 1) / 2;
}

double Ggx::pdf_visible(const Vec3& w, const Vec3& wm) const {
    if (w.z == 0) return 0;
    return g1(w) / std::fabs(w.z) * d(wm) * std::fabs(dot(w, wm));
}

Vec3 Ggx::sample_visible(const Vec3& w, double u1, double u2) const {
    Vec3 wh = normalize(Vec3(alpha * w.x, alpha * w.y, w.z));
    if (wh.z < 0) wh = -wh;
    const double len2 = wh.x * wh.x + wh.y * wh.y;
    const Vec3 t1 = len2 > 0 ? Vec3(-wh.y, wh.x, 0) / std::sqrt(len2) : Vec3(1, 0, 0);
    const Vec3 t2 = cross(wh, t1);
    const double r = std::sqrt(u1), phi = 2 * kPi * u2;
    const double p1 = r * std::cos(phi);
    double p2 = r * std::sin(phi);
    const double s = 0.5 * (1 + wh.z);
    p2 = (1 - s) * std::sqrt(std::max(0.0, 1 - p1 * p1)) + s * p2;
    const Vec3 nh = t1 * p1 + t2 * p2 + wh * std::sqrt(std::max(0.0, 1 - p1 * p1 - p2 * p2));
    return normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(1e-9, nh.z)));
}

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
    b.ggx_.alpha = std::max(r * r, 1e-4);
    b.spec_delta_ = r * r < kDeltaAlpha;
    b.w_diffuse_ = (1 - m) * (1 - tr);
    b.diffuse_color_ = p.base * b.w_diffuse_;
    b.burley_ = p.diffuse_model == DiffuseModel::Burley;
    if (!(average(b.diffuse_color_) > 0)) b.w_diffuse_ = 0;
    // Cycles: cspec0 = 0.08 specular (1 - metallic) + base metallic, clamped to [0, 1], and the
    // interpolation's IOR from `specular` (specular_tint 0: the IR carries none).
    const double spec = std::max(0.0, p.specular);
    const Color cs = Color(0.08 * spec) * (1 - m) + p.base * m;
    b.spec_color_ = Color(std::clamp(cs.r, 0.0, 1.0), std::clamp(cs.g, 0.0, 1.0),
                          std::clamp(cs.b, 0.0, 1.0));
    b.spec_ior_ = specular_ior(spec);
    b.spec_f0_ = fresnel_dielectric(1.0, b.spec_ior_);
    // No reflection lobe without specular and metallic, as in Cycles (POV-Ray's plain diffuse
    // surfaces are pure Lambert).
    b.w_spec_ = (spec > 1e-5 || m > 1e-5) ? 1 - t : 0.0;
    b.w_trans_ = t;
    b.trans_tint_ = p.base;
    b.eta_ = p.ior > 0 ? p.ior : 1.45;
    b.trans_delta_ = b.spec_delta_ || std::fabs(b.eta_ - 1) < kIndexMatched;
    if (average(p.phong_ks) > 0) {
        b.phong_ks_ = p.phong_ks;
        b.phong_n_ = std::max(0.0, p.phong_exponent);
        b.w_phong_ = 1;
    }
    return b;
}

Color Bsdf::spec_fresnel(double cos_h) const {
    if (spec_f0_ >= 1) return Color(1);
    const double fh = std::clamp(
        (fresnel_dielectric(std::fabs(cos_h), spec_ior_) - spec_f0_) / (1 - spec_f0_), 0.0, 1.0);
    return spec_color_ * (1 - fh) + Color(fh);
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

Color Bsdf::eval(const Vec3& wo, const Vec3& wi) const {
    Color f;
    const double s = wo.z < 0 ? -1.0 : 1.0;
    const Vec3 o(wo.x, wo.y, wo.z * s), i(wi.x, wi.y, wi.z * s);
    const bool same_side = o.z > 0 && i.z > 0;
    if (w_diffuse_ > 0 && same_side) f += diffuse_color_ * (kInvPi * diffuse_shape(o, i));
    if (w_phong_ > 0 && same_side)
        f += phong_ks_ * ((phong_n_ + 2) / (2 * kPi) * phong_pow(phong_cos(o, i), phong_n_));
    if (w_spec_ > 0 && same_side && !spec_delta_) {
        double pdf;
        const double g = reflection_eval(ggx_, o, i, &pdf);
        f += spec_fresnel(dot(i, normalize(o + i))) * (w_spec_ * g);
    }
    if (w_trans_ > 0 && !trans_delta_ && o.z > 0 && i.z != 0) {
        const double F = glass_fresnel(wo);
        double pdf;
        if (i.z > 0) {
            f += Color(w_trans_ * F * reflection_eval(ggx_, o, i, &pdf));
        } else {
            const double etap = wo.z > 0 ? eta_ : 1.0 / eta_;
            f += trans_tint_ *
                 (w_trans_ * refraction_share(F) * refraction_eval(ggx_, etap, o, i, &pdf));
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
    if (same_side && ((l.s > 0 && !spec_delta_) || (l.gr > 0 && !trans_delta_))) {
        reflection_eval(ggx_, o, i, &p);
        if (!spec_delta_) pdf += l.s * p;
        if (!trans_delta_) pdf += l.gr * p;
    }
    if (l.gt > 0 && !trans_delta_ && o.z > 0 && i.z < 0) {
        refraction_eval(ggx_, wo.z > 0 ? eta_ : 1.0 / eta_, o, i, &p);
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
    if (u < l.d) {
        i = cosine_hemisphere(rescaled(0, l.d), u2);
    } else if (u < l.d + l.s) {
        if (spec_delta_) return delta(Vec3(-o.x, -o.y, o.z), spec_fresnel(o.z) * w_spec_, l.s / sum);
        i = reflect(o, ggx_.sample_visible(o, rescaled(l.d, l.s), u2));
        if (i.z <= 0) return false;
    } else if (u < l.d + l.s + l.gr) {
        if (trans_delta_)
            return delta(Vec3(-o.x, -o.y, o.z), Color(w_trans_ * glass_fresnel(wo)), l.gr / sum);
        i = reflect(o, ggx_.sample_visible(o, rescaled(l.d + l.s, l.gr), u2));
        if (i.z <= 0) return false;
    } else if (u < l.d + l.s + l.gr + l.gt) {
        const double etap = wo.z > 0 ? eta_ : 1.0 / eta_;
        const double share = refraction_share(glass_fresnel(wo));
        if (std::fabs(eta_ - 1) < kIndexMatched)  // straight on: an IOR 1 object leaves no trace
            return delta(-o, trans_tint_ * (w_trans_ * share), l.gt / sum);
        const Vec3 wm = trans_delta_ ? Vec3(0, 0, 1)
                                     : ggx_.sample_visible(o, rescaled(l.d + l.s + l.gr, l.gt), u2);
        double unused;
        if (dot(o, wm) <= 0) return false;
        if (!refract(o, wm, etap, &unused, &i) || i.z >= 0) return false;
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
