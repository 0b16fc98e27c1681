// Prints a scene::Scene as readable, stable text: what `glint ir scene.pov` shows, and what
// importer tests compare against. Every importer produces the same IR, so one printer serves.
#pragma once

#include <string>

#include "scene/scene.h"

namespace glint::formats {

std::string print_ir(const scene::Scene& scene);

}  // namespace glint::formats
