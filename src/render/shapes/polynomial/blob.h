// The blob by the plain algorithm: every query meets every element and every stretch between
// chord ends is solved, without make_blob()'s (shapes.h) bounding hierarchy and root-free
// stretch test. The unit tests' reference for make_blob().
#pragma once

#include <memory>

#include "render/shapes/primitive.h"
#include "scene/shape.h"

namespace glint::render {

std::unique_ptr<Primitive> make_blob_exhaustive(const scene::Blob& s, const char** why);

}  // namespace glint::render
