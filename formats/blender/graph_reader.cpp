#include "formats/blender/graph_reader.h"

#include <filesystem>

namespace glint::blender {

namespace {

scene::SocketType socket_type(const std::string& t) {
    using S = scene::SocketType;
    if (t == "VALUE") return S::Value;
    if (t == "RGBA") return S::Rgba;
    if (t == "VECTOR") return S::Vector;
    if (t == "SHADER") return S::Shader;
    if (t == "INT") return S::Int;
    if (t == "BOOLEAN") return S::Boolean;
    if (t == "STRING") return S::String;
    return S::Other;
}

scene::ShaderProp read_prop(const JsonReader& r) {
    scene::ShaderProp p;
    const Json& j = r.json();
    if (j.is_string()) {
        p.text = j.get<std::string>();
        p.is_text = true;
    } else if (j.is_boolean()) {
        p.numbers = {j.get<bool>() ? 1.0 : 0.0};
    } else if (j.is_number()) {
        p.numbers = {j.get<double>()};
    } else if (j.is_array()) {
        for (const Json& e : j)
            if (e.is_number()) p.numbers.push_back(e.get<double>());
            else if (e.is_boolean()) p.numbers.push_back(e.get<bool>() ? 1.0 : 0.0);
    }
    return p;
}

std::vector<float> read_table(const JsonReader& r, size_t width) {
    std::vector<float> out;
    const Json& j = r.json();
    if (!j.is_array()) r.fail("expected an array");
    out.reserve(j.size() * width);
    for (size_t i = 0; i < j.size(); ++i) {
        const JsonReader e = r.at(i);
        if (width == 1) {
            out.push_back(static_cast<float>(e.number()));
            continue;
        }
        const std::vector<double> v = e.numbers();
        if (v.size() < width) e.fail("expected " + std::to_string(width) + " numbers");
        for (size_t k = 0; k < width; ++k) out.push_back(static_cast<float>(v[k]));
    }
    return out;
}

}  // namespace

scene::ShaderGraph read_graph(const JsonReader& r, const std::string& name,
                              const std::string& base_dir) {
    scene::ShaderGraph g;
    g.name = name;
    const JsonReader nodes = r.at("nodes");
    if (!nodes.is_array()) nodes.fail("expected an array of nodes");
    g.nodes.resize(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) {
        const JsonReader n = nodes.at(i);
        scene::ShaderNode& node = g.nodes[i];
        node.type = n.at("type").string();
        node.name = n.string("name", node.type);
        if (n.has("outputs"))
            for (size_t k = 0; k < n.at("outputs").size(); ++k) {
                const JsonReader o = n.at("outputs").at(k);
                scene::ShaderOutput out;
                out.id = o.at("id").string();
                out.type = socket_type(o.string("type", ""));
                if (o.has("value")) {
                    const Json& v = o.at("value").json();
                    if (v.is_number()) out.value[0] = v.get<double>();
                    else if (v.is_array())
                        for (size_t c = 0; c < v.size() && c < 4; ++c)
                            if (v[c].is_number()) out.value[c] = v[c].get<double>();
                }
                node.outputs.push_back(std::move(out));
            }
        if (n.has("props") && n.at("props").json().is_object()) {
            const JsonReader props = n.at("props");
            for (auto it = props.json().begin(); it != props.json().end(); ++it) {
                const JsonReader p(it.value(), props.path() + "." + it.key(), nullptr);
                if (it.key() == "ramp" && it.value().is_object()) {
                    const JsonReader ramp = props.at("ramp");
                    node.ramp = read_table(ramp.at("table"), 4);
                    if (node.ramp.size() != 256 * 4) ramp.at("table").fail("expected 256 entries");
                    for (const char* key : {"interpolation", "color_mode", "hue_interpolation"})
                        if (ramp.has(key)) node.props[key] = read_prop(ramp.at(key));
                } else if (it.key() == "curves" && it.value().is_object()) {
                    const JsonReader c = props.at("curves");
                    const std::vector<double> range = c.at("range").numbers();
                    if (range.size() < 2) c.at("range").fail("expected [min, max]");
                    node.curve_min = range[0];
                    node.curve_max = range[1];
                    node.curve_extrapolate = c.boolean("extrapolate", true);
                    const JsonReader tables = c.at("tables");
                    for (size_t k = 0; k < tables.size(); ++k)
                        node.curves.push_back(read_table(tables.at(k), 1));
                } else if (it.key() == "image" && it.value().is_object()) {
                    const JsonReader im = props.at("image");
                    node.has_image = true;
                    std::string path = im.string("path", "");
                    if (!path.empty() && std::filesystem::path(path).is_relative())
                        path = (std::filesystem::path(base_dir) / path).string();
                    node.image.path = path;
                    node.image.colorspace = im.string("colorspace", "sRGB");
                    node.image.alpha_mode = im.string("alpha_mode", "STRAIGHT");
                    node.image.is_float = im.boolean("is_float", false);
                } else {
                    node.props[it.key()] = read_prop(p);
                }
            }
        }
    }
    // Inputs after every node's outputs are known, so links can be checked.
    for (size_t i = 0; i < nodes.size(); ++i) {
        const JsonReader n = nodes.at(i);
        scene::ShaderNode& node = g.nodes[i];
        if (!n.has("inputs")) continue;
        const JsonReader ins = n.at("inputs");
        for (size_t k = 0; k < ins.size(); ++k) {
            const JsonReader in = ins.at(k);
            scene::ShaderInput s;
            s.id = in.at("id").string();
            s.type = socket_type(in.string("type", ""));
            s.enabled = in.boolean("enabled", true);
            if (in.has("value")) {
                const Json& v = in.at("value").json();
                if (v.is_number() || v.is_boolean()) {
                    s.value[0] = in.at("value").number();
                } else if (v.is_string()) {
                    s.text = in.at("value").string();
                } else if (v.is_array()) {
                    const std::vector<double> nums = in.at("value").numbers();
                    for (size_t c = 0; c < nums.size() && c < 4; ++c) s.value[c] = nums[c];
                }
            }
            if (in.has("link") && !in.at("link").is_null()) {
                const JsonReader l = in.at("link");
                const int from = l.at(size_t{0}).integer();
                const std::string out = l.at(size_t{1}).string();
                if (from < 0 || from >= static_cast<int>(g.nodes.size()))
                    l.fail("links to node " + std::to_string(from) + ", which does not exist");
                bool found = false;
                for (const scene::ShaderOutput& o : g.nodes[from].outputs) found |= o.id == out;
                if (!found)
                    l.fail("links to output '" + out + "' of node '" + g.nodes[from].name +
                           "', which has no such output");
                s.link = {from, out};
            }
            node.inputs.push_back(std::move(s));
        }
    }
    g.output = r.integer("output", -1);
    if (g.output >= static_cast<int>(g.nodes.size())) r.at("output").fail("no such node");
    return g;
}

}  // namespace glint::blender
