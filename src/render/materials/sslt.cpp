#include "render/materials/sslt.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/float.h"
#include "render/sampling/sampler.h"

namespace glint::render {

double sslt_transmittance(double cos_angle, double eta) {
    const double c = cos_angle;
    const double g2 = eta * eta + c * c - 1;
    if (!(g2 >= 0)) return 0;  // total internal reflection
    const double g = std::sqrt(g2);
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1) / (c * (g - c) + 1);
    const double f = 0.5 * a * a * (1 + b * b);
    if (!std::isfinite(f)) return 0;
    return 1 - std::clamp(f, 0.0, 1.0);
}

double fresnel_diffuse_reflectance(double eta) {
    // Not Jensen's polynomial (it fails for large and small eta): POV-Ray's stable fit.
    if (eta < 1) return eta * eta - std::pow(eta, 2.25);
    const double k = 1 - 1 / eta;
    return (k + 3 * std::pow(k, 4.5)) / 4;
}

double dipole_total_reflectance(double A, double alpha_prime) {
    const double root = std::sqrt(3 * (1 - alpha_prime));
    return alpha_prime / 2 * (1 + std::exp(-4.0 / 3.0 * A * root)) * std::exp(-root);
}

double reduced_albedo(double reflectance, double eta) {
    // R_d grows with the albedo from 0 to 1/2 (1 + e^0) = 1: bisection.
    const double r = std::clamp(reflectance, 0.0, 1.0);
    if (r <= 0) return 0;
    if (r >= 1) return 1;
    const double fdr = fresnel_diffuse_reflectance(eta);
    const double A = (1 + fdr) / (1 - fdr);
    double lo = 0, hi = 1;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (dipole_total_reflectance(A, mid) < r ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

double dipole_reflectance(double dist_sqr, double sigma_prime_s, double sigma_a, double eta) {
    const double sigma_prime_t = sigma_prime_s + sigma_a;
    if (!(sigma_prime_t > 0)) return 0;
    const double alpha_prime = sigma_prime_s / sigma_prime_t;
    const double fdr = fresnel_diffuse_reflectance(eta);
    const double A = (1 + fdr) / (1 - fdr);
    const double sigma_tr = std::sqrt(3 * sigma_a * sigma_prime_t);
    // The real source one mean free path below the surface, the virtual one mirrored above
    // the extrapolated boundary.
    const double z_r = 1 / sigma_prime_t;
    const double z_v = z_r * (1 + A * 4.0 / 3.0);
    const double d2_r = z_r * z_r + dist_sqr, d2_v = z_v * z_v + dist_sqr;
    const double d_r = std::sqrt(d2_r), d_v = std::sqrt(d2_v);
    const double real = z_r * (sigma_tr + 1 / d_r) * std::exp(-sigma_tr * d_r) / d2_r;
    const double virt = z_v * (sigma_tr + 1 / d_v) * std::exp(-sigma_tr * d_v) / d2_v;
    return alpha_prime / (4 * kPi) * (real + virt);
}

SsltCoefficients::SsltCoefficients(const Color& translucency, const Color& reflectance,
                                   double eta) {
    const double t[3] = {translucency.r, translucency.g, translucency.b};
    const double rd[3] = {reflectance.r, reflectance.g, reflectance.b};
    double s[3], st[3], sa[3];
    for (int c = 0; c < 3; ++c) {
        // (A translucency of 0 scatters infinitely: no light gets in; kept finite.)
        s[c] = t[c] > 0 ? 1 / t[c] : 1e30;
        const double alpha = reduced_albedo(rd[c], eta);
        st[c] = alpha > 0 ? s[c] / alpha : 1e30;
        sa[c] = std::max(0.0, st[c] - s[c]);
    }
    sigma_prime_s = Color(s[0], s[1], s[2]);
    sigma_prime_t = Color(st[0], st[1], st[2]);
    sigma_a = Color(sa[0], sa[1], sa[2]);
}


namespace {

// POV-Ray's greyscale weights (RGBColour::greyscale).
double grey(const Color& c) { return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b; }
double channel(const Color& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : c.b; }
double& channel(Color& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : c.b; }

uint32_t bits_hash(uint32_t h, double v) {
    uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    h = hash_u32(h ^ static_cast<uint32_t>(b));
    return hash_u32(h ^ static_cast<uint32_t>(b >> 32));
}

struct Random {
    uint32_t state;
    double operator()() {
        state = hash_u32(state + 0x9e3779b9U);
        return static_cast<double>(state) * (1.0 / 4294967296.0);
    }
};

// POV-Ray's SSLTComputeRefractedDirection: `v` through a surface of normal `n` (either side)
// into a medium of relative index 1 / eta; false on total internal reflection.
bool refracted(const Vec3& v, const Vec3& n, double eta, Vec3* out) {
    double c = dot(v, n);
    Vec3 m = n;
    if (c > 0)
        m = -n;
    else
        c = -c;
    const double t = 1 + eta * eta * (c * c - 1);
    if (t < 0) return false;
    *out = normalize(v * eta + m * (eta * c - std::sqrt(t)));
    return true;
}

}  // namespace

Color subsurface_light(const SsltScene& scene, const SsltSettings& s, const Color& translucency,
                       const Color& reflectance, double eta, const Ray& ray, const Hit& out,
                       const Vec3& raw_n) {
    const int n_diffuse = s.samples_diffuse, n_single = s.samples_single;
    const double mm = s.mm_per_unit;
    const Vec3 v_out = -normalize(ray.dir);
    const SsltCoefficients k(translucency, reflectance, eta);
    // Lights seen from inside the surface: its normal must face them (else it is at fault),
    // and light along it gets nowhere.
    auto light = [&](size_t l, const Hit& at, Vec3* n, double* cos_in) {
        Vec3 dir;
        const Color lc = scene.light(l, at, &dir);
        if (lc.is_black()) return Color();
        *cos_in = dot(*n, dir);
        if (*cos_in < 0) {
            *n = -*n;
            *cos_in = -*cos_in;
        }
        return *cos_in < kPovEpsilon ? Color() : lc;
    };
    // Random numbers from the ray: the same image whatever the thread count.
    uint32_t seed = 0x51u;
    for (double v : {out.p.x, out.p.y, out.p.z, ray.dir.x, ray.dir.y, ray.dir.z})
        seed = bits_hash(seed, v);
    Random rnd{seed};
    Color total;

    // Diffuse: the dipole between points around a base point below the surface (one mean
    // free path of the channels' mean extinction down, or halfway through a thin object) and
    // this one, lit by the lights.
    const double free_path = 1 / (grey(k.sigma_prime_t) * mm);
    const Vec3 inwards = dot(raw_n, v_out) > 0 ? -raw_n : raw_n;
    Vec3 base = out.p + inwards * free_path;
    {
        Hit back;
        const Vec3 o = offset_ray_origin(out.p, out.p_error, out.ng, inwards);
        if (scene.intersect(o, inwards, 2 * free_path, &back))
            base = back.object == out.object
                       ? out.p + inwards * (back.t / 2)
                       : out.p + inwards * std::min(free_path, back.t - kPovEpsilon);
    }
    const double cos_out = std::clamp(dot(v_out, raw_n), -1.0, 1.0);
    const double ft_out = sslt_transmittance(cos_out, eta);
    int used = 0;
    const double lattice_u = rnd(), lattice_v = rnd();
    for (int i = 0; i < n_diffuse; ++i) {
        // A stratified direction (a rotated Fibonacci lattice on the sphere).
        const double u = std::fmod((i + lattice_u) / n_diffuse, 1.0);
        const double w = std::fmod(i * 0.6180339887498949 + lattice_v, 1.0);
        const double z = 1 - 2 * u, r = std::sqrt(std::max(0.0, 1 - z * z));
        const Vec3 dir(r * std::cos(2 * kPi * w), r * std::sin(2 * kPi * w), z);
        Hit in;
        if (!scene.intersect(base, dir, kInfinity, &in)) continue;
        const Vec3 delta = in.p - base;
        const double dist = length(delta);
        if (!(dist > 0)) continue;
        const double cos_phi = std::max(0.01, std::fabs(dot(delta / dist, in.n)));
        // The sample's solid angle as an area on the surface.
        const double area = 4 * kPi * (dist * mm) * (dist * mm) / cos_phi;
        ++used;
        if (in.object != out.object) continue;
        const double dist_sqr = length_squared(in.p - out.p) * mm * mm;
        for (size_t l = 0; l < scene.light_count(); ++l) {
            Vec3 n = in.n;
            double cos_in = 0;
            const Color lc = light(l, in, &n, &cos_in);
            if (lc.is_black()) continue;
            const double ft = sslt_transmittance(cos_in, eta) * ft_out * area * cos_in;
            for (int c = 0; c < 3; ++c)
                channel(total, c) += channel(lc, c) * ft *
                                     dipole_reflectance(dist_sqr, channel(k.sigma_prime_s, c),
                                                        channel(k.sigma_a, c), eta);
        }
    }
    if (used > 0) total = total / used;

    // Along the refracted eye ray: single scattering towards each light, and what crosses
    // the object unscattered.
    Vec3 eye_in;
    if (!refracted(ray.dir, raw_n, 1 / eta, &eye_in)) return total;
    Hit exit;
    const bool found = scene.intersect(offset_ray_origin(out.p, out.p_error, out.ng, eye_in),
                                       eye_in, kInfinity, &exit);
    const double dist = found ? length(exit.p - out.p) * mm : kInfinity;
    const double cos_out_prime =
        std::sqrt(std::max(0.0, 1 - (1 - cos_out * cos_out) / (eta * eta)));
    for (int i = 0; i < n_single; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double st = channel(k.sigma_prime_t, c), ss = channel(k.sigma_prime_s, c);
            const double s_out = std::fabs(std::log(std::max(rnd(), 1e-300))) / st;
            if (s_out >= dist) continue;  // past the object: the unscattered term's
            const Vec3 bend = out.p + eye_in * (s_out / mm);
            for (size_t l = 0; l < scene.light_count(); ++l) {
                Vec3 towards;
                if (!scene.light_direction(l, bend, &towards)) continue;
                // Where light from the source would enter (refraction ignored).
                Hit xi;
                if (!scene.intersect(bend, towards, kInfinity, &xi) || xi.object != out.object)
                    continue;
                Vec3 n = xi.n;
                double cos_in = 0;
                const Color lc = light(l, xi, &n, &cos_in);
                if (lc.is_black()) continue;
                const double cin2 = 1 - (1 - cos_in * cos_in) / (eta * eta);
                if (!(cin2 > 0)) continue;
                const double cos_in_prime = std::sqrt(cin2);
                if (cos_in_prime <= kPovEpsilon) continue;
                const double s_in = length(bend - xi.p) * mm * cos_in / cos_in_prime;
                const double ft = sslt_transmittance(cos_in, eta) * ft_out;
                const double sigma_tc = st + std::fabs(cos_out_prime / cos_in_prime) * st;
                // The phase 1/4 (isotropic; POV-Ray's light already holds the 1/pi).
                const double factor =
                    ss * ft * 0.25 / sigma_tc * std::exp(-s_in * st) * std::exp(-s_out * st);
                channel(total, c) += channel(lc, c) * cos_in * std::min(factor, 1e300) / n_single;
            }
        }
    }

    // Unscattered: out through the far side, refracted twice (Fresnel left out, as POV-Ray).
    const Color att(std::exp(-k.sigma_prime_t.r * dist), std::exp(-k.sigma_prime_t.g * dist),
                    std::exp(-k.sigma_prime_t.b * dist));
    const double w = att.max();
    if (found && w > s.adc_bailout && exit.object == out.object) {
        Vec3 n = exit.n;
        if (dot(eye_in, n) > 0) n = -n;
        Vec3 eye_out;
        if (refracted(eye_in, n, eta, &eye_out)) {
            Ray r;
            r.dir = eye_out;
            r.origin = offset_ray_origin(exit.p, exit.p_error, exit.ng, eye_out);
            total += scene.trace(r, w) * att;
        }
    }
    return total;
}

}  // namespace glint::render
