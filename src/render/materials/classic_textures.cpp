// How the Whitted integrator walks POV-Ray's patterned textures (ComputeOneTextureColour and
// ComputeShadowTexture in POV-Ray's trace.cpp): texture_map, block patterns of textures,
// average and material_map route a hit to plain textures, lit (or filtering shadow rays)
// in their pattern's warped space.
#include <cmath>

#include "render/integrators/whitted.h"
#include "render/textures/normal.h"

namespace glint::render {
namespace {

// Light that passes a layer: rgb * filter + transmit (Colour::rgbTransm).
Color rgb_transm(const scene::ColorFT& c) {
    return Color(c.rgb.r * c.filter + c.transmit, c.rgb.g * c.filter + c.transmit,
                 c.rgb.b * c.filter + c.transmit);
}

}  // namespace

Color Whitted::texture_colour(const Ray& ray, const Hit& hit, const scene::Texture& tex,
                              const PatternPoint& at, const Vec3& n, double weight,
                              const RayState& state, TextureStack stack) const {
    // ComputeOneTextureColour: a patterned texture picks (and blends) the textures of its map
    // by its pattern value; each one is lit on its own, in the pattern's warped space.
    if (tex.kind == scene::PatternKind::Plain)
        return lighted_texture(ray, hit, tex, at, n, weight, state, stack);
    if (stack.count < TextureStack::kMax) stack.texture[stack.count++] = &tex;
    Vec3 p = at.p;
    if (tex.uv_mapping) p = uv_mapped(at);
    const scene::PatternParams& pp = tex.params;
    const Vec3 local = tex.transform.is_identity() ? p : tex.transform.inverse_point(p);
    const Vec3 tp = pp.warps.empty() ? local : warp_point(tex.kind, pp, local);
    const PatternPoint sub{tp, at.uv, at.has_uv, at.normal};
    if (tex.kind == scene::PatternKind::ImageMap)  // material_map: the pixel picks the texture
        return texture_colour(ray, hit, material_map_entry(tex, pigments_.textures(), tp), sub,
                              n, weight, state, stack);
    if (tex.kind == scene::PatternKind::Average) {
        Color sum;
        double total = 0;
        for (const scene::TextureMapEntry& e : tex.texture_map) {
            sum += texture_colour(ray, hit, e.texture[0], sub, n, weight, state, stack) * e.value;
            total += e.value;
        }
        return sum / total;
    }
    PatternContext on_surface = pigments_.context();
    on_surface.normal = at.normal;
    on_surface.ray_dir = at.ray_dir;
    const double value = evaluate_pattern(tex.kind, pp, local, on_surface);
    if (is_block_pattern(tex.kind)) {
        const scene::Texture& e = tex.entries[block_index(value, tex.entries.size())];
        return texture_colour(ray, hit, e, sub, n, weight, state, stack);
    }
    const auto& map = tex.texture_map;
    BlendPick b = search_blend_map(map, value);
    Color c = texture_colour(ray, hit, map[b.cur].texture[0], sub, n, weight, state, stack);
    if (b.prev != b.cur) {
        Color c2 = texture_colour(ray, hit, map[b.prev].texture[0], sub, n, weight, state, stack);
        c = c * b.fraction + c2 * (1.0 - b.fraction);
    }
    return c;
}

Vec3 Whitted::layer_normal(const scene::Normal& normal, const PatternPoint& at, const Vec3& n,
                           const TextureStack& stack) const {
    if (normal.kind == scene::PatternKind::Plain || !features_.normals) return n;
    // The enclosing patterned textures' transforms carry the normal into their space.
    Vec3 m = n;
    for (int i = 0; i < stack.count; ++i)
        m = warp_normal(stack.texture[i]->transform, stack.texture[i]->params, m);
    m = perturb_normal(normal, at, m, pigments_.context(), pigments_.textures());
    for (int i = stack.count - 1; i >= 0; --i)
        m = unwarp_normal(stack.texture[i]->transform, stack.texture[i]->params, m);
    return m;
}


Color Whitted::shadow_texture(const scene::Texture& tex, const PatternPoint& at,
                              double caustics, const Vec3& raw_normal, const Vec3& dir) const {
    if (tex.kind == scene::PatternKind::Plain) {
        // Every layer filters the light (ComputeShadowTexture), and with an interior's
        // `caustics` each layer brightens it by 1 + |n . d|^caustics (POV-Ray's fake
        // caustics, n the layer's perturbed normal): light through a curved glass surface
        // gathers where the surface faces the light.
        Color filter(1.0);
        scene::ColorFT pig;
        auto layer = [&](const scene::Texture& l) {
            if (pigments_.evaluate(l.pigment, at, &pig)) filter *= rgb_transm(pig);
            if (caustics != 0.0) {
                Vec3 n = raw_normal;
                if (l.normal.kind != scene::PatternKind::Plain && features_.normals)
                    n = perturb_normal(l.normal, at, n, pigments_.context(),
                                       pigments_.textures());
                filter *= 1.0 + std::pow(std::fabs(dot(n, dir)), caustics);
            }
        };
        layer(tex);
        for (const scene::Texture& l : tex.layers) layer(l);
        return filter;
    }
    Vec3 p = at.p;
    if (tex.uv_mapping) p = uv_mapped(at);
    const scene::PatternParams& pp = tex.params;
    const Vec3 local = tex.transform.is_identity() ? p : tex.transform.inverse_point(p);
    const PatternPoint sub{pp.warps.empty() ? local : warp_point(tex.kind, pp, local), at.uv,
                           at.has_uv, at.normal};
    if (tex.kind == scene::PatternKind::ImageMap)
        return shadow_texture(material_map_entry(tex, pigments_.textures(), sub.p), sub,
                              caustics, raw_normal, dir);
    if (tex.kind == scene::PatternKind::Average) {
        Color sum;
        double total = 0;
        for (const scene::TextureMapEntry& e : tex.texture_map) {
            sum += shadow_texture(e.texture[0], sub, caustics, raw_normal, dir) * e.value;
            total += e.value;
        }
        return sum / total;
    }
    PatternContext on_surface = pigments_.context();
    on_surface.normal = at.normal;
    on_surface.ray_dir = at.ray_dir;
    const double value = evaluate_pattern(tex.kind, pp, local, on_surface);
    if (is_block_pattern(tex.kind))
        return shadow_texture(tex.entries[block_index(value, tex.entries.size())], sub, caustics,
                              raw_normal, dir);
    BlendPick b = search_blend_map(tex.texture_map, value);
    Color c = shadow_texture(tex.texture_map[b.cur].texture[0], sub, caustics, raw_normal, dir);
    if (b.prev != b.cur)
        c = c * b.fraction +
            shadow_texture(tex.texture_map[b.prev].texture[0], sub, caustics, raw_normal, dir) *
                (1.0 - b.fraction);
    return c;
}

}  // namespace glint::render
