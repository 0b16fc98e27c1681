// The text primitive: POV-Ray's TrueType text object (glyph outlines extruded along z), built
// from the IR's scene::Text by the object tree.
#pragma once

#include <memory>

#include "render/shapes/primitive.h"
#include "scene/shape.h"

namespace glint::render {

// nullptr with `*why` set for input that makes no shape; throws glint::Error (MissingFile)
// at `loc` when the font cannot be read.
std::unique_ptr<Primitive> make_text(const scene::Text& s, const FileLoc& loc, const char** why);

}  // namespace glint::render
