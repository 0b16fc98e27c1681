// The single BSDFs of Blender's shader nodes that the Principled model (bsdf.h) does not
// cover, as Cycles 3.4 defines them (kernel/closure/bsdf_*.h): Oren-Nayar, Translucent, the
// two Toon lobes, Ashikhmin's Velvet, the Principled BSDF's sheen and clearcoat, microfacet
// reflection (Glossy and Anisotropic: GGX, Beckmann, Ashikhmin-Shirley) and refraction
// (Refraction BSDF), and the Multiscatter GGX random walks (reflection and glass). A lobe
// lives in a local frame (z the shading normal, x the tangent); wo points towards the viewer.
// eval() returns f |cos wi|, as Cycles' closures do (Toon is defined by that product, not by
// f). Plain values, built per hit on the stack.
#pragma once

#include <cstdint>

#include "render/bsdf/bsdf.h"
#include "render/bsdf/microfacet.h"
#include "render/bsdf/multiscatter.h"

namespace glint::render {

class Lobe {
public:
    enum class Kind : uint8_t {
        OrenNayar, Translucent, DiffuseToon, GlossyToon, Velvet, Sheen, Clearcoat,
        Reflection, Refraction, AshikhminShirley, MultiGGX, MultiGlass, SubsurfaceExit,
        RetroReflection, BurleyLambert
    };

    // Oren-Nayar with Cycles' sigma = roughness in [0, 1] (0 is Lambert).
    static Lobe oren_nayar(double roughness);
    // Lambertian transmission: light from the far side.
    static Lobe translucent();
    // Toon: full intensity within size * 90 degrees of the normal (diffuse) or of the mirror
    // direction (glossy), fading to 0 over a further smooth * 90 degrees. Sampled uniformly in
    // the cone, with Cycles' weight (sample() does not agree with eval(): see lobe.cpp).
    static Lobe toon(bool glossy, double size, double smooth);
    static Lobe velvet(double sigma);
    // The Principled BSDF's sheen (Schlick's weight of the angle to the half vector).
    static Lobe sheen();
    // The Principled BSDF's clearcoat: GTR1 of alpha = clearcoat roughness^2, Fresnel of IOR
    // 1.5, scaled by 0.25 clearcoat.
    static Lobe clearcoat(double clearcoat, double roughness);
    // Microfacet reflection without Fresnel (Glossy, Anisotropic); alpha below 1e-3 is a
    // mirror. Ashikhmin-Shirley has its own model with exponents 2 / alpha^2 - 2.
    static Lobe reflection(const Microfacet& m);
    static Lobe ashikhmin_shirley(double alpha_x, double alpha_y);
    // Microfacet refraction without Fresnel (Refraction BSDF); `eta` inside over outside.
    static Lobe refraction(const Microfacet& m, double eta);
    // Multiscatter GGX reflection (multiscatter.h); alpha below Cycles' singular threshold is
    // a mirror. Its eval() is an estimate (right in expectation), as in Cycles.
    static Lobe multi_ggx(const MultiGgx& m);
    // Multiscatter GGX glass (multiscatter.h) with `eta` inside over outside; the lobe turns
    // it to the viewer's side. Alpha is clamped to [1e-4, 1] as in Cycles; below its singular
    // threshold the lobe is a smooth dielectric (mirror or refraction by the Fresnel term).
    static Lobe multi_glass(const MultiGlass& m);
    // Where a Principled BSDF's subsurface walk leaves the surface: Lambert times Burley's
    // exit Fresnel 1 - 0.5 (1 - cos wi)^5 (Cycles' PRINCIPLED_DIFFUSE_LAMBERT_EXIT).
    static Lobe subsurface_exit();
    // The retro-reflection that Burley's diffuse keeps beside a subsurface BSSRDF (Cycles'
    // PRINCIPLED_DIFFUSE_RETRO_REFLECTION), with its share scaled by roughness x Schlick's
    // weight of the view as Cycles scales it.
    static Lobe retro_reflection(double roughness);
    // Burley's diffuse without its retro-reflection: Lambert x (1 - 0.5 FV)(1 - 0.5 FL), what
    // Cycles keeps for the channels whose subsurface radius is too small to walk.
    static Lobe burley_lambert();

    Kind kind() const { return kind_; }
    bool delta() const { return delta_; }
    // Cycles' diffuse closures (CLOSURE_IS_BSDF_DIFFUSE): the bump shadowing term applies.
    bool diffuse() const {
        return kind_ == Kind::OrenNayar || kind_ == Kind::Translucent ||
               kind_ == Kind::DiffuseToon || kind_ == Kind::Sheen ||
               kind_ == Kind::SubsurfaceExit || kind_ == Kind::RetroReflection ||
               kind_ == Kind::BurleyLambert;
    }
    // Cycles' factor on a closure's sample weight that depends on the view (sheen's average
    // value, clearcoat's Fresnel): the weight of the lobe among the others for wo.
    double sample_scale(const Vec3& wo) const;

    Color eval(const Vec3& wo, const Vec3& wi, double* pdf) const;
    bool sample(const Vec3& wo, double u1, double u2, BsdfSample* out) const;

private:
    Kind kind_ = Kind::OrenNayar;
    bool delta_ = false;
    double a_ = 0, b_ = 0;  // Oren-Nayar's A, B; Toon's angle and smooth; Velvet 1/sigma^2;
                            // Ashikhmin-Shirley's exponents; clearcoat's amount
    double eta_ = 1;
    Microfacet m_;
    MultiGgx multi_;
    MultiGlass glass_;
};

}  // namespace glint::render
