#include "render/bsdf/bsdf.h"

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

// The rough (or smooth) dielectric of Walter et al. 2007, without the tint: f and the pdf of
// its own sampling (reflection chosen with probability F).
double dielectric_eval(const Ggx& ggx, double eta, const Vec3& wo, const Vec3& wi, double* pdf) {
    *pdf = 0;
    const double cos_o = wo.z, cos_i = wi.z;
    if (cos_o == 0 || cos_i == 0) return 0;
    const bool reflection = cos_o * cos_i > 0;
    double etap = 1;
    if (!reflection) etap = cos_o > 0 ? eta : 1.0 / eta;
    Vec3 wm = wi * etap + wo;
    if (length_squared(wm) == 0) return 0;
    wm = normalize(wm);
    if (wm.z < 0) wm = -wm;
    // Microfacets seen from behind by either direction contribute nothing.
    if (dot(wm, wi) * cos_i < 0 || dot(wm, wo) * cos_o < 0) return 0;
    const double F = fresnel_dielectric(dot(wo, wm), eta);
    const double pv = ggx.pdf_visible(wo, wm);
    if (reflection) {
        *pdf = pv / (4 * std::fabs(dot(wo, wm))) * F;
        return ggx.d(wm) * ggx.g(wo, wi) * F / std::fabs(4 * cos_i * cos_o);
    }
    const double denom = sqr(dot(wi, wm) + dot(wo, wm) / etap);
    if (denom == 0) return 0;
    *pdf = pv * std::fabs(dot(wi, wm)) / denom * (1 - F);
    return ggx.d(wm) * (1 - F) * ggx.g(wo, wi) *
           std::fabs(dot(wi, wm) * dot(wo, wm) / (cos_i * cos_o * denom));
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
    const double t = std::clamp(p.transmission, 0.0, 1.0) * (1 - m);
    const double r = std::clamp(p.roughness, 0.0, 1.0);
    b.ggx_.alpha = std::max(r * r, 1e-4);
    b.spec_delta_ = r * r < kDeltaAlpha;
    b.w_diffuse_ = (1 - m) * (1 - std::clamp(p.transmission, 0.0, 1.0));
    b.diffuse_color_ = p.base * b.w_diffuse_;
    b.diffuse_fresnel_f0_ = std::clamp(0.08 * p.specular, 0.0, 1.0);
    const Color f0d(b.diffuse_fresnel_f0_);
    b.spec_color_ = f0d * (1 - m) + p.base * m;
    // specular 0 on a dielectric: no reflection lobe at all (and no Fresnel on the diffuse),
    // so POV-Ray's plain diffuse surfaces are pure Lambert.
    b.w_spec_ = b.spec_color_.max() > 0 ? 1 - t : 0.0;
    b.diffuse_fresnel_ = b.w_spec_ > 0;
    b.w_trans_ = t;
    b.trans_tint_ = p.base;
    b.eta_ = p.ior > 0 ? p.ior : 1.45;
    b.trans_delta_ = b.spec_delta_ || std::fabs(b.eta_ - 1) < kIndexMatched;
    if (b.w_diffuse_ <= 0) b.w_diffuse_ = 0;
    return b;
}

Color Bsdf::spec_fresnel(double cos_h) const {
    const double w = schlick_weight(cos_h);
    return spec_color_ + (Color(1) - spec_color_) * w;
}

void Bsdf::lobe_probs(const Vec3& wo, double* pd, double* ps, double* pt, double* pp) const {
    const double c = std::fabs(wo.z);
    const double fd = diffuse_fresnel_
                          ? diffuse_fresnel_f0_ + (1 - diffuse_fresnel_f0_) * schlick_weight(c)
                          : 0.0;
    *pd = w_diffuse_ > 0 ? average(diffuse_color_) * (1 - fd) : 0;
    *ps = w_spec_ > 0 ? w_spec_ * average(spec_fresnel(c)) : 0;
    *pt = w_trans_ > 0 ? w_trans_ * std::max(average(trans_tint_), 1e-3) : 0;
    *pp = w_phong_ > 0 ? average(phong_ks_) : 0;
    // A lobe that contributes must keep a chance of being sampled.
    if (w_diffuse_ > 0 && *pd <= 0 && average(diffuse_color_) > 0) *pd = 1e-3;
}

Color Bsdf::eval(const Vec3& wo, const Vec3& wi) const {
    Color f;
    const double s = wo.z < 0 ? -1.0 : 1.0;
    const Vec3 o(wo.x, wo.y, wo.z * s), i(wi.x, wi.y, wi.z * s);
    const bool same_side = o.z > 0 && i.z > 0;
    if (w_diffuse_ > 0 && same_side) {
        const double fd =
            diffuse_fresnel_ ? diffuse_fresnel_f0_ + (1 - diffuse_fresnel_f0_) * schlick_weight(o.z)
                             : 0.0;
        f += diffuse_color_ * (kInvPi * (1 - fd));
    }
    if (w_phong_ > 0 && same_side)
        f += phong_ks_ * ((phong_n_ + 2) / (2 * kPi) * phong_pow(phong_cos(o, i), phong_n_));
    if (w_spec_ > 0 && same_side && !spec_delta_) {
        const Vec3 wm = normalize(o + i);
        f += spec_fresnel(dot(o, wm)) *
             (w_spec_ * ggx_.d(wm) * ggx_.g(o, i) / (4 * o.z * i.z));
    }
    if (w_trans_ > 0 && !trans_delta_) {
        double pdf;
        f += trans_tint_ * (w_trans_ * dielectric_eval(ggx_, eta_, wo, wi, &pdf));
    }
    return f;
}

double Bsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    double pd, ps, pt, pp;
    lobe_probs(wo, &pd, &ps, &pt, &pp);
    const double sum = pd + ps + pt + pp;
    if (!(sum > 0)) return 0;
    const double s = wo.z < 0 ? -1.0 : 1.0;
    const Vec3 o(wo.x, wo.y, wo.z * s), i(wi.x, wi.y, wi.z * s);
    const bool same_side = o.z > 0 && i.z > 0;
    double pdf = 0;
    if (pd > 0 && same_side) pdf += pd * i.z * kInvPi;
    if (pp > 0 && same_side)
        pdf += pp * (phong_n_ + 1) / (2 * kPi) * phong_pow(phong_cos(o, i), phong_n_);
    if (ps > 0 && same_side && !spec_delta_) {
        const Vec3 wm = normalize(o + i);
        pdf += ps * ggx_.pdf_visible(o, wm) / (4 * dot(o, wm));
    }
    if (pt > 0 && !trans_delta_) {
        double p;
        dielectric_eval(ggx_, eta_, wo, wi, &p);
        pdf += pt * p;
    }
    return pdf / sum;
}

bool Bsdf::sample(const Vec3& wo, double u_lobe, double u1, double u2, BsdfSample* out) const {
    if (wo.z == 0) return false;
    double pd, ps, pt, pp;
    lobe_probs(wo, &pd, &ps, &pt, &pp);
    const double sum = pd + ps + pt + pp;
    if (!(sum > 0)) return false;
    const double s = wo.z < 0 ? -1.0 : 1.0;
    const Vec3 o(wo.x, wo.y, wo.z * s);
    double u = u_lobe * sum;
    Vec3 wi;
    if (u < pd) {
        const Vec3 i = cosine_hemisphere(u1, u2);
        wi = Vec3(i.x, i.y, i.z * s);
    } else if (u >= pd + ps + pt) {
        // Phong lobe: cos^n around the mirror direction.
        const Vec3 r(-o.x, -o.y, o.z);
        const double cos_a = std::pow(u1, 1.0 / (phong_n_ + 1));
        const double sin_a = std::sqrt(std::max(0.0, 1 - cos_a * cos_a));
        const double phi = 2 * kPi * u2;
        const Frame fr = Frame::from_normal(r);
        const Vec3 i = fr.to_world(Vec3(sin_a * std::cos(phi), sin_a * std::sin(phi), cos_a));
        if (i.z <= 0) return false;
        wi = Vec3(i.x, i.y, i.z * s);
    } else if (u < pd + ps) {
        if (spec_delta_) {
            const double p = ps / sum;
            out->wi = Vec3(-wo.x, -wo.y, wo.z);
            out->weight = spec_fresnel(o.z) * (w_spec_ / p);
            out->pdf = p;
            out->delta = true;
            return true;
        }
        const Vec3 wm = ggx_.sample_visible(o, u1, u2);
        const Vec3 i = reflect(o, wm);
        if (i.z <= 0) return false;
        wi = Vec3(i.x, i.y, i.z * s);
    } else {
        // Reflect or refract by the Fresnel term, reusing the rest of u_lobe.
        const double uc = std::clamp((u - pd - ps) / pt, 0.0, 1.0);
        const Vec3 wm = trans_delta_ ? Vec3(0, 0, 1) : ggx_.sample_visible(wo, u1, u2);
        const bool matched = std::fabs(eta_ - 1) < kIndexMatched;
        const double F = matched ? 0.0 : fresnel_dielectric(dot(wo, wm), eta_);
        if (matched) {
            wi = -wo;  // exactly straight on, so an IOR 1 object leaves no trace
        } else if (uc < F) {
            wi = reflect(wo, wm);
            if (wi.z * wo.z <= 0) return false;
        } else {
            double etap;
            if (!refract(wo, wm, eta_, &etap, &wi)) return false;
            if (wi.z * wo.z >= 0) return false;
        }
        if (trans_delta_) {
            const double p = pt / sum;
            out->wi = wi;
            out->weight = trans_tint_ * (w_trans_ / p);
            out->pdf = p * (uc < F ? F : 1 - F);
            out->delta = true;
            return true;
        }
    }
    const double pdf = this->pdf(wo, wi);
    if (!(pdf > 0)) return false;
    out->wi = wi;
    out->pdf = pdf;
    out->weight = eval(wo, wi) * (std::fabs(wi.z) / pdf);
    out->delta = false;
    return true;
}

}  // namespace glint::render
