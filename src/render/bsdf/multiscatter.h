// Multiple-scattering GGX reflection and glass (Heitz et al. 2016, "Multiple-Scattering
// Microfacet BSDFs with the Smith Model"), as Cycles 3.4's Multiscatter GGX closures define
// them. Reflection first (MultiGgx), the dielectric walk below (MultiGlass). A random
// walk over the microsurface's heights and normals until the light leaves it. eval() adds the
// analytic single-scattering term (height-correlated masking) to a stochastic estimate of the
// rest, so its value is right in expectation only, as Cycles' is; its pdf is Cycles'
// approximation (the single-scattering visible-normal pdf blended with a cosine lobe by the
// single-scattering albedo). sample() walks the surface and returns the walk's throughput.
// Directions are local (z the normal), wo towards the viewer; for reflection both above.
#pragma once

#include <cstdint>

#include "core/math.h"

namespace glint::render {

struct MultiGgx {
    double alpha_x = 0.25, alpha_y = 0.25;
    // Each scattering after the first is tinted by `color` (Glossy), or by Cycles' Fresnel
    // interpolation from `cspec0` at `eta` (Principled's specular lobe), which then also
    // tints the first.
    bool fresnel = false;
    Color color{1, 1, 1};
    Color cspec0{1, 1, 1};
    double eta = 1.5;
};

// f |cos wi| (wi towards the light) and the approximate pdf; `seed` drives the walk.
Color multi_ggx_eval(const MultiGgx& m, const Vec3& wo, const Vec3& wi, uint64_t seed,
                     double* pdf);
// A direction by the random walk from wo; false when the walk does not escape upwards.
bool multi_ggx_sample(const MultiGgx& m, const Vec3& wo, uint64_t seed, Vec3* wi,
                      Color* weight, double* pdf);
// Cycles' fit of the single-scattering albedo (mf_ggx_albedo), alpha in [0, 1].
double multi_ggx_single_albedo(double alpha);

// Multiple-scattering GGX glass, Cycles 3.4's Multiscatter GGX glass closures: the same walk,
// where each microfacet reflects or refracts by its dielectric Fresnel term and the walk may
// cross to the far side of the microsurface (and back). Isotropic only, as in Cycles. `eta`
// is the index ratio seen from wo's side (the far side over wo's side); wo.z > 0, and wi
// below the surface is transmission. eval() is again a stochastic estimate and the pdf
// Cycles' approximation (mf_glass_pdf): the Fresnel-split single-scattering pdf blended with
// a cosine lobe by fitted albedos.
struct MultiGlass {
    double alpha = 0.25;
    double eta = 1.5;
    // Each scattering after the first is tinted by `color` (Glass BSDF). With `fresnel`
    // (Principled's glass), refractions are tinted by `color` and reflections by Cycles'
    // Fresnel interpolation from `cspec0`, and eval()'s reflection gets that tint as well.
    Color color{1, 1, 1};
    bool fresnel = false;
    Color cspec0{1, 1, 1};
};

Color multi_glass_eval(const MultiGlass& m, const Vec3& wo, const Vec3& wi, uint64_t seed,
                       double* pdf);
// A direction by the random walk from wo; false when the walk has not left the surface after
// Cycles' ten scatterings (the light is lost).
bool multi_glass_sample(const MultiGlass& m, const Vec3& wo, uint64_t seed, Vec3* wi,
                        Color* weight, double* pdf);
// Cycles' tint interpolation (interpolate_fresnel_color): cspec0 at normal incidence, white
// where the dielectric Fresnel of `eta` at cos_h reaches 1.
Color fresnel_tint(const Color& cspec0, double eta, double cos_h);
// Cycles' dielectric Fresnel (fresnel_dielectric_cos): |cos_i|, no inversion of eta.
double fresnel_cos(double cos_i, double eta);

}  // namespace glint::render
