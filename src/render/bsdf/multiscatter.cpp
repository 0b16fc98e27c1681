#include "render/bsdf/multiscatter.h"

#include <algorithm>
#include <cmath>

#include "render/bsdf/microfacet.h"

namespace glint::render {
namespace {

constexpr int kMaxOrder = 10;  // Cycles' walk length

// A small counter-based generator for the walk (splitmix64).
struct Walk {
    uint64_t state;
    double next() {
        uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z ^= z >> 31;
        return static_cast<double>(z >> 11) * 0x1.0p-53;
    }
};

double d_ggx(const Vec3& wm, double ax, double ay) {
    const double sx = wm.x / ax, sy = wm.y / ay;
    const double t = wm.z * wm.z + sx * sx + sy * sy;
    return 1 / std::max(kPi * t * t * ax * ay, 1e-7);
}

// Smith's lambda, negative for directions pointing down (the walk's convention).
double lambda(const Vec3& w, double ax, double ay) {
    if (w.z > 0.9999) return 0;
    if (w.z < -0.9999) return -0.9999;
    const double inv_z2 = 1 / std::max(w.z * w.z, 1e-7);
    const double a2 = (w.x * ax) * (w.x * ax) + (w.y * ay) * (w.y * ay);
    double v = std::sqrt(1 + a2 * inv_z2);
    if (w.z <= 0) v = -v;
    return 0.5 * (v - 1);
}

// The uniform height distribution on [-1, 1]: its CDF and inverse.
double c1(double h) { return std::clamp(0.5 * (h + 1), 0.0, 1.0); }
double inv_c1(double c) { return 2 * std::clamp(c, 0.0, 1.0) - 1; }

double g1(const Vec3& w, double c, double lam) {
    if (w.z > 0.9999) return 1;
    if (w.z < 1e-5) return 0;
    return std::pow(c, lam);
}

// The next height along direction w from the current one; false when the ray leaves.
bool sample_height(const Vec3& w, double* h, double* c, double* g, double* lam, double u) {
    if (w.z > 0.9999) return false;
    if (w.z < -0.9999) {
        *c *= u;
        *h = inv_c1(*c);
        *g = g1(w, *c, *lam);
    } else if (std::fabs(w.z) >= 1e-4) {
        if (u > 1 - *g) return false;
        *c = *lam >= 0 ? 1.0 : *c * std::pow(1 - u, -1 / *lam);
        *h = inv_c1(*c);
        *g = g1(w, *c, *lam);
    }
    return true;
}

// Slopes of the unit-roughness distribution's visible normals (Heitz's supplemental code).
void sample_p22(double cos_i, double ux, double uy, double* sx, double* sy) {
    if (cos_i > 0.9999 || std::fabs(cos_i) < 1e-6) {
        const double r = std::sqrt(ux / std::max(1 - ux, 1e-7)), phi = 2 * kPi * uy;
        *sx = r * std::cos(phi);
        *sy = r * std::sin(phi);
        return;
    }
    const double sin_i = std::sqrt(std::max(0.0, 1 - cos_i * cos_i));
    const double tan_i = sin_i / cos_i;
    const double proj = 0.5 * (cos_i + 1);
    *sx = *sy = 0;
    if (proj < 1e-4) return;
    const double a = 2 * ux * proj / cos_i - 1;
    double tmp = a * a - 1;
    if (std::fabs(tmp) < 1e-7) return;
    tmp = 1 / tmp;
    const double d = std::sqrt(std::max(0.0, tan_i * tan_i * tmp * tmp - (a * a - tan_i * tan_i) * tmp));
    const double x2 = tan_i * tmp + d;
    *sx = (a < 0 || x2 > 1 / tan_i) ? tan_i * tmp - d : x2;
    const double u2 = uy >= 0.5 ? 2 * (uy - 0.5) : 2 * (0.5 - uy);
    const double z = (u2 * (u2 * (u2 * 0.27385 - 0.73369) + 0.46341)) /
                     (u2 * (u2 * (u2 * 0.093073 + 0.309420) - 1) + 0.597999);
    *sy = (uy >= 0.5 ? 1 : -1) * z * std::sqrt(1 + *sx * *sx);
}

Vec3 sample_vndf(const Vec3& w, double ax, double ay, double ux, double uy) {
    const Vec3 w11 = normalize(Vec3(ax * w.x, ay * w.y, w.z));
    double s11x, s11y;
    sample_p22(w11.z, ux, uy, &s11x, &s11y);
    const double r = std::sqrt(w11.x * w11.x + w11.y * w11.y);
    const double c = r > 0 ? w11.x / r : 1, s = r > 0 ? w11.y / r : 0;
    const double slope_x = ax * (c * s11x - s * s11y);
    const double slope_y = ay * (s * s11x + c * s11y);
    return normalize(Vec3(-slope_x, -slope_y, 1));
}

// Scattering from the walk's direction w towards wo off a microfacet: the phase function.
double phase(const Vec3& w, double lam, const Vec3& wo, double ax, double ay) {
    if (w.z > 0.9999) return 0;
    const Vec3 wh = normalize(wo - w);
    if (wh.z < 0) return 0;
    const double area = w.z < -0.9999 ? 1.0 : lam * w.z;
    const double dw = dot(-w, wh);
    if (dw < 0) return 0;
    return std::max(0.0, dw) * 0.25 / std::max(area * dw, 1e-7) * d_ggx(wh, ax, ay);
}

Color fresnel_color(const MultiGgx& m, const Vec3& w, const Vec3& h) {
    return fresnel_tint(m.cspec0, m.eta, dot(w, h));
}

double approx_pdf(const MultiGgx& m, const Vec3& wo, const Vec3& wi) {
    const double d = d_ggx(normalize(wo + wi), m.alpha_x, m.alpha_y);
    const double single = 0.25 * d / std::max((1 + lambda(wo, m.alpha_x, m.alpha_y)) * wo.z, 1e-7);
    const double albedo = multi_ggx_single_albedo(std::sqrt(m.alpha_x * m.alpha_y));
    return albedo * single + (1 - albedo) * wi.z / kPi;
}

// ---- glass

// Cycles' isotropic GGX D (D_ggx), as its glass walk uses it.
double d_ggx_iso(const Vec3& wm, double alpha) {
    const double z2 = wm.z * wm.z, a2 = alpha * alpha;
    const double t = (1 - z2) + a2 * z2;
    return a2 / std::max(kPi * t * t, 1e-7);
}

// log Gamma(x) for x >= 0.5 (Lanczos, g = 7): the transmission's height-correlated masking
// needs the Beta function of arguments that grow without bound at grazing angles. (std::lgamma
// writes a global sign in glibc.)
double log_gamma(double x) {
    static constexpr double kC[9] = {0.99999999999980993,  676.5203681218851,
                                     -1259.1392167224028,  771.32342877765313,
                                     -176.61502916214059,  12.507343278686905,
                                     -0.13857109526572012, 9.9843695780195716e-6,
                                     1.5056327351493116e-7};
    x -= 1;
    double a = kC[0];
    for (int i = 1; i < 9; ++i) a += kC[i] / (x + i);
    const double t = x + 7.5;
    return 0.5 * std::log(2 * kPi) + (x + 0.5) * std::log(t) - t + std::log(a);
}

double beta_fn(double x, double y) {
    return std::exp(log_gamma(x) + log_gamma(y) - log_gamma(x + y));
}

// The glass phase function: light along w (pointing into the microsurface, lambda its Smith
// lambda) scattered towards wo by a microfacet, reflected when wo_outside, else refracted
// (wo then below). Each includes its share of the microfacet's Fresnel term.
double phase_glass(const Vec3& w, double lam, const Vec3& wo, bool wo_outside, double alpha,
                   double eta) {
    if (w.z > 0.9999) return 0;
    const double area = std::max(w.z < -0.9999 ? 1.0 : lam * w.z, 1e-7);
    if (wo_outside) {
        const Vec3 wh = normalize(wo - w);
        if (wh.z < 0) return 0;
        const double dw = dot(-w, wh);
        if (!(dw > 0)) return 0;
        return fresnel_cos(dw, eta) * d_ggx_iso(wh, alpha) * 0.25 / area;
    }
    Vec3 wh = normalize(wo * eta - w);
    if (wh.z < 0) wh = -wh;
    const double dw = dot(-w, wh), dwo = dot(wo, wh);
    if (dw < 0) return 0;
    const double t = dw + eta * dwo;
    if (!(t * t > 1e-14)) return 0;
    return (1 - fresnel_cos(dw, eta)) * dw * std::max(0.0, -dwo) * d_ggx_iso(wh, alpha) /
           (area * t * t);
}

// A scattering off the microfacet wm from wi (pointing away from it): reflected with the
// probability of the Fresnel term, else refracted; *outside says which.
Vec3 sample_phase_glass(const Vec3& wi, double eta, const Vec3& wm, double u, bool* outside) {
    const double cos_i = dot(wi, wm);
    if (u < fresnel_cos(cos_i, eta)) {
        *outside = true;
        return wm * (2 * cos_i) - wi;
    }
    *outside = false;
    const double inv = 1 / eta;
    const double cos_t = -std::sqrt(std::max(0.0, 1 - (1 - cos_i * cos_i) * inv * inv));
    return normalize(wm * (cos_i * inv + cos_t) - wi * inv);
}

// Cycles' fit of the single-scattering transmission albedo (mf_ggx_transmission_albedo).
double transmission_albedo(double a, double ior) {
    if (ior < 1) ior = 1 / ior;
    a = std::clamp(a, 0.0, 1.0);
    ior = std::clamp(ior, 1.0, 3.0);
    const double i1 = 0.0476898 * std::exp(-0.978352 * (ior - 0.65657) * (ior - 0.65657)) -
                      0.033756 * ior + 0.993261;
    const double r1 = (((0.116991 * a - 0.270369) * a + 0.0501366) * a - 0.00411511) * a + 1.00008;
    const double i2 = (((-2.08704 * ior + 26.3298) * ior - 127.906) * ior + 292.958) * ior -
                      287.946 + 199.803 / (ior * ior) - 101.668 / (ior * ior * ior);
    const double r2 =
        ((((5.3725 * a - 24.9307) * a + 22.7437) * a - 3.40751) * a + 0.0986325) * a + 0.00493504;
    return std::clamp(1 + i2 * r2 * 0.0019127 - (1 - i1) * (1 - r1) * 9.3205, 0.0, 1.0);
}

// Cycles' approximate pdf (mf_glass_pdf), wo the viewer's side, wi either side.
double glass_pdf(const MultiGlass& m, const Vec3& wo, const Vec3& wi) {
    const bool reflective = wo.z * wi.z > 0;
    const Vec3 sum = wo + (reflective ? wi : wi * m.eta);
    const double len = length(sum);
    if (!(len > 1e-12)) return 0;
    Vec3 wh = sum * (1 / len);
    if (wh.z < 0) wh = -wh;
    const Vec3 o = wo.z < 0 ? -wo : wo;
    const double lam = lambda(o, m.alpha, m.alpha);
    const double d = d_ggx_iso(wh, m.alpha);
    const double f = fresnel_cos(dot(o, wh), m.eta);
    const double cosine = std::fabs(wi.z) / kPi;
    if (reflective) {
        const double single = 0.25 * d / std::max((1 + lam) * o.z, 1e-7);
        const double albedo = multi_ggx_single_albedo(m.alpha);
        return f * (albedo * single + (1 - albedo) * cosine);
    }
    const double single = std::fabs(dot(o, wh) * dot(wi, wh) * d * m.eta * m.eta /
                                    std::max((1 + lam) * o.z * len * len, 1e-7));
    const double albedo = transmission_albedo(m.alpha, m.eta);
    return (1 - f) * (albedo * single + (1 - albedo) * cosine);
}

}  // namespace

double fresnel_cos(double cos_i, double eta) { return fresnel_dielectric(std::fabs(cos_i), eta); }

Color fresnel_tint(const Color& cspec0, double eta, double cos_h) {
    const double f0 = fresnel_dielectric(1.0, eta);
    if (f0 >= 1) return Color(1, 1, 1);
    const double fh =
        std::clamp((fresnel_dielectric(std::fabs(cos_h), eta) - f0) / (1 - f0), 0.0, 1.0);
    return cspec0 * (1 - fh) + Color(fh);
}

double multi_ggx_single_albedo(double r) {
    double a = 0.806495 * std::exp(-1.98712 * r * r) + 0.199531;
    a -= ((((((1.76741 * r - 8.43891) * r + 15.784) * r - 14.398) * r + 6.45221) * r - 1.19722) * r +
          0.027803) * r + 0.00568739;
    return std::clamp(a, 0.0, 1.0);
}

Color multi_ggx_eval(const MultiGgx& m, const Vec3& wo_in, const Vec3& wi_in, uint64_t seed,
                     double* pdf) {
    *pdf = 0;
    if (!(wo_in.z > 0 && wi_in.z > 0)) return {};
    *pdf = approx_pdf(m, wo_in, wi_in);
    if (!(*pdf > 0)) {
        *pdf = 0;
        return {};
    }
    // The walk starts from the shallower direction (less noise; the BSDF is reciprocal).
    Vec3 wi = wo_in, wo = wi_in;
    const bool swapped = wo.z < wi.z;
    if (swapped) std::swap(wi, wo);
    if (wi.z < 1e-5 || wo.z < 1e-5) return {};
    const double ax = m.alpha_x, ay = m.alpha_y;
    double lam_r = lambda(-wi, ax, ay);
    const double shadow_lam = lambda(wo, ax, ay);
    // Single scattering, analytic, with height-correlated masking.
    const Vec3 wh = normalize(wi + wo);
    const double g2 = 1 / (1 - (lam_r + 1) + shadow_lam);
    Color eval(g2 * 0.25 / wi.z * d_ggx(wh, ax, ay));
    Color throughput(1, 1, 1);
    if (m.fresnel) {
        throughput = fresnel_color(m, wi, wh);
        eval *= throughput;
    }
    Walk rng{seed};
    Vec3 wr = -wi;
    double hr = 1, c_r = 1, g_r = 0;
    for (int order = 0; order < kMaxOrder; ++order) {
        if (!sample_height(wr, &hr, &c_r, &g_r, &lam_r, rng.next())) break;
        const double uy = rng.next(), ux = rng.next();
        const Vec3 wm = sample_vndf(-wr, ax, ay, ux, uy);
        // (The tint enters twice here, as in Cycles 3.4's mf_eval.)
        if (order > 0)
            eval += throughput * phase(wr, lam_r, wo, ax, ay) * throughput *
                    g1(wo, c1(hr), shadow_lam);
        if (order + 1 < kMaxOrder) {
            if (m.fresnel && order > 0) throughput *= fresnel_color(m, -wr, wm);
            wr = reflect(-wr, wm);
            lam_r = lambda(wr, ax, ay);
            if (!m.fresnel) throughput *= m.color;
            c_r = c1(hr);
            g_r = g1(wr, c_r, lam_r);
        }
    }
    if (swapped) eval *= std::fabs(wi.z / wo.z);
    return eval;
}

bool multi_ggx_sample(const MultiGgx& m, const Vec3& wo, uint64_t seed, Vec3* wi, Color* weight,
                      double* pdf) {
    if (!(wo.z > 0)) return false;
    const double ax = m.alpha_x, ay = m.alpha_y;
    Walk rng{seed};
    Color throughput(1, 1, 1);
    Vec3 wr = -wo;
    double lam_r = lambda(wr, ax, ay);
    double hr = 1, c_r = 1, g_r = 0;
    for (int order = 0; order < kMaxOrder; ++order) {
        if (!sample_height(wr, &hr, &c_r, &g_r, &lam_r, rng.next())) {
            // Left the surface.
            if (!(wr.z > 0)) return false;
            *wi = wr;
            *pdf = approx_pdf(m, wo, wr);
            if (!(*pdf > 0)) return false;
            *weight = throughput;
            return true;
        }
        const double uy = rng.next(), ux = rng.next();
        const Vec3 wm = sample_vndf(-wr, ax, ay, ux, uy);
        // The first scattering's colour is in the closure's weight.
        if (!m.fresnel && order > 0) throughput *= m.color;
        if (m.fresnel) {
            const Color t = fresnel_color(m, -wr, wm);
            throughput = order == 0 ? t : throughput * t;
        }
        wr = reflect(-wr, wm);
        lam_r = lambda(wr, ax, ay);
        g_r = g1(wr, c_r, lam_r);
    }
    return false;
}

Color multi_glass_eval(const MultiGlass& m, const Vec3& wo_in, const Vec3& wi_in, uint64_t seed,
                       double* pdf) {
    *pdf = 0;
    if (!(wo_in.z > 0)) return {};
    const double p = glass_pdf(m, wo_in, wi_in);
    *pdf = std::isfinite(p) && p > 0 ? p : 0;
    // The light reflected (above) or transmitted (below).
    const bool up = wi_in.z >= 0;
    const bool tint = m.fresnel && up;
    const double alpha = m.alpha, eta = m.eta;
    // In the walk's terms wi is the viewer and wo the light. It starts from the shallower of
    // the two; for transmission both are mirrored through the surface, and eta is kept as it
    // was (as Cycles does).
    Vec3 wi = wo_in, wo = wi_in;
    bool swapped = false;
    if (wi.z * wo.z < 0) {
        if (-wo.z < wi.z) {
            swapped = true;
            const Vec3 t = -wo;
            wo = -wi;
            wi = t;
        }
    } else if (wo.z < wi.z) {
        swapped = true;
        std::swap(wi, wo);
    }
    if (wi.z < 1e-5 || (up && wo.z < 1e-5) || (!up && wo.z > -1e-5)) return {};
    const Vec3 wo_up = up ? wo : -wo;
    double lam_r = lambda(-wi, alpha, alpha);
    const double shadow_lam = lambda(wo_up, alpha, alpha);
    // Single scattering, analytic, with height-correlated masking and shadowing.
    Color eval(phase_glass(-wi, lam_r, wo, up, alpha, eta) *
               (up ? -lam_r / (shadow_lam - lam_r) : -lam_r * beta_fn(-lam_r, shadow_lam + 1)));
    Color throughput(1, 1, 1);
    if (tint) {
        throughput = fresnel_tint(m.cspec0, eta, dot(wi, normalize(wi + wo)));
        eval *= throughput;
    }
    Walk rng{seed};
    Vec3 wr = -wi;
    double hr = 1, c_r = 1, g_r = 0;
    bool outside = true;
    for (int order = 0; order < kMaxOrder; ++order) {
        if (!sample_height(wr, &hr, &c_r, &g_r, &lam_r, rng.next())) break;
        const double uy = rng.next(), ux = rng.next();
        const Vec3 wm = sample_vndf(-wr, alpha, alpha, ux, uy);
        // Scattering towards the light from here; with the Fresnel tint the first one
        // replaces the analytic term by this estimate, as Cycles 3.4's mf_eval does.
        if (order > 0 || tint) {
            const double ph = outside ? phase_glass(wr, lam_r, wo, up, alpha, eta)
                                      : phase_glass(wr, lam_r, -wo, !up, alpha, 1 / eta);
            const Color term =
                throughput * (ph * g1(wo_up, c1(outside == up ? hr : -hr), shadow_lam));
            eval = order == 0 ? term : eval + term;
        }
        if (order + 1 < kMaxOrder) {
            const Vec3 from = -wr;
            bool reflected;
            wr = sample_phase_glass(from, outside ? eta : 1 / eta, wm, rng.next(), &reflected);
            if (!reflected) {
                // Through the microsurface: the walk goes on, mirrored, on the other side.
                outside = !outside;
                wr = -wr;
                hr = -hr;
            }
            if (tint && !reflected) throughput *= m.color;
            else if (tint && order > 0) throughput *= fresnel_tint(m.cspec0, eta, dot(from, wm));
            lam_r = lambda(wr, alpha, alpha);
            if (!tint) throughput *= m.color;
            c_r = c1(hr);
            g_r = g1(wr, c_r, lam_r);
        }
    }
    if (swapped) eval *= std::fabs(wi.z / wo.z);
    if (!(std::isfinite(eval.r) && std::isfinite(eval.g) && std::isfinite(eval.b))) return {};
    return eval;
}

bool multi_glass_sample(const MultiGlass& m, const Vec3& wo, uint64_t seed, Vec3* wi,
                        Color* weight, double* pdf) {
    if (!(wo.z > 0)) return false;
    const double alpha = m.alpha, eta = m.eta;
    Walk rng{seed};
    Color throughput(1, 1, 1);
    Vec3 wr = -wo;
    double lam_r = lambda(wr, alpha, alpha);
    double hr = 1, c_r = 1, g_r = 0;
    bool outside = true;
    for (int order = 0; order < kMaxOrder; ++order) {
        if (!sample_height(wr, &hr, &c_r, &g_r, &lam_r, rng.next())) {
            // Left the microsurface, on the side it is on.
            *wi = outside ? wr : -wr;
            *pdf = glass_pdf(m, wo, *wi);
            if (!(std::isfinite(*pdf) && *pdf > 0)) return false;
            *weight = throughput;
            return true;
        }
        const double uy = rng.next(), ux = rng.next();
        const Vec3 wm = sample_vndf(-wr, alpha, alpha, ux, uy);
        // The first scattering's colour is in the closure's weight.
        if (!m.fresnel && order > 0) throughput *= m.color;
        const Vec3 from = -wr;
        bool reflected;
        wr = sample_phase_glass(from, outside ? eta : 1 / eta, wm, rng.next(), &reflected);
        if (!reflected) {
            hr = -hr;
            wr = -wr;
            outside = !outside;
        }
        if (m.fresnel) {
            if (!reflected) {
                throughput *= m.color;
            } else {
                const Color t = fresnel_tint(m.cspec0, eta, dot(from, wm));
                throughput = order == 0 ? t : throughput * t;
            }
        }
        // Cycles' mf_sample keeps the height's CDF value from before a crossing (unlike its
        // mf_eval, which recomputes it from the mirrored height); kept, to sample as it does.
        lam_r = lambda(wr, alpha, alpha);
        g_r = g1(wr, c_r, lam_r);
    }
    return false;
}

}  // namespace glint::render
