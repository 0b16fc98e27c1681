// POV-Ray 3.7's subsurface light transport (finish `subsurface`; the manual's "Subsurface
// Light Transport", source/backend/render/trace.cpp's SSLT functions and
// backend/lighting/subsurface.cpp): Jensen et al. 2001's dipole diffusion term and single
// scattering, with POV-Ray's own Fresnel approximations. Lengths are in millimetres
// (global_settings mm_per_unit converts scene units), coefficients per millimetre.
#pragma once

#include <cstddef>

#include "core/math.h"
#include "render/ray.h"

namespace glint::render {

// The Fresnel transmittance into (or out of) a medium of relative index `eta` for light at
// incidence cosine `cos_angle`: 1 - F with POV-Ray's unpolarized Fresnel formula (ComputeFt).
double sslt_transmittance(double cos_angle, double eta);

// POV-Ray's approximation of the diffuse Fresnel reflectance F_dr (FresnelDiffuseReflectance).
double fresnel_diffuse_reflectance(double eta);

// The total diffuse reflectance of a semi-infinite medium of reduced albedo `alpha_prime`
// under uniform light (Jensen's R_d), A = (1 + F_dr) / (1 - F_dr).
double dipole_total_reflectance(double A, double alpha_prime);

// The reduced albedo that gives diffuse reflectance `reflectance` (clamped to [0, 1]): what
// POV-Ray derives from pigment times diffuse (SubsurfaceInterior::GetReducedAlbedo).
double reduced_albedo(double reflectance, double eta);

// The dipole's diffuse reflectance R_d(r) at squared distance `dist_sqr` (mm^2) between
// where light enters and leaves, per unit area (1/mm^2), without the Fresnel terms.
double dipole_reflectance(double dist_sqr, double sigma_prime_s, double sigma_a, double eta);

// Subsurface coefficients of one finish at one point, per channel: the reduced scattering
// 1 / translucency, the reduced extinction from the reduced albedo, absorption the rest.
struct SsltCoefficients {
    Color sigma_prime_s, sigma_prime_t, sigma_a;
    SsltCoefficients(const Color& translucency, const Color& reflectance, double eta);
};

// What the subsurface estimate asks of the renderer around it.
class SsltScene {
public:
    virtual ~SsltScene() = default;
    // The first surface along `dir` from `origin` within `tmax` (every object).
    virtual bool intersect(const Vec3& origin, const Vec3& dir, double tmax, Hit* hit) const = 0;
    virtual size_t light_count() const = 0;
    // The direction from `p` towards light `k`; false where the light cannot reach `p`.
    virtual bool light_direction(size_t k, const Vec3& p, Vec3* dir) const = 0;
    // Light `k` arriving at the surface point `at` past whatever lies towards it, and its
    // direction; black where none arrives.
    virtual Color light(size_t k, const Hit& at, Vec3* dir) const = 0;
    // What a ray leaving the object sees, traced with `weight`.
    virtual Color trace(const Ray& ray, double weight) const = 0;
};

struct SsltSettings {
    int samples_diffuse = 50, samples_single = 50;
    double mm_per_unit = 10;
    double adc_bailout = 1.0 / 255;
};

// POV-Ray's ComputeSubsurfaceScattering: the light a subsurface finish sends back along `ray`
// from `out` (raw_n: the surface normal facing the ray), made of the diffuse dipole term
// gathered from samples_diffuse points, single scattering from samples_single distances along
// the refracted ray, and what crosses the object unscattered. `reflectance` is pigment times
// diffuse, `eta` the relative index into the object.
Color subsurface_light(const SsltScene& scene, const SsltSettings& settings,
                       const Color& translucency, const Color& reflectance, double eta,
                       const Ray& ray, const Hit& out, const Vec3& raw_n);

}  // namespace glint::render
