// Whether a POV-Ray texture can ever let light through (a filter or transmit somewhere in its
// pigments, or an image map): the Whitted shadow walk filters light only through such
// surfaces, and the geometry answers the others with a plain any-hit query.
#pragma once

#include "scene/texture.h"

namespace glint::render {

class TextureCache;

// An image map lets light through where it has filter all, transmit all or an alpha channel,
// and beyond the image with `once`;
// which images have one the loaded `textures` tell (without them every image map may).
bool pigment_can_be_transparent(const scene::Pigment& p, const TextureCache* textures);
// A plain texture's layers filter only what the bottom lets through: all must be see-through.
bool texture_can_be_transparent(const scene::Texture& t, const TextureCache* textures);

}  // namespace glint::render
