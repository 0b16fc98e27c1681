// Microfacet distributions and the reflection and refraction terms built on them, in a local
// frame (z the normal, x the tangent of an anisotropic surface). Shared by the Principled
// model (bsdf.h) and the single lobes of node graphs (lobe.h).
//   GGX        Trowbridge-Reitz, anisotropic, Smith masking; sampled by visible normals
//              (Heitz 2018)
//   Beckmann   anisotropic, with the rational Smith G1 that Cycles 3.4 uses; sampled by
//              D(m) cos(m)
//   Clearcoat  Burley's GTR1 for D with GGX masking of a fixed alpha 0.25, as the Principled
//              BSDF's clearcoat; sampled by D(m) cos(m)
// G is separable, G1(o) G1(i), as Cycles 3.4 takes it.
#pragma once

#include "core/math.h"

namespace glint::render {

// Fresnel reflectance of a dielectric interface; cos_i < 0 means arriving from inside.
// `eta` is the interior over the exterior index of refraction.
double fresnel_dielectric(double cos_i, double eta);

struct Microfacet {
    enum class Kind { GGX, Beckmann, Clearcoat };
    Kind kind = Kind::GGX;
    double alpha_x = 0.25, alpha_y = 0.25;

    static Microfacet ggx(double alpha) { return {Kind::GGX, alpha, alpha}; }

    double d(const Vec3& wm) const;
    double g1(const Vec3& w) const;
    double g(const Vec3& wo, const Vec3& wi) const { return g1(wo) * g1(wi); }
    // The density over normals of sample_normal() seen from w (w on either side).
    double pdf_normal(const Vec3& w, const Vec3& wm) const;
    // A microfacet normal with wm.z > 0 for the view w.
    Vec3 sample_normal(const Vec3& w, double u1, double u2) const;
};

// Microfacet reflection without Fresnel for o.z, i.z > 0: f, and in *pdf the density of
// reflecting a normal drawn by sample_normal() from o.
double microfacet_reflection(const Microfacet& m, const Vec3& o, const Vec3& i, double* pdf);
// Microfacet refraction without Fresnel (Walter et al. 2007, in the form Cycles evaluates:
// radiance not scaled by 1 / eta^2) for o.z > 0 > i.z in the frame flipped to o's side;
// etap: the index on i's side over o's. f, and the density of refracting a sampled normal.
double microfacet_refraction(const Microfacet& m, double etap, const Vec3& o, const Vec3& i,
                             double* pdf);

// Mirror direction of wo about n, and the refraction of wi through n (eta: inside over
// outside; wi on either side); false under total internal reflection.
Vec3 reflect(const Vec3& wo, const Vec3& n);
bool refract(const Vec3& wi, Vec3 n, double eta, Vec3* wt);

}  // namespace glint::render
