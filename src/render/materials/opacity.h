// Whether a POV-Ray texture can ever let light through (a filter or transmit somewhere in its
// pigments, or an image map): the Whitted shadow walk filters light only through such
// surfaces, and the geometry answers the others with a plain any-hit query.
#pragma once

#include "scene/texture.h"

namespace glint::render {

bool pigment_can_be_transparent(const scene::Pigment& p);
// A plain texture's layers filter only what the bottom lets through: all must be see-through.
bool texture_can_be_transparent(const scene::Texture& t);

}  // namespace glint::render
