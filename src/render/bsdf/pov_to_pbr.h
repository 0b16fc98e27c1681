// The surface parameters the path tracer shades with, from either half of an IR material:
// the Pbr block as an importer filled it (OBJ/MTL, Blender), or, where Pbr is `derived`, the
// classic POV-Ray finish through the mapping documented in docs/pbr-mapping.md.
#pragma once

#include "render/bsdf/bsdf.h"
#include "render/textures/image_texture.h"
#include "scene/color.h"
#include "scene/texture.h"

namespace glint::render {

struct SurfacePbr {
    PrincipledParams bsdf;
    Color emission;     // emitted radiance (both sides)
    double alpha = 1;   // coverage; 1 - alpha of the rays pass straight through
    // POV-Ray's subsurface light transport as a random-walk BSSRDF of the base colour in
    // place of the diffuse lobe: per channel its diffusion length (Cycles' subsurface radius)
    // in scene units; black: none.
    Color subsurface_radius;
};

// POV-Ray finish + interior + the pigment color at the hit -> the Principled BSDF with a Lambert
// diffuse (docs/pbr-mapping.md). `mm_per_unit` > 0: the scene's subsurface light transport is
// on (global_settings subsurface), and a finish with `subsurface` gets a BSSRDF.
SurfacePbr pov_to_pbr(const scene::Finish& finish, const scene::Interior& interior,
                      const scene::ColorFT& pigment, double mm_per_unit = 0);

// An importer-filled Pbr; `base` is the base color at the hit (base_color or its map).
SurfacePbr pbr_surface(const scene::Pbr& pbr, const Color& base);

// One PBR image map ready for lookups at a surface uv: the image (nullptr when the material
// has no such map or its file is missing) and MTL's -o/-s (the image is read at uv * s + o).
struct PbrMapLookup {
    const ImageTexture* image = nullptr;
    double ou = 0, ov = 0, su = 1, sv = 1;
    // The image holds 8-bit sRGB values as stored, decoded after the bilinear blend: Cycles
    // 3.4 keeps such images as bytes and decodes the interpolated value ("compress as sRGB"),
    // which differs from blending decoded texels wherever neighbours differ much (a texture's
    // wrap seam by up to 70%).
    bool decode_after = false;
    explicit operator bool() const { return image != nullptr; }
    // Bilinear, repeating, (0, 0) at the image's bottom left: r, g, b, filter, transmit.
    void lookup(Vec2 uv, float out[5]) const;
    // Luminance (Rec. 709 weights) of the color: a data map's value.
    double value(Vec2 uv) const;
};

// The maps of one importer-filled material, loaded at prepare time (formats/obj/MTL.md).
struct PbrMaps {
    PbrMapLookup base_color, specular, emission, roughness, metallic, exponent, alpha, bump;
    // The bump image is colored: a tangent-space normal map (what Blender writes as map_Bump)
    // rather than a gray height map.
    bool normal_map = false;
    double bump_multiplier = 1;
    bool any() const {
        return base_color || specular || emission || roughness || metallic || exponent || alpha ||
               bump;
    }
};

// Loads `pbr`'s maps into `cache`: data maps as stored; color maps of 8-bit sRGB files as
// stored too, decoded at lookup (decode_after), others decoded from their own gamma at load.
PbrMaps prepare_pbr_maps(const scene::Pbr& pbr, TextureCache& cache);

// The surface at `uv`: each map present replaces its constant (MTL.md says how each is read).
SurfacePbr pbr_surface(const scene::Pbr& pbr, const PbrMaps& maps, Vec2 uv);

// The shading normal `n` bent by the material's bump map at `uv`, given the uv tangents dpdu,
// dpdv (world space). A height map displaces the surface by bump_multiplier * h along n
// (h the image value, in world units); a normal map is decoded in the tangent frame (tangent
// along dpdu, bitangent on dpdv's side) and mixed with n by the strength bump_multiplier, as
// Blender's Normal Map node does. `n` unchanged without a bump map or without tangents.
Vec3 mapped_normal(const PbrMaps& maps, Vec2 uv, const Vec3& n, const Vec3& dpdu,
                   const Vec3& dpdv);

// The plain texture the path tracer reads a POV-Ray texture's finish and pigment from: the
// texture itself, or for patterned textures their first entry (layers are not combined).
const scene::Texture& base_texture(const scene::Texture& texture);

}  // namespace glint::render
