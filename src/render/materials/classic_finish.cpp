#include "render/materials/classic_finish.h"

#include <cmath>

#include "core/noise.h"

namespace glint::render {

ClassicFinish::ClassicFinish(const scene::Finish& f)
    : ambient(f.ambient),
      emission(f.emission),
      diffuse(f.diffuse),
      diffuse_back(f.diffuse_back),
      brilliance(f.brilliance),
      phong(f.phong),
      phong_size(f.phong_size),
      specular(f.specular),
      // parstxtr.cpp: Roughness = 1 / roughness (a zero roughness is kept as 0).
      roughness_exponent(f.roughness != 0.0 ? 1.0 / f.roughness : 0.0),
      metallic(f.metallic),
      reflection_min(f.reflection.min),
      reflection_max(f.reflection.max),
      reflection_falloff(f.reflection.falloff),
      fresnel(f.reflection.fresnel),
      reflect_metallic(f.reflection.metallic),
      reflect_exponent(f.reflection.exponent != 0.0 ? 1.0 / f.reflection.exponent : 1.0),
      conserve_energy(f.conserve_energy),
      subsurface(f.subsurface),
      translucency(f.translucency),
      irid(f.irid),
      irid_thickness(f.irid_thickness),
      irid_turbulence(f.irid_turbulence) {}

Color irid_factor(const ClassicFinish& f, const Vec3& to_light, const Vec3& eye_dir,
                  const Vec3& n, const Vec3& p, const Color& wavelength, int noise_generator) {
    double thickness = f.irid_thickness;
    if (f.irid_turbulence != 0.0) {
        // POV-Ray's fixed turbulence for irid: 5 octaves, omega 0.5, lambda 2; 0..1 -> -1..1.
        TurbulenceParams turb;
        turb.octaves = 5;
        turb.omega = 0.5;
        turb.lambda = 2.0;
        const double noise = 2.0 * turbulence(p, turb, noise_generator) - 1.0;
        thickness *= 1.0 + noise * f.irid_turbulence;
    }
    // Both directions as unit vectors, as POV-Ray's rays carry them.
    const double phase = 2.0 * kPi * thickness *
                         (std::fabs(dot(n, normalize(to_light))) +
                          std::fabs(dot(n, normalize(eye_dir))));
    return Color(1.0 + f.irid * std::cos(phase / wavelength.r),
                 1.0 + f.irid * std::cos(phase / wavelength.g),
                 1.0 + f.irid * std::cos(phase / wavelength.b));
}

double metallic_fresnel(double cos_angle) {
    double x = std::fabs(std::acos(std::clamp(cos_angle, -1.0, 1.0))) / (kPi / 2);
    double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
    return std::min(1.0, std::max(0.0, f));
}

Color metallic_tint(double metallic, double cos_angle, const Color& pigment, const Color& light) {
    double f = metallic_fresnel(cos_angle);
    return light * (Color(1.0) + (pigment - Color(1.0)) * (metallic * (1.0 - f)));
}

Color diffuse_term(const ClassicFinish& f, const Vec3& n, const Vec3& to_light,
                   const Color& pigment, const Color& light, double attenuation, bool backside) {
    const double diffuse = backside ? f.diffuse_back : f.diffuse;
    if (diffuse <= 0.0) return Color();
    double c = dot(n, to_light);
    double intensity = f.brilliance != 1.0 ? std::pow(std::fabs(c), f.brilliance) : std::fabs(c);
    intensity *= diffuse * attenuation;
    return pigment * light * intensity;
}

Color phong_term(const ClassicFinish& f, const Vec3& n, const Vec3& to_light, const Vec3& eye_dir,
                 const Color& pigment, const Color& light) {
    Vec3 reflect = eye_dir + n * (-2.0 * dot(eye_dir, n));
    double c = dot(reflect, to_light);
    if (c <= 0.0) return Color();
    // "rgs": tiny cosines are dropped for large exponents.
    double intensity = (f.phong_size < 60 || c > 0.0008) ? f.phong * std::pow(c, f.phong_size)
                                                          : 0.0;
    if (f.metallic > 0.0)
        return metallic_tint(f.metallic, dot(n, to_light), pigment, light) * intensity;
    return light * intensity;
}

Color specular_term(const ClassicFinish& f, const Vec3& n, const Vec3& to_light,
                    const Vec3& eye_dir, const Color& pigment, const Color& light) {
    Vec3 halfway = (-eye_dir + to_light) * 0.5;
    double hl = length(halfway);
    if (hl <= 0.0) return Color();
    double c = dot(halfway, n) / hl;
    if (c <= 0.0) return Color();
    double intensity = f.specular * std::pow(c, f.roughness_exponent);
    if (f.metallic > 0.0)
        return metallic_tint(f.metallic, dot(n, to_light), pigment, light) * intensity;
    return light * intensity;
}

Color reflectivity(const ClassicFinish& f, double cos_angle, double ior, double* weight) {
    if (!f.fresnel) {
        double wmax = f.reflection_max.max();
        double wmin = f.reflection_min.max();
        *weight *= std::max(wmax, wmin);
        double frac = std::fabs(f.reflection_falloff - 1.0) > kPovEpsilon
                          ? std::pow(1.0 - cos_angle, f.reflection_falloff)
                          : 1.0 - cos_angle;
        if (std::fabs(frac) < kPovEpsilon) return f.reflection_min;
        if (std::fabs(frac - 1.0) < kPovEpsilon) return f.reflection_max;
        return f.reflection_max * frac + f.reflection_min * (1.0 - frac);
    }
    // Unpolarized Fresnel reflectance, as in ComputeReflectivity.
    Color r;
    double sqx = ior * ior + cos_angle * cos_angle - 1.0;
    if (sqx > 0.0) {
        double g = std::sqrt(sqx);
        double fr = 0.5 * ((g - cos_angle) * (g - cos_angle)) / ((g + cos_angle) * (g + cos_angle));
        double a = cos_angle * (g + cos_angle) - 1.0;
        double b = cos_angle * (g - cos_angle) + 1.0;
        fr = fr * (1.0 + (a * a) / (b * b));
        fr = std::min(1.0, std::max(0.0, fr));
        r = f.reflection_max * fr + f.reflection_min * (1.0 - fr);
    } else {
        r = f.reflection_max;
    }
    *weight *= r.max();
    return r;
}

}  // namespace glint::render
