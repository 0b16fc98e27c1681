#include "render/bsdf/lobe.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>

namespace glint::render {
namespace {

constexpr double kInvPi = 1.0 / kPi;

double schlick_weight(double cos) {
    const double m = std::clamp(1.0 - cos, 0.0, 1.0);
    return (m * m) * (m * m) * m;
}

Vec3 cosine_hemisphere(double u1, double u2) {
    const double r = std::sqrt(u1), phi = 2 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u1))};
}

// Uniform within `angle` of the axis; the density is 1 / (2 pi (1 - cos angle)).
Vec3 uniform_cone(const Vec3& axis, double angle, double u1, double u2) {
    const double zmin = std::cos(angle);
    const double z = zmin + (1 - zmin) * u1;
    const double r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u2;
    return Frame::from_normal(axis).to_world(Vec3(r * std::cos(phi), r * std::sin(phi), z));
}

double cone_pdf(double angle) {
    const double d = 1 - std::cos(angle);
    return d > 0 ? 1 / (2 * kPi * d) : 0;
}

// Cycles' Toon: 1 within max_angle, a linear fade over `smooth`, 0 beyond.
double toon_intensity(double max_angle, double smooth, double angle) {
    if (angle < max_angle) return 1;
    if (smooth != 0 && angle < max_angle + smooth) return 1 - (angle - max_angle) / smooth;
    return 0;
}

double ashikhmin_exponent(double alpha) { return 2 / (alpha * alpha) - 2; }

}  // namespace

Lobe Lobe::oren_nayar(double roughness) {
    Lobe l;
    l.kind_ = Kind::OrenNayar;
    const double sigma = std::clamp(roughness, 0.0, 1.0);
    const double div = 1 / (kPi + (3 * kPi - 4) / 6 * sigma);
    l.a_ = div;
    l.b_ = sigma * div;
    return l;
}

Lobe Lobe::subsurface_exit() {
    Lobe l;
    l.kind_ = Kind::SubsurfaceExit;
    return l;
}

Lobe Lobe::retro_reflection(double roughness) {
    Lobe l;
    l.kind_ = Kind::RetroReflection;
    l.a_ = roughness;
    return l;
}

Lobe Lobe::burley_lambert() {
    Lobe l;
    l.kind_ = Kind::BurleyLambert;
    return l;
}

Lobe Lobe::translucent() {
    Lobe l;
    l.kind_ = Kind::Translucent;
    return l;
}

Lobe Lobe::toon(bool glossy, double size, double smooth) {
    Lobe l;
    l.kind_ = glossy ? Kind::GlossyToon : Kind::DiffuseToon;
    l.a_ = std::clamp(size, 0.0, 1.0) * kPi / 2;
    l.b_ = std::clamp(smooth, 0.0, 1.0) * kPi / 2;
    return l;
}

Lobe Lobe::velvet(double sigma) {
    Lobe l;
    l.kind_ = Kind::Velvet;
    const double s = std::max(sigma, 0.01);
    l.a_ = 1 / (s * s);
    return l;
}

Lobe Lobe::sheen() {
    Lobe l;
    l.kind_ = Kind::Sheen;
    return l;
}

Lobe Lobe::clearcoat(double clearcoat, double roughness) {
    Lobe l;
    l.kind_ = Kind::Clearcoat;
    l.a_ = clearcoat;
    const double alpha = std::clamp(roughness * roughness, 1e-4, 1.0);
    l.m_ = Microfacet{Microfacet::Kind::Clearcoat, alpha, alpha};
    return l;
}

Lobe Lobe::reflection(const Microfacet& m) {
    Lobe l;
    l.kind_ = Kind::Reflection;
    l.m_ = m;
    l.m_.alpha_x = std::clamp(m.alpha_x, 0.0, 1.0);
    l.m_.alpha_y = std::clamp(m.alpha_y, 0.0, 1.0);
    // Cycles' singular threshold for microfacet closures.
    l.delta_ = l.m_.alpha_x * l.m_.alpha_y <= 1e-7;
    return l;
}

Lobe Lobe::ashikhmin_shirley(double alpha_x, double alpha_y) {
    Lobe l;
    l.kind_ = Kind::AshikhminShirley;
    alpha_x = std::clamp(alpha_x, 1e-4, 1.0);
    alpha_y = std::clamp(alpha_y, 1e-4, 1.0);
    l.delta_ = std::max(alpha_x, alpha_y) <= 1e-4;
    l.a_ = ashikhmin_exponent(alpha_x);
    l.b_ = ashikhmin_exponent(alpha_y);
    return l;
}

Lobe Lobe::refraction(const Microfacet& m, double eta) {
    Lobe l;
    l.kind_ = Kind::Refraction;
    l.m_ = m;
    l.eta_ = std::max(eta, 1e-5);
    l.delta_ = m.alpha_x * m.alpha_y <= 1e-7 || std::fabs(l.eta_ - 1) < 1e-6;
    return l;
}

Lobe Lobe::multi_ggx(const MultiGgx& m) {
    Lobe l;
    l.kind_ = Kind::MultiGGX;
    l.multi_ = m;
    l.multi_.alpha_x = std::clamp(m.alpha_x, 0.0, 1.0);
    l.multi_.alpha_y = std::clamp(m.alpha_y, 0.0, 1.0);
    l.delta_ = l.multi_.alpha_x * l.multi_.alpha_y < 1e-7;
    return l;
}

Lobe Lobe::multi_glass(const MultiGlass& m) {
    Lobe l;
    l.kind_ = Kind::MultiGlass;
    l.glass_ = m;
    l.glass_.alpha = std::clamp(m.alpha, 1e-4, 1.0);
    l.glass_.eta = std::max(m.eta, 1e-5);
    auto saturate = [](const Color& c) {
        return Color(std::clamp(c.r, 0.0, 1.0), std::clamp(c.g, 0.0, 1.0),
                     std::clamp(c.b, 0.0, 1.0));
    };
    l.glass_.color = saturate(m.color);
    l.glass_.cspec0 = saturate(m.cspec0);
    l.delta_ = l.glass_.alpha * l.glass_.alpha < 1e-7;
    return l;
}

namespace {
// A seed from the bits of some doubles: the multiscatter walk's random numbers, the same for
// the same directions whatever the thread.
uint64_t seed_of(std::initializer_list<double> values) {
    uint64_t h = 0xcbf29ce484222325ULL;
    for (double v : values) {
        uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = (h ^ bits) * 0x100000001b3ULL;
        h ^= h >> 29;
    }
    return h;
}
}  // namespace

double Lobe::sample_scale(const Vec3& wo) const {
    const double c = std::fabs(wo.z);
    if (kind_ == Kind::Sheen) return schlick_weight(c) * c;
    if (kind_ == Kind::RetroReflection) return a_ * schlick_weight(c);
    if (kind_ == Kind::Clearcoat) return 0.25 * a_ * fresnel_dielectric(c, 1.5);
    if (kind_ == Kind::MultiGGX && multi_.fresnel) {
        // Cycles: the Fresnel colour at n . wo, averaged.
        const double f0 = fresnel_dielectric(1.0, multi_.eta);
        const double fh =
            f0 >= 1 ? 1.0
                    : std::clamp((fresnel_dielectric(c, multi_.eta) - f0) / (1 - f0), 0.0, 1.0);
        const Color f = multi_.cspec0 * (1 - fh) + Color(fh);
        return (f.r + f.g + f.b) / 3;
    }
    if (kind_ == Kind::MultiGlass && glass_.fresnel) {
        // The same for the glass, with the index ratio of wo's side.
        const double eta = wo.z < 0 ? 1 / glass_.eta : glass_.eta;
        const Color f = fresnel_tint(glass_.cspec0, eta, c);
        return (f.r + f.g + f.b) / 3;
    }
    return 1;
}

Color Lobe::eval(const Vec3& wo, const Vec3& wi, double* pdf) const {
    *pdf = 0;
    if (delta_ || wo.z == 0) return {};
    // Evaluated with the viewer above the surface (the frame flipped to wo's side).
    const double s = wo.z < 0 ? -1.0 : 1.0;
    const Vec3 o(wo.x, wo.y, wo.z * s), i(wi.x, wi.y, wi.z * s);
    if (kind_ == Kind::Translucent) {
        if (i.z >= 0) return {};
        *pdf = -i.z * kInvPi;
        return Color(*pdf);
    }
    if (kind_ == Kind::MultiGlass) {
        MultiGlass g = glass_;
        if (wo.z < 0) g.eta = 1 / g.eta;
        return multi_glass_eval(g, o, i, seed_of({o.x, o.y, i.x, i.y, i.z}), pdf);
    }
    if (kind_ == Kind::Refraction) {
        if (i.z >= 0) return {};
        const double etap = wo.z > 0 ? eta_ : 1 / eta_;
        const double f = microfacet_refraction(m_, etap, o, i, pdf);
        return Color(f * -i.z);
    }
    if (i.z <= 0) return {};
    switch (kind_) {
        case Kind::OrenNayar: {
            const double nl = i.z, nv = std::max(o.z, 0.0);
            double t = dot(i, o) - nl * nv;
            if (t > 0) t /= std::max(nl, nv) + 1e-300;
            *pdf = i.z * kInvPi;
            return Color(nl * (a_ + b_ * t));
        }
        case Kind::DiffuseToon: {
            const double cone = std::min(a_ + b_, kPi / 2);
            const double angle = std::acos(std::min(i.z, 1.0));
            if (angle >= cone) return {};
            *pdf = cone_pdf(cone);
            return Color(*pdf * toon_intensity(a_, b_, angle));
        }
        case Kind::GlossyToon: {
            const double cone = std::min(a_ + b_, kPi / 2);
            const Vec3 r(-o.x, -o.y, o.z);
            const double angle = std::acos(std::clamp(dot(r, i), 0.0, 1.0));
            if (angle >= cone) return {};
            *pdf = cone_pdf(cone);
            return Color(*pdf * toon_intensity(a_, b_, angle));
        }
        case Kind::Velvet: {
            *pdf = 0.5 * kInvPi;
            const Vec3 h = normalize(i + o);
            const double cos_nh = h.z, cos_ho = std::fabs(dot(o, h));
            if (!(std::fabs(cos_nh) < 1 - 1e-5 && cos_ho > 1e-5)) return {};
            const double r = std::max(cos_nh / cos_ho, 1e-5);
            const double g = std::min(1.0, std::min(2 * r * o.z, 2 * r * i.z));
            const double sin2 = 1 - cos_nh * cos_nh;
            const double d = std::exp(-cos_nh * cos_nh / sin2 * a_) * a_ * kInvPi / (sin2 * sin2);
            return Color(0.25 * d * g / o.z);
        }
        case Kind::SubsurfaceExit:
            *pdf = i.z * kInvPi;
            return Color(*pdf * (1 - 0.5 * schlick_weight(i.z)));
        case Kind::BurleyLambert:
            *pdf = i.z * kInvPi;
            return Color(*pdf * (1 - 0.5 * schlick_weight(std::max(o.z, 0.0))) *
                         (1 - 0.5 * schlick_weight(i.z)));
        case Kind::RetroReflection: {
            // Burley's retro-reflection: R (FL + FV + FL FV (R - 1)), R = roughness
            // (1 + cos(wi, wo)) = 2 roughness cos^2 of the half angle.
            *pdf = i.z * kInvPi;
            const double fl = schlick_weight(i.z), fv = schlick_weight(std::max(o.z, 0.0));
            const double rr = a_ * (dot(i, o) + 1);
            return Color(*pdf * rr * (fl + fv + fl * fv * (rr - 1)));
        }
        case Kind::Sheen: {
            *pdf = i.z * kInvPi;
            const Vec3 h = normalize(i + o);
            return Color(schlick_weight(dot(i, h)) * i.z);
        }
        case Kind::Clearcoat: {
            const double f = microfacet_reflection(m_, o, i, pdf);
            const Vec3 h = normalize(i + o);
            return Color(0.25 * a_ * fresnel_dielectric(dot(i, h), 1.5) * f * i.z);
        }
        case Kind::Reflection: return Color(microfacet_reflection(m_, o, i, pdf) * i.z);
        case Kind::MultiGGX: return multi_ggx_eval(multi_, o, i, seed_of({o.x, o.y, i.x, i.y}), pdf);
        case Kind::AshikhminShirley: {
            const double n_dot_o = std::max(o.z, 1e-6), n_dot_i = std::max(i.z, 1e-6);
            const Vec3 h = normalize(i + o);
            const double h_dot_o = std::max(std::fabs(dot(h, o)), 1e-6);
            const double h_dot_n = std::max(h.z, 1e-6);
            const double pump = 1 / std::max(1e-6, h_dot_o * std::max(n_dot_i, n_dot_o));
            double lobe, norm;
            if (a_ == b_) {
                lobe = std::pow(h_dot_n, a_);
                norm = (a_ + 1) / (8 * kPi);
            } else {
                const double e = h_dot_n < 1
                                     ? (a_ * h.x * h.x + b_ * h.y * h.y) / (1 - h_dot_n * h_dot_n)
                                     : 0.0;
                lobe = std::pow(h_dot_n, e);
                norm = std::sqrt((a_ + 1) * (b_ + 1)) / (8 * kPi);
            }
            *pdf = norm * lobe / h_dot_o;
            return Color(n_dot_i * norm * lobe * pump);
        }
        default: return {};
    }
}

bool Lobe::sample(const Vec3& wo, double u1, double u2, BsdfSample* out) const {
    if (wo.z == 0) return false;
    const double s = wo.z < 0 ? -1.0 : 1.0;
    const Vec3 o(wo.x, wo.y, wo.z * s);
    out->roughness2 = kind_ == Kind::Refraction
                          ? (delta_ || std::fabs(eta_ - 1) < 1e-6 ? 0.0 : m_.alpha_x * m_.alpha_y)
                      : kind_ == Kind::MultiGlass ? (delta_ ? 0.0 : glass_.alpha * glass_.alpha)
                                                  : kInfinity;
    // Cycles' LABEL_DIFFUSE lobes.
    out->diffuse = diffuse() || kind_ == Kind::Velvet;
    auto finish = [&](const Vec3& i, bool is_delta, const Color& delta_weight) {
        out->wi = Vec3(i.x, i.y, i.z * s);
        out->delta = is_delta;
        if (is_delta) {
            out->pdf = 1;
            out->weight = delta_weight;
            return true;
        }
        const Color f = eval(wo, out->wi, &out->pdf);
        if (!(out->pdf > 0)) return false;
        out->weight = f * (1 / out->pdf);
        return true;
    };
    Vec3 i;
    switch (kind_) {
        case Kind::OrenNayar:
        case Kind::SubsurfaceExit:
        case Kind::RetroReflection:
        case Kind::BurleyLambert:
        case Kind::Sheen: i = cosine_hemisphere(u1, u2); break;
        case Kind::Translucent: {
            const Vec3 c = cosine_hemisphere(u1, u2);
            i = Vec3(c.x, c.y, -c.z);
            break;
        }
        case Kind::Velvet: {
            const double z = u1, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u2;
            i = Vec3(r * std::cos(phi), r * std::sin(phi), z);
            break;
        }
        case Kind::DiffuseToon:
        case Kind::GlossyToon: {
            const double cone = std::min(a_ + b_, kPi / 2);
            if (!(cone > 0)) return false;
            const Vec3 axis = kind_ == Kind::DiffuseToon ? Vec3(0, 0, 1) : Vec3(-o.x, -o.y, o.z);
            i = uniform_cone(axis, cone, u1, u2);
            if (i.z <= 0) return false;
            // Cycles 3.4 weighs a sampled direction by the intensity at cone * u1, not at the
            // direction's own angle (u1 runs in cos from the cone's rim), so BSDF-sampled light
            // differs from what eval() says: kept, so that Toon looks as it does in Cycles.
            out->wi = Vec3(i.x, i.y, i.z * s);
            out->delta = false;
            out->pdf = cone_pdf(cone);
            out->weight = Color(toon_intensity(a_, b_, cone * u1));
            return true;
        }
        case Kind::Clearcoat:
        case Kind::Reflection: {
            if (delta_) return finish(Vec3(-o.x, -o.y, o.z), true, Color(1, 1, 1));
            i = reflect(o, m_.sample_normal(o, u1, u2));
            break;
        }
        case Kind::MultiGGX: {
            // Cycles' singular case: a mirror of weight 1, Fresnel or not.
            if (delta_) return finish(Vec3(-o.x, -o.y, o.z), true, Color(1, 1, 1));
            Color weight;
            double pdf;
            if (!multi_ggx_sample(multi_, o, seed_of({u1, u2, o.x, o.y}), &i, &weight, &pdf))
                return false;
            out->wi = Vec3(i.x, i.y, i.z * s);
            out->delta = false;
            out->pdf = pdf;
            out->weight = weight;
            return true;
        }
        case Kind::MultiGlass: {
            MultiGlass g = glass_;
            if (wo.z < 0) g.eta = 1 / g.eta;
            if (delta_) {
                // Cycles' singular case: a smooth interface, mirror or refraction by the
                // Fresnel term, of weight 1.
                const double f = fresnel_dielectric(o.z, g.eta);
                if (u1 < f || !refract(o, Vec3(0, 0, 1), g.eta, &i)) {
                    if (!finish(Vec3(-o.x, -o.y, o.z), true, Color(1, 1, 1))) return false;
                    out->pdf = f;
                    return true;
                }
                if (!finish(i, true, Color(1, 1, 1))) return false;
                out->pdf = 1 - f;
                return true;
            }
            Color weight;
            double pdf;
            if (!multi_glass_sample(g, o, seed_of({u1, u2, o.x, o.y}), &i, &weight, &pdf))
                return false;
            out->wi = Vec3(i.x, i.y, i.z * s);
            out->delta = false;
            out->pdf = pdf;
            out->weight = weight;
            return true;
        }
        case Kind::AshikhminShirley: {
            if (delta_) return finish(Vec3(-o.x, -o.y, o.z), true, Color(1, 1, 1));
            double phi, cos_t;
            if (a_ == b_) {
                phi = 2 * kPi * u1;
                cos_t = std::pow(u2, 1 / (a_ + 1));
            } else {
                // The first quadrant's azimuth mirrored into the four (Ashikhmin & Shirley 2000).
                auto quadrant = [&](double u) {
                    return std::atan(std::sqrt((a_ + 1) / (b_ + 1)) * std::tan(kPi / 2 * u));
                };
                if (u1 < 0.25) phi = quadrant(4 * u1);
                else if (u1 < 0.5) phi = kPi - quadrant(4 * (0.5 - u1));
                else if (u1 < 0.75) phi = kPi + quadrant(4 * (u1 - 0.5));
                else phi = 2 * kPi - quadrant(4 * (1 - u1));
                const double c = std::cos(phi), sn = std::sin(phi);
                cos_t = std::pow(u2, 1 / (a_ * c * c + b_ * sn * sn + 1));
            }
            const double sin_t = std::sqrt(std::max(0.0, 1 - cos_t * cos_t));
            const Vec3 h(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t);
            i = reflect(o, h);
            break;
        }
        case Kind::Refraction: {
            const double etap = wo.z > 0 ? eta_ : 1 / eta_;
            if (std::fabs(eta_ - 1) < 1e-6) return finish(-o, true, Color(1, 1, 1));
            const Vec3 wm = delta_ ? Vec3(0, 0, 1) : m_.sample_normal(o, u1, u2);
            if (dot(o, wm) <= 0) return false;
            if (!refract(o, wm, etap, &i) || i.z >= 0) return false;
            if (delta_) return finish(i, true, Color(1, 1, 1));
            break;
        }
    }
    if (kind_ == Kind::Translucent || kind_ == Kind::Refraction ? i.z >= 0 : i.z <= 0)
        return false;
    return finish(i, false, Color());
}

}  // namespace glint::render
