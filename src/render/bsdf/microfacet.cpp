#include "render/bsdf/microfacet.h"

#include <algorithm>
#include <cmath>

namespace glint::render {
namespace {

double sqr(double v) { return v * v; }

// cos^2 and sin^2 of the azimuth of w, (1, 0) at the pole.
void azimuth2(const Vec3& w, double* c2, double* s2) {
    const double r2 = w.x * w.x + w.y * w.y;
    if (!(r2 > 0)) {
        *c2 = 1;
        *s2 = 0;
        return;
    }
    *c2 = w.x * w.x / r2;
    *s2 = w.y * w.y / r2;
}

// The GGX masking of the clearcoat lobe: a fixed alpha of 0.25 (Cycles 3.4, after Burley).
constexpr double kClearcoatMaskAlpha = 0.25;

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

double Microfacet::d(const Vec3& wm) const {
    const double cos2 = wm.z * wm.z;
    if (cos2 <= 0) return 0;
    switch (kind) {
        case Kind::GGX: {
            const double t = sqr(wm.x / alpha_x) + sqr(wm.y / alpha_y) + cos2;
            return 1 / (kPi * alpha_x * alpha_y * t * t);
        }
        case Kind::Beckmann: {
            const double e = (sqr(wm.x / alpha_x) + sqr(wm.y / alpha_y)) / cos2;
            return std::exp(-e) / (kPi * alpha_x * alpha_y * cos2 * cos2);
        }
        case Kind::Clearcoat: {
            const double a2 = alpha_x * alpha_x;
            if (a2 >= 1) return 1 / kPi;
            return (a2 - 1) / (kPi * std::log(a2) * (1 + (a2 - 1) * cos2));
        }
    }
    return 0;
}

double Microfacet::g1(const Vec3& w) const {
    const double cos2 = w.z * w.z;
    if (cos2 <= 0) return 0;
    const double tan2 = std::max(0.0, 1 - cos2) / cos2;
    double c2, s2;
    azimuth2(w, &c2, &s2);
    if (kind == Kind::Beckmann) {
        // Cycles' rational fit of Beckmann's Smith G1, of the alpha projected on w's azimuth.
        const double inv_a = std::sqrt((c2 * alpha_x * alpha_x + s2 * alpha_y * alpha_y) * tan2);
        if (inv_a < 0.625) return 1;
        const double a = 1 / inv_a;
        return ((2.181 * a + 3.535) * a) / ((2.577 * a + 2.276) * a + 1);
    }
    const double a2 = kind == Kind::Clearcoat ? sqr(kClearcoatMaskAlpha)
                                              : c2 * alpha_x * alpha_x + s2 * alpha_y * alpha_y;
    return 2 / (1 + std::sqrt(1 + a2 * tan2));
}

double Microfacet::pdf_normal(const Vec3& w, const Vec3& wm) const {
    if (kind != Kind::GGX) return d(wm) * std::max(wm.z, 0.0);
    if (w.z == 0) return 0;
    return g1(w) / std::fabs(w.z) * d(wm) * std::fabs(dot(w, wm));
}

Vec3 Microfacet::sample_normal(const Vec3& w, double u1, double u2) const {
    if (kind == Kind::Beckmann) {
        // D(m) cos(m): the azimuth by the ellipse of the alphas, then the slope.
        double phi;
        if (alpha_x == alpha_y) {
            phi = 2 * kPi * u2;
        } else {
            phi = std::atan(alpha_y / alpha_x * std::tan(2 * kPi * u2 + 0.5 * kPi));
            if (u2 > 0.5) phi += kPi;
        }
        const double c = std::cos(phi), s = std::sin(phi);
        const double inv_a2 = sqr(c / alpha_x) + sqr(s / alpha_y);
        const double tan2 = -std::log(std::max(1 - u1, 1e-300)) / inv_a2;
        const double cos_t = 1 / std::sqrt(1 + tan2);
        const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
        return {sin_t * c, sin_t * s, std::max(cos_t, 1e-9)};
    }
    if (kind == Kind::Clearcoat) {
        const double a2 = alpha_x * alpha_x;
        const double cos2 = a2 >= 1 ? 1 - u1 : (1 - std::pow(a2, 1 - u1)) / (1 - a2);
        const double cos_t = std::sqrt(std::clamp(cos2, 0.0, 1.0));
        const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
        const double phi = 2 * kPi * u2;
        return {sin_t * std::cos(phi), sin_t * std::sin(phi), std::max(cos_t, 1e-9)};
    }
    // GGX visible normals: stretch the view to the unit-roughness configuration, sample the
    // projected hemisphere there, stretch back.
    Vec3 wh = normalize(Vec3(alpha_x * w.x, alpha_y * w.y, w.z));
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
    return normalize(Vec3(alpha_x * nh.x, alpha_y * nh.y, std::max(1e-9, nh.z)));
}

double microfacet_reflection(const Microfacet& m, const Vec3& o, const Vec3& i, double* pdf) {
    const Vec3 wm = normalize(o + i);
    const double om = dot(o, wm);
    if (!(om > 0)) {
        *pdf = 0;
        return 0;
    }
    *pdf = m.pdf_normal(o, wm) / (4 * om);
    return m.d(wm) * m.g(o, i) / (4 * o.z * i.z);
}

double microfacet_refraction(const Microfacet& m, double etap, const Vec3& o, const Vec3& i,
                             double* pdf) {
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
    *pdf = m.pdf_normal(o, wm) * std::fabs(im) / denom;
    return m.d(wm) * m.g(o, i) * std::fabs(im * om / (i.z * o.z * denom));
}

Vec3 reflect(const Vec3& wo, const Vec3& n) { return -wo + n * (2.0 * dot(wo, n)); }

bool refract(const Vec3& wi, Vec3 n, double eta, Vec3* wt) {
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
    return true;
}

}  // namespace glint::render
