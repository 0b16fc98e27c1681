// The objects of POV-Ray's object patterns (Scene::pattern_objects) built as the renderer
// builds scene objects, answering PatternKind::Object's inside test. Made only for scenes
// that have such patterns.
#pragma once

#include <memory>
#include <vector>

#include "core/log.h"
#include "render/textures/pattern.h"
#include "scene/scene.h"

namespace glint::render {



// Null when the scene has no object pattern.
std::unique_ptr<PatternObjects> build_pattern_objects(const scene::Scene& scene,
                                                      Diagnostics& diag);

}  // namespace glint::render
