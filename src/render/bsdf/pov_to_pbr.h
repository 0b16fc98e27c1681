// The surface parameters the path tracer shades with, from either half of an IR material:
// the Pbr block as an importer filled it (OBJ/MTL, Blender), or, where Pbr is `derived`, the
// classic POV-Ray finish through the mapping documented in docs/pbr-mapping.md.
#pragma once

#include "render/bsdf/bsdf.h"
#include "scene/color.h"
#include "scene/texture.h"

namespace glint::render {

struct SurfacePbr {
    PrincipledParams bsdf;
    Color emission;     // emitted radiance (both sides)
    double alpha = 1;   // coverage; 1 - alpha of the rays pass straight through
};

// POV-Ray finish + interior + the pigment color at the hit -> Principled-lite.
SurfacePbr pov_to_pbr(const scene::Finish& finish, const scene::Interior& interior,
                      const scene::ColorFT& pigment);

// An importer-filled Pbr; `base` is the base color at the hit (base_color or its map).
SurfacePbr pbr_surface(const scene::Pbr& pbr, const Color& base);

// The plain texture the path tracer reads a POV-Ray texture's finish and pigment from: the
// texture itself, or for patterned textures their first entry (layers are not combined).
const scene::Texture& base_texture(const scene::Texture& texture);

}  // namespace glint::render
