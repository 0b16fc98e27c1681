#include "render/media/subsurface.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/float.h"
#include "render/bsdf/bsdf.h"

namespace glint::render {
namespace {

using Rgb = std::array<double, 3>;

Rgb rgb(const Color& c) { return {c.r, c.g, c.b}; }

double hg_density(double cos_theta, double g) {
    const double d = 1 + g * g - 2 * g * cos_theta;
    return (1 - g * g) / (4 * kPi * d * std::sqrt(d));
}

// A direction at `cos_theta` from the unit `axis`, turned by 2 pi u about it.
Vec3 around(const Vec3& axis, double cos_theta, double u) {
    const double sin_theta = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
    const double phi = 2 * kPi * u;
    return normalize(Frame::from_normal(axis).to_world(
        Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta)));
}

// Henyey-Greenstein about the direction of travel; the pdf of what it drew.
Vec3 hg_sample(const Vec3& d, double g, double u1, double u2, double* pdf) {
    double cos_theta;
    if (std::fabs(g) < 1e-3) {
        cos_theta = 1 - 2 * u1;
        *pdf = 1 / (4 * kPi);
    } else {
        const double k = (1 - g * g) / (1 - g + 2 * g * u1);
        cos_theta = std::clamp((1 + g * g - k * k) / (2 * g), -1.0, 1.0);
        *pdf = hg_density(cos_theta, g);
    }
    return around(d, cos_theta, u2);
}

// Dwivedi's guiding: directions at cos_theta from the axis with density
// 1 / ((v - cos) log((v + 1) / (v - 1))) per unit cos, v the diffusion length (d'Eon and
// Krivanek 2020, eq. 67, for its value from the albedo).
double diffusion_length(double alpha) {
    return 1 / std::sqrt(1 - std::pow(alpha, 2.44294 - 0.0215813 * alpha + 0.578637 / alpha));
}

// The per-channel density of a free flight of length t under extinction s: s e^{-s t}, or
// e^{-s t} for reaching the surface at t.
Rgb flight_pdf(const Rgb& s, double t, bool reached, Rgb* transmittance = nullptr) {
    Rgb p;
    for (int c = 0; c < 3; ++c) {
        const double tr = std::exp(-s[c] * t);
        if (transmittance) (*transmittance)[c] = tr;
        p[c] = reached ? tr : s[c] * tr;
    }
    return p;
}

}  // namespace

void subsurface_coefficients(double albedo, double d, double g, double* sigma_t,
                             double* alpha) {
    // The fits of the single-scattering albedo that gives the surface albedo, as polynomials
    // in g (Chiang et al. 2016; Wrenninge et al. 2017's anisotropic extension).
    const double g2 = g * g, g3 = g2 * g, g4 = g3 * g, g5 = g4 * g, g6 = g5 * g, g7 = g6 * g;
    const double A = 1.8260523782 - 1.28451056436 * g - 1.79904629312 * g2 +
                     9.19393289202 * g3 - 22.8215585862 * g4 + 32.0234874259 * g5 -
                     23.6264803333 * g6 + 7.21067002658 * g7;
    const double B = 4.98511194385 +
                     0.127355959438 * std::exp(31.1491581433 * g - 201.847017512 * g2 +
                                               841.576016723 * g3 - 2018.09288505 * g4 +
                                               2731.71560286 * g5 - 1935.41424244 * g6 +
                                               559.009054474 * g7);
    const double C = 1.09686102424 - 0.394704063468 * g + 1.05258115941 * g2 -
                     8.83963712726 * g3 + 28.8643230661 * g4 - 46.8802913581 * g5 +
                     38.5402837518 * g6 - 12.7181042538 * g7;
    const double D = 0.496310210422 + 0.360146581622 * g - 2.15139309747 * g2 +
                     17.8896899217 * g3 - 55.2984010333 * g4 + 82.065982243 * g5 -
                     58.5106008578 * g6 + 15.8478295021 * g7;
    const double E = 4.23190299701 +
                     0.00310603949088 * std::exp(76.7316253952 * g - 594.356773233 * g2 +
                                                 2448.8834203 * g3 - 5576.68528998 * g4 +
                                                 7116.60171912 * g5 - 4763.54467887 * g6 +
                                                 1303.5318055 * g7);
    const double F = 2.40602999408 - 2.51814844609 * g + 9.18494908356 * g2 -
                     79.2191708682 * g3 + 259.082868209 * g4 - 403.613804597 * g5 +
                     302.85712436 * g6 - 87.4370473567 * g7;
    const double blend = std::pow(albedo, 0.25);
    const double a = (1 - blend) * A * std::pow(std::atan(B * albedo), C) +
                     blend * D * std::pow(std::atan(E * albedo), F);
    *alpha = std::clamp(a, 0.0, 0.999999);
    *sigma_t = 1 / std::max(d, 1e-16) / (1 - g);
}

bool subsurface_walk(const Geometry& geometry, const Bssrdf& b, const Hit& entry,
                     const Vec3& wo, const std::function<double()>& random, Color* beta,
                     Hit* exit, Vec3* exit_dir, uint64_t* rays) {
    const Vec3 n = b.n;
    const Vec3 ng = dot(entry.ng, wo) >= 0 ? entry.ng : -entry.ng;
    const Vec3 p0 = entry.p;
    // Into the surface by a cosine-weighted direction about -n.
    Vec3 dir;
    {
        const double u1 = random(), u2 = random();
        dir = around(-n, std::sqrt(std::max(0.0, 1 - u1)), u2);
    }
    if (dot(-ng, dir) <= 0) return false;

    const double g = b.anisotropy;
    const Rgb albedo = rgb(b.albedo), radius = rgb(b.radius);
    Rgb sigma_t, alpha, throughput = rgb(*beta);
    for (int c = 0; c < 3; ++c) {
        subsurface_coefficients(albedo[c], radius[c], g, &sigma_t[c], &alpha[c]);
        // The albedo comes back through the scatterings.
        throughput[c] = albedo[c] != 0 ? throughput[c] / albedo[c] : 0;
        // Very low albedos would give a diffusion length of 1 (an infinite guide): raise
        // alpha to 0.2 and take the difference from the throughput.
        if (alpha[c] < 0.2) {
            throughput[c] *= alpha[c] / 0.2;
            alpha[c] = 0.2;
        }
    }
    Rgb sigma_s;
    for (int c = 0; c < 3; ++c) sigma_s[c] = sigma_t[c] * alpha[c];
    // The guide for the highest albedo: too low a one gives fireflies, too high only noise.
    const double dl = diffusion_length(std::max({alpha[0], alpha[1], alpha[2]}));
    if (!(dl > 1) || std::isinf(dl)) return false;
    const double phase_log = std::log((dl + 1) / (dl - 1));
    const double guided_fraction0 = 1 - std::max(0.5, std::pow(std::fabs(g), 0.125));
    // Past the first bounces an isotropic medium of reduced scattering stands in for the
    // anisotropic one (the similarity relation).
    Rgb sigma_s_iso, sigma_t_iso;
    for (int c = 0; c < 3; ++c) {
        sigma_s_iso[c] = sigma_s[c] * (1 - g);
        sigma_t_iso[c] = sigma_t[c] - sigma_s[c] + sigma_s_iso[c];
    }
    const double min_sigma_t = std::min({sigma_t[0], sigma_t[1], sigma_t[2]});

    Ray ray;
    ray.origin = offset_ray_origin(entry.p, entry.p_error, entry.ng, dir);
    ray.dir = dir;
    ray.time = 0.5;
    bool have_opposite = false;
    double opposite_distance = 0;
    Hit h;
    for (int bounce = 0; bounce < kSubsurfaceMaxBounces; ++bounce) {
        const bool iso = bounce > 9;
        const double gb = iso ? 0.0 : g;
        const double guided_fraction = iso ? 0.75 : guided_fraction0;
        const Rgb& st = iso ? sigma_t_iso : sigma_t;
        const Rgb& ss = iso ? sigma_s_iso : sigma_s;

        // The channel by throughput x albedo.
        Rgb channel_pdf;
        int channel = 2;
        {
            double sum = 0;
            for (int c = 0; c < 3; ++c) sum += channel_pdf[c] = std::fabs(throughput[c] * alpha[c]);
            for (int c = 0; c < 3; ++c) channel_pdf[c] = sum > 0 ? channel_pdf[c] / sum : 1.0 / 3;
            const double u = random();
            double acc = 0;
            for (int c = 0; c < 3; ++c) {
                acc += channel_pdf[c];
                if (u < acc) {
                    channel = c;
                    break;
                }
            }
        }
        double sample_st = st[static_cast<size_t>(channel)];
        const double u_dist = random();

        double backward_fraction = 0, forward_factor = 0, backward_factor = 0;
        double forward_stretch = 1, backward_stretch = 1;
        if (bounce > 0) {
            const bool guided = random() < guided_fraction;
            bool backward = false;
            if (have_opposite) {
                // Towards the far side more often the nearer the walk is to it.
                const double x = std::clamp(dot(ray.origin - p0, -n), 0.0, opposite_distance);
                backward_fraction = 1 / (1 + std::exp((opposite_distance - 2 * x) / dl));
                backward = random() < backward_fraction;
            }
            const double u1 = random(), u2 = random();
            double cos_theta, hg_pdf;
            Vec3 next;
            if (guided) {
                cos_theta = dl - (dl + 1) * std::exp(-u1 * phase_log);
                if (backward) cos_theta = -cos_theta;
                next = around(n, cos_theta, u2);
                hg_pdf = std::fabs(gb) < 1e-3 ? 1 / (4 * kPi) : hg_density(dot(ray.dir, next), gb);
            } else {
                next = hg_sample(ray.dir, gb, u1, u2, &hg_pdf);
                cos_theta = dot(next, n);
            }
            ray.dir = next;
            // The guide's density over the phase function's (which cancels in the estimate).
            forward_factor = 1 / (2 * kPi * (dl - cos_theta) * phase_log * hg_pdf);
            backward_factor = 1 / (2 * kPi * (dl + cos_theta) * phase_log * hg_pdf);
            forward_stretch = 1 - cos_theta / dl;
            backward_stretch = 1 + cos_theta / dl;
            if (guided) sample_st *= backward ? backward_stretch : forward_stretch;
        }
        double t = -std::log(1 - u_dist) / sample_st;

        // The first flight also probes ten mean free paths ahead for the far side.
        ray.tmax = bounce == 0 ? std::max(t, 10 / min_sigma_t) : t;
        ++*rays;
        bool reached = geometry.intersect_object(ray, entry.object, &h);
        if (bounce == 0) {
            if (reached) {
                have_opposite = true;
                opposite_distance = dot(ray.origin + ray.dir * h.t - p0, -n);
            }
            reached = reached && h.t < t;
        }
        if (reached) t = h.t;
        ray.origin = ray.origin + ray.dir * t;

        Rgb tr;
        Rgb pdf = flight_pdf(st, t, reached, &tr);
        if (bounce > 0) {
            auto scaled = [&](double k) {
                Rgb s;
                for (int c = 0; c < 3; ++c) s[c] = st[c] * k;
                return flight_pdf(s, t, reached);
            };
            Rgb guided = scaled(forward_stretch);
            if (have_opposite) {
                const Rgb back = scaled(backward_stretch);
                for (int c = 0; c < 3; ++c)
                    guided[c] = guided[c] * forward_factor * (1 - backward_fraction) +
                                back[c] * backward_factor * backward_fraction;
            } else {
                for (double& v : guided) v *= forward_factor;
            }
            for (int c = 0; c < 3; ++c)
                pdf[c] = pdf[c] * (1 - guided_fraction) + guided[c] * guided_fraction;
        }
        // The balance heuristic over the channels and the strategies.
        double denom = 0;
        for (int c = 0; c < 3; ++c) denom += channel_pdf[c] * pdf[c];
        if (!(denom > 0)) return false;
        for (int c = 0; c < 3; ++c) throughput[c] *= (reached ? tr[c] : ss[c] * tr[c]) / denom;

        if (reached) {
            *exit = h;
            *exit_dir = ray.dir;
            *beta = Color(throughput[0], throughput[1], throughput[2]);
            return std::isfinite(beta->r) && std::isfinite(beta->g) && std::isfinite(beta->b);
        }
        if (std::max({throughput[0], throughput[1], throughput[2]}) < 1e-6) return false;
    }
    return false;
}

}  // namespace glint::render
