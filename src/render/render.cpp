#include "render/render.h"

#include "core/error.h"

namespace glint::render {
RenderResult render(const scene::Scene&, const RenderOptions&, Diagnostics&) {
    throw Error(ErrorKind::Render, {}, "renderer not written yet");
}
}  // namespace glint::render
