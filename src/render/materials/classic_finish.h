// POV-Ray 3.7's classic finish model, term by term (source/backend/render/trace.cpp:
// ComputeDiffuseColour, ComputePhongColour, ComputeSpecularColour, ComputeReflectivity; the
// reference manual section 3.5.6 "Finish"). The Whitted integrator sums these per light.
#pragma once

#include "scene/texture.h"

namespace glint::render {

// The finish with POV-Ray's parse-time conversions applied (roughness and reflection
// exponent inverted, reflection type chosen), so that shading does no per-hit setup.
struct ClassicFinish {
    Color ambient;
    Color emission;
    double diffuse = 0.6;
    double diffuse_back = 0;  // for lights on the far side (scene::Finish::diffuse_back)
    double brilliance = 1;
    double phong = 0;
    double phong_size = 40;
    double specular = 0;
    double roughness_exponent = 20;  // 1 / roughness
    double metallic = 0;
    Color reflection_min;
    Color reflection_max;
    double reflection_falloff = 1;
    bool fresnel = false;
    double reflect_metallic = 0;
    double reflect_exponent = 1;  // 1 / reflection_exponent
    bool conserve_energy = false;
    // Subsurface light transport (finish `subsurface`; only with global_settings'
    // subsurface block): it stands in for the diffuse term.
    bool subsurface = false;
    Color translucency;
    double irid = 0, irid_thickness = 0, irid_turbulence = 0;

    explicit ClassicFinish(const scene::Finish& f);
    bool reflects() const { return !reflection_min.is_black() || !reflection_max.is_black(); }
};

// POV-Ray's ComputeIridColour: the factor thin-film interference puts on one light's
// contribution (or the reflection), 1 + irid * cos(2 pi t (|n.l| + |n.e|) / wavelength) per
// channel, the film thickness t varied by turbulence at `p` when the finish has some.
Color irid_factor(const ClassicFinish& f, const Vec3& to_light, const Vec3& eye_dir,
                  const Vec3& n, const Vec3& p, const Color& wavelength, int noise_generator);

// Diffuse term for one light: |n.l|^brilliance * diffuse * attenuation * pigment * light;
// `backside`: a light on the far side of the surface, with diffuse_back for diffuse.
Color diffuse_term(const ClassicFinish& f, const Vec3& n, const Vec3& to_light,
                   const Color& pigment, const Color& light, double attenuation,
                   bool backside = false);

// Phong highlight: phong * (r.l)^phong_size with r the mirrored eye ray; `eye_dir` is the
// incoming ray direction (unit).
Color phong_term(const ClassicFinish& f, const Vec3& n, const Vec3& to_light, const Vec3& eye_dir,
                 const Color& pigment, const Color& light);

// Specular highlight: specular * (h.n)^(1/roughness), h halfway between -eye_dir and to_light.
Color specular_term(const ClassicFinish& f, const Vec3& n, const Vec3& to_light,
                    const Vec3& eye_dir, const Color& pigment, const Color& light);

// POV-Ray's empirical Fresnel-like curve used by `metallic` (trace.cpp, [DB 9/94]).
double metallic_fresnel(double cos_angle);

// `light` tinted towards the pigment by `metallic`, less so at grazing angles: POV-Ray's
// metallic highlights (ComputePhongColour) and metallic reflection (ComputeLightedTexture).
Color metallic_tint(double metallic, double cos_angle, const Color& pigment, const Color& light);

// Reflectivity for an incidence cosine (ComputeReflectivity); `relative_ior` is only used by
// fresnel reflection. `weight` is scaled like POV-Ray's reflection ray weight.
Color reflectivity(const ClassicFinish& f, double cos_angle, double relative_ior, double* weight);

}  // namespace glint::render
