// Shader graphs of the exchange (FORMAT.md "materials and shader graphs") into the IR.
#pragma once

#include "formats/blender/json_reader.h"
#include "scene/shader_graph.h"

namespace glint::blender {

// Reads one graph; `base_dir` resolves relative image paths. Links are checked: a link to a
// node or output that does not exist fails naming the input.
scene::ShaderGraph read_graph(const JsonReader& r, const std::string& name,
                              const std::string& base_dir);

}  // namespace glint::blender
