// Shader node graphs as plain data: Blender's node trees as the add-on exports them
// (formats/blender/FORMAT.md), node groups already flattened, reroutes followed and muted nodes
// replaced by their internal links. The renderer compiles a graph into a flat program
// (render/shader/); the IR only holds what Blender holds.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/error.h"

namespace glint::scene {

// Blender's socket types.
enum class SocketType { Value, Rgba, Vector, Shader, Int, Boolean, String, Other };

// A link into one of another node's outputs, by index into ShaderGraph::nodes and the output's
// identifier.
struct ShaderLink {
    int node = -1;
    std::string output;
    bool linked() const { return node >= 0; }
};

struct ShaderInput {
    std::string id;  // Blender's socket identifier, unique within the node
    SocketType type = SocketType::Value;
    double value[4] = {0, 0, 0, 0};  // the unlinked value (float: [0]; colours: rgba)
    std::string text;                // a String socket's value (attribute names)
    bool enabled = true;
    ShaderLink link;
};

struct ShaderOutput {
    std::string id;
    SocketType type = SocketType::Value;
    double value[4] = {0, 0, 0, 0};  // its own value (Value and RGB nodes keep theirs here)
};

// A node's own settings: enums as their Python identifier strings, numbers and booleans
// (1/0), vectors; baked tables for ramps and curves.
struct ShaderProp {
    std::string text;            // enums and strings
    std::vector<double> numbers;  // numbers, booleans, vectors
    bool is_text = false;
};

struct ShaderImage {
    std::string path;        // a file on disk (the add-on saves packed and generated images)
    std::string colorspace;  // Blender's colour space name ("sRGB", "Non-Color", ...)
    std::string alpha_mode;  // "STRAIGHT", "PREMUL", "CHANNEL_PACKED", "NONE"
    bool is_float = false;
};

struct ShaderNode {
    std::string type;  // Blender's bl_idname, e.g. "ShaderNodeTexNoise"
    std::string name;  // the node's name in its tree (messages)
    std::vector<ShaderInput> inputs;
    std::vector<ShaderOutput> outputs;
    std::map<std::string, ShaderProp> props;
    // ColorRamp's table (256 rgba, row-major) and the curve nodes' tables with their range.
    std::vector<float> ramp;
    std::vector<std::vector<float>> curves;
    double curve_min = 0, curve_max = 1;
    bool curve_extrapolate = true;
    ShaderImage image;
    bool has_image = false;

    const ShaderInput* input(const std::string& id) const {
        for (const ShaderInput& in : inputs)
            if (in.id == id) return &in;
        return nullptr;
    }
    const ShaderProp* prop(const std::string& key) const {
        auto it = props.find(key);
        return it == props.end() ? nullptr : &it->second;
    }
};

struct ShaderGraph {
    std::string name;  // the material, world or light it belongs to (messages)
    std::vector<ShaderNode> nodes;
    int output = -1;  // the active output node, -1 when there is none
    FileLoc loc;
};

}  // namespace glint::scene
