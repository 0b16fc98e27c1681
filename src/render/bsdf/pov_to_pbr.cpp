#include "render/bsdf/pov_to_pbr.h"

#include <cmath>

namespace glint::render {
namespace {

// A Blinn-Phong exponent n and a microfacet roughness give highlights of about the same width
// when alpha = sqrt(2 / (n + 2)) (Walter et al. 2007); Blender's roughness is sqrt(alpha).
double roughness_from_exponent(double n) {
    const double alpha = std::sqrt(2.0 / (std::max(n, 0.0) + 2.0));
    return std::sqrt(alpha);
}

}  // namespace

SurfacePbr pov_to_pbr(const scene::Finish& finish, const scene::Interior& interior,
                      const scene::ColorFT& pigment) {
    SurfacePbr s;
    PrincipledParams& p = s.bsdf;
    p.base = Color(std::clamp(pigment.rgb.r, 0.0, 1.0), std::clamp(pigment.rgb.g, 0.0, 1.0),
                   std::clamp(pigment.rgb.b, 0.0, 1.0));
    const double refl = std::clamp(finish.reflection.max.max(), 0.0, 1.0);
    const bool tinted = finish.reflection.metallic > 0 || finish.metallic > 0;
    const double highlight = std::clamp(finish.phong + finish.specular, 0.0, 1.0);
    if (refl > 0) {
        // POV-Ray's reflection is a perfect mirror.
        p.roughness = 0;
        if (tinted) {
            p.metallic = refl;
            p.specular = 0.5;
        } else {
            p.metallic = 0;
            p.specular = refl / 0.08;  // F0 = reflection
        }
    } else if (highlight > 0) {
        const double n = finish.phong > 0 ? finish.phong_size
                                           : (finish.roughness > 0 ? 1.0 / finish.roughness : 1e4);
        p.roughness = roughness_from_exponent(n);
        p.specular = 0.5 * (1 + highlight);  // F0 from 0.04 to 0.08
        p.metallic = tinted ? std::clamp(finish.metallic, 0.0, 1.0) : 0.0;
    } else {
        p.roughness = 1;
        p.specular = 0;  // POV-Ray's plain diffuse surface has no highlight at all
        p.metallic = 0;
    }
    const double f = std::clamp(pigment.filter, 0.0, 1.0);
    const double t = std::clamp(pigment.transmit, 0.0, 1.0);
    p.ior = interior.ior > 0 ? interior.ior : 1.0;
    if (p.ior == 1.0) {
        // Untinted transmit lets rays pass (coverage); filter tints what passes.
        s.alpha = 1 - t;
        p.transmission = s.alpha > 0 ? std::clamp(f / s.alpha, 0.0, 1.0) : 0.0;
    } else {
        s.alpha = 1;
        p.transmission = std::clamp(f + t, 0.0, 1.0);
        if (p.transmission > 0) p.roughness = 0;  // POV-Ray's refraction is sharp
    }
    s.emission = pigment.rgb * finish.emission;
    return s;
}

SurfacePbr pbr_surface(const scene::Pbr& pbr, const Color& base) {
    SurfacePbr s;
    PrincipledParams& p = s.bsdf;
    p.base = base;
    p.metallic = pbr.metallic;
    p.roughness = pbr.roughness;
    p.specular = pbr.specular;
    p.ior = pbr.ior;
    p.transmission = pbr.transmission;
    s.emission = pbr.emission * pbr.emission_strength;
    s.alpha = std::clamp(pbr.alpha, 0.0, 1.0);
    return s;
}

const scene::Texture& base_texture(const scene::Texture& texture) {
    const scene::Texture* t = &texture;
    for (int i = 0; i < 16 && t->kind != scene::PatternKind::Plain; ++i) {
        if (!t->entries.empty()) t = &t->entries.front();
        else if (!t->texture_map.empty() && !t->texture_map.front().texture.empty())
            t = &t->texture_map.front().texture.front();
        else break;
    }
    return *t;
}

}  // namespace glint::render
