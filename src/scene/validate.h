// Rejects what cannot be rendered: negative radii, degenerate cameras, dangling ids,
// non-finite numbers. Throws glint::Error(ErrorKind::Scene) with the culprit's FileLoc.
#pragma once

#include "scene/scene.h"

namespace glint::scene {

void validate(const Scene& scene);

}  // namespace glint::scene
