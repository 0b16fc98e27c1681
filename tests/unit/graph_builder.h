// Shader node graphs built in tests: nodes by type with their inputs' values and links, as
// the add-on's exchange would give them (scene/shader_graph.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "scene/shader_graph.h"

namespace glint::testing {

// A small builder: nodes by type with their inputs' values and links.
struct GraphBuilder {
    scene::ShaderGraph g;
    int node(const std::string& type,
             std::vector<std::pair<std::string, scene::SocketType>> outs = {}) {
        scene::ShaderNode n;
        n.type = type;
        n.name = type + "." + std::to_string(g.nodes.size());
        for (auto& [id, t] : outs) {
            scene::ShaderOutput o;
            o.id = id;
            o.type = t;
            n.outputs.push_back(o);
        }
        g.nodes.push_back(n);
        return static_cast<int>(g.nodes.size()) - 1;
    }
    scene::ShaderInput& in(int node, const std::string& id, scene::SocketType type, double a,
                           double b = 0, double c = 0) {
        scene::ShaderInput i;
        i.id = id;
        i.type = type;
        i.value[0] = a;
        i.value[1] = b;
        i.value[2] = c;
        g.nodes[node].inputs.push_back(i);
        return g.nodes[node].inputs.back();
    }
    void link(int to, const std::string& input, int from, const std::string& output) {
        for (scene::ShaderInput& i : g.nodes[to].inputs)
            if (i.id == input) {
                i.link = {from, output};
                return;
            }
        scene::ShaderInput i;
        i.id = input;
        i.type = scene::SocketType::Shader;
        i.link = {from, output};
        g.nodes[to].inputs.push_back(i);
    }
    void prop(int node, const std::string& key, const std::string& text) {
        scene::ShaderProp p;
        p.text = text;
        p.is_text = true;
        g.nodes[node].props[key] = p;
    }
    int output() {
        const int o = node("ShaderNodeOutputMaterial");
        g.output = o;
        return o;
    }
    // An Emission whose colour comes from `from`'s `output`, into the output node.
    void emit(int from, const std::string& output) {
        const int e = node("ShaderNodeEmission", {{"Emission", scene::SocketType::Shader}});
        in(e, "Color", scene::SocketType::Rgba, 1, 1, 1);
        in(e, "Strength", scene::SocketType::Value, 1);
        link(e, "Color", from, output);
        link(output_node(), "Surface", e, "Emission");
    }
    int output_node() {
        if (g.output < 0) output();
        return g.output;
    }
};

}  // namespace glint::testing
