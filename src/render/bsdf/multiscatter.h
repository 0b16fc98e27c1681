// Multiple-scattering GGX reflection (Heitz et al. 2016, "Multiple-Scattering Microfacet
// BSDFs with the Smith Model"), as Cycles 3.4's Multiscatter GGX closures define it: a random
// walk over the microsurface's heights and normals until the light leaves it. eval() adds the
// analytic single-scattering term (height-correlated masking) to a stochastic estimate of the
// rest, so its value is right in expectation only, as Cycles' is; its pdf is Cycles'
// approximation (the single-scattering visible-normal pdf blended with a cosine lobe by the
// single-scattering albedo). sample() walks the surface and returns the walk's throughput.
// Directions are local (z the normal), both above the surface; wo is towards the viewer.
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

}  // namespace glint::render
