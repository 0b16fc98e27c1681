#include "render/bsdf/pov_to_pbr.h"

#include <algorithm>
#include <cmath>

#include "render/materials/sslt.h"

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
                      const scene::ColorFT& pigment, double mm_per_unit) {
    SurfacePbr s;
    PrincipledParams& p = s.bsdf;
    p.diffuse_model = DiffuseModel::Lambert;  // POV-Ray's diffuse is Lambert
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
        if (finish.specular > 0) {
            // POV-Ray's `specular` is a Blinn-Phong highlight: a GGX lobe of the same width.
            const double n = finish.roughness > 0 ? 1.0 / finish.roughness : 1e4;
            p.roughness = roughness_from_exponent(n);
            p.specular = 0.5 * (1 + std::clamp(finish.specular, 0.0, 1.0));  // F0 0.04 .. 0.08
            p.metallic = tinted ? std::clamp(finish.metallic, 0.0, 1.0) : 0.0;
        } else {
            p.roughness = 1;
            p.specular = 0;
            p.metallic = 0;
        }
        if (finish.phong > 0) {
            // POV-Ray's `phong` is cos^n of the angle to the mirror direction: the modified
            // Phong lobe itself, its weight the phong amount (tinted by the pigment as far as
            // `metallic` says), and the diffuse albedo kept at or below 1 - ks per channel so
            // the surface reflects no more than it receives.
            const double amount = std::clamp(finish.phong, 0.0, 1.0);
            const double m = tinted ? std::clamp(finish.metallic, 0.0, 1.0) : 0.0;
            p.phong_ks = (Color(1.0) * (1 - m) + p.base * m) * amount;
            p.phong_exponent = std::max(0.0, finish.phong_size);
            p.base = Color(std::min(p.base.r, 1 - p.phong_ks.r),
                           std::min(p.base.g, 1 - p.phong_ks.g),
                           std::min(p.base.b, 1 - p.phong_ks.b));
        }
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
    if (finish.subsurface && mm_per_unit > 0 && p.transmission < 1) {
        // The classic renderer's coefficients (render/materials/sslt.h): reduced scattering
        // 1 / translucency (per mm), the reduced albedo that gives the base colour as its
        // diffuse reflectance (the base colour, as the Lambert lobe it replaces); the walk's
        // length scale is the diffusion length 1 / sigma_tr.
        const SsltCoefficients k(finish.translucency, p.base, p.ior);
        auto radius = [mm_per_unit](double sa, double st) {
            const double tr = std::sqrt(3 * sa * st);
            // (No absorption: light diffuses without end; a thousand free paths stand in.)
            return 1 / (std::max(tr, 1e-3 * st) * mm_per_unit);
        };
        s.subsurface_radius = Color(radius(k.sigma_a.r, k.sigma_prime_t.r),
                                    radius(k.sigma_a.g, k.sigma_prime_t.g),
                                    radius(k.sigma_a.b, k.sigma_prime_t.b));
        p.diffuse_lobe = false;
    }
    return s;
}

SurfacePbr pbr_surface(const scene::Pbr& pbr, const Color& base) {
    SurfacePbr s;
    PrincipledParams& p = s.bsdf;
    p.base = base;
    // Blender's Principled BSDF has Burley's diffuse; other MTL materials (Blender's Diffuse
    // BSDF, other exporters) a Lambert one.
    p.diffuse_model = pbr.principled ? DiffuseModel::Burley : DiffuseModel::Lambert;
    p.metallic = pbr.metallic;
    p.roughness = pbr.roughness;
    p.specular = pbr.specular;
    p.ior = pbr.ior;
    p.transmission = pbr.transmission;
    s.emission = pbr.emission * pbr.emission_strength;
    s.alpha = std::clamp(pbr.alpha, 0.0, 1.0);
    return s;
}

void PbrMapLookup::lookup(Vec2 uv, float out[5]) const {
    const int w = image->width(), h = image->height();
    // Texel centres at (i + 0.5) / w; row 0 is the top of the image, v = 0 its bottom.
    const double x = (uv.x * su + ou) * w - 0.5;
    const double y = (1.0 - (uv.y * sv + ov)) * h - 0.5;
    const double fx0 = std::floor(x), fy0 = std::floor(y);
    const double fx = x - fx0, fy = y - fy0;
    auto wrap = [](double i, int n) {
        const double m = std::fmod(i, static_cast<double>(n));
        const int k = static_cast<int>(m < 0 ? m + n : m);
        return std::clamp(k, 0, n - 1);  // fmod of a huge or NaN uv stays in range
    };
    const int x0 = wrap(fx0, w), x1 = x0 + 1 < w ? x0 + 1 : 0;
    const int y0 = wrap(fy0, h), y1 = y0 + 1 < h ? y0 + 1 : 0;
    const float *a = image->texel(x0, y0), *b = image->texel(x1, y0),
                *c = image->texel(x0, y1), *d = image->texel(x1, y1);
    const double wa = (1 - fx) * (1 - fy), wb = fx * (1 - fy), wc = (1 - fx) * fy, wd = fx * fy;
    for (int k = 0; k < 5; ++k)
        out[k] = static_cast<float>(a[k] * wa + b[k] * wb + c[k] * wc + d[k] * wd);
    if (decode_after)
        for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(srgb_decode(out[k]));
}

double PbrMapLookup::value(Vec2 uv) const {
    float t[5];
    lookup(uv, t);
    return 0.2126 * t[0] + 0.7152 * t[1] + 0.0722 * t[2];
}

namespace {

PbrMapLookup prepare_map(const scene::PbrMap& m, bool color, TextureCache& cache) {
    PbrMapLookup l;
    if (!m.present()) return l;
    // A color map is read as stored first: an 8-bit sRGB file (nearly every one) is used so
    // and decoded after the blend; any other is read again, decoded at load.
    cache.add_pbr(m, false);
    l.image = cache.find_pbr(m, false);
    if (color && l.image && l.image->srgb8()) {
        l.decode_after = true;
    } else if (color) {
        cache.add_pbr(m, true);
        l.image = cache.find_pbr(m, true);
    }
    if (l.image && (l.image->width() <= 0 || l.image->height() <= 0)) l.image = nullptr;
    l.ou = m.offset.x;
    l.ov = m.offset.y;
    l.su = m.scale.x != 0 ? m.scale.x : 1;
    l.sv = m.scale.y != 0 ? m.scale.y : 1;
    return l;
}

// A gray image (r = g = b, up to the odd rounding a JPEG adds) holds heights; a colored one a
// normal map, whose texels are far from gray (about (0.5, 0.5, 1)).
bool is_gray(const ImageTexture& img) {
    double spread = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const float* t = img.texel(x, y);
            spread += std::fabs(t[0] - t[1]) + std::fabs(t[1] - t[2]);
        }
    return spread < 0.02 * img.width() * img.height();
}

}  // namespace

PbrMaps prepare_pbr_maps(const scene::Pbr& pbr, TextureCache& cache) {
    PbrMaps m;
    m.base_color = prepare_map(pbr.base_color_map, true, cache);
    m.specular = prepare_map(pbr.specular_map, true, cache);
    m.emission = prepare_map(pbr.emission_map, true, cache);
    m.roughness = prepare_map(pbr.roughness_map, false, cache);
    m.metallic = prepare_map(pbr.metallic_map, false, cache);
    m.exponent = prepare_map(pbr.exponent_map, false, cache);
    m.alpha = prepare_map(pbr.alpha_map, false, cache);
    m.bump = prepare_map(pbr.bump_map, false, cache);
    m.bump_multiplier = pbr.bump_map.bump_multiplier;
    if (m.bump) m.normal_map = !is_gray(*m.bump.image);
    return m;
}

SurfacePbr pbr_surface(const scene::Pbr& pbr, const PbrMaps& maps, Vec2 uv) {
    float t[5];
    Color base = pbr.base_color;
    if (maps.base_color) {
        maps.base_color.lookup(uv, t);
        base = Color(t[0], t[1], t[2]);
    }
    SurfacePbr s = pbr_surface(pbr, base);
    PrincipledParams& p = s.bsdf;
    if (maps.specular) p.specular = std::max(0.0, maps.specular.value(uv));
    if (maps.roughness) {
        p.roughness = maps.roughness.value(uv);
    } else if (maps.exponent) {
        // map_Ns scales the exponent range 0..1000: Ns = 1000 v, roughness as for Ns.
        p.roughness = 1.0 - std::sqrt(std::clamp(maps.exponent.value(uv), 0.0, 1.0));
    }
    p.roughness = std::clamp(p.roughness, 0.0, 1.0);
    if (maps.metallic) p.metallic = std::clamp(maps.metallic.value(uv), 0.0, 1.0);
    if (maps.emission) {
        maps.emission.lookup(uv, t);
        s.emission = Color(std::max(0.0f, t[0]), std::max(0.0f, t[1]), std::max(0.0f, t[2]));
    }
    if (maps.alpha) {
        // The image's alpha channel where it has one (Blender links the Alpha output), else
        // its gray value (a mask).
        if (maps.alpha.image->has_alpha()) {
            maps.alpha.lookup(uv, t);
            s.alpha = 1.0 - t[4];
        } else {
            s.alpha = maps.alpha.value(uv);
        }
        s.alpha = std::clamp(s.alpha, 0.0, 1.0);
    }
    return s;
}

Vec3 mapped_normal(const PbrMaps& maps, Vec2 uv, const Vec3& n, const Vec3& dpdu,
                   const Vec3& dpdv) {
    if (!maps.bump) return n;
    // The tangents in the shading normal's plane.
    const Vec3 tu = dpdu - n * dot(n, dpdu);
    const Vec3 tv = dpdv - n * dot(n, dpdv);
    const double lu = length(tu), lv = length(tv);
    if (!(lu > 0) || !(lv > 0) || !std::isfinite(lu) || !std::isfinite(lv)) return n;
    Vec3 r;
    if (maps.normal_map) {
        float t[5];
        maps.bump.lookup(uv, t);
        const Vec3 c(2.0 * t[0] - 1.0, 2.0 * t[1] - 1.0, 2.0 * t[2] - 1.0);
        const Vec3 tangent = tu / lu;
        Vec3 bitangent = cross(n, tangent);
        if (dot(bitangent, tv) < 0) bitangent = -bitangent;  // mirrored uvs
        const Vec3 mapped = tangent * c.x + bitangent * c.y + n * c.z;
        const double strength = std::max(0.0, maps.bump_multiplier);
        r = n + (mapped - n) * strength;
    } else {
        // Central differences one texel apart (in the surface's uv, so -s is included).
        const PbrMapLookup& b = maps.bump;
        const double du = 1.0 / (b.image->width() * std::fabs(b.su));
        const double dv = 1.0 / (b.image->height() * std::fabs(b.sv));
        const double hu = (b.value(Vec2(uv.x + du / 2, uv.y)) -
                           b.value(Vec2(uv.x - du / 2, uv.y))) / du;
        const double hv = (b.value(Vec2(uv.x, uv.y + dv / 2)) -
                           b.value(Vec2(uv.x, uv.y - dv / 2))) / dv;
        const double k = maps.bump_multiplier;
        r = cross(tu + n * (k * hu), tv + n * (k * hv));
        if (dot(r, n) < 0) r = -r;
    }
    const double len = length(r);
    if (!(len > 0) || !std::isfinite(len)) return n;
    return r / len;
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
