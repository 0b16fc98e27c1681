// The graph -> program compiler's working state, shared by the files that teach it nodes
// (compile_*.cpp): registers, constants, operations and the per-kind node tables.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "render/shader/program.h"

namespace glint::render::shader {

class Compiler;

// A value node's compile step: reads its inputs (Compiler::in), emits operations, sets its
// outputs (Compiler::set_out). A shader node's returns the closure tree node it makes.
using ValueNodeFn = void (*)(Compiler& c, int node);
using ShaderNodeFn = int (*)(Compiler& c, int node);

struct NodeTables {
    std::map<std::string, ValueNodeFn> values;
    std::map<std::string, ShaderNodeFn> shaders;
};
void add_basic_nodes(NodeTables& t);     // compile.cpp: inputs, converters, colour, vector
void add_texture_nodes(NodeTables& t);   // compile_textures.cpp
void add_shader_nodes(NodeTables& t);    // compile_closures.cpp: BSDFs, mixes, bump, normal map

class Compiler;

// Cycles' Bump over the registers given (height, the normal it bends, strength, distance):
// the new normal's register, or `normal` itself when the height is constant.
int bump_normal(Compiler& c, int height, int normal, int strength, int distance, bool invert);

class Compiler {
public:
    Compiler(const scene::ShaderGraph& graph, ShaderProgram& program, TextureCache* textures,
             Diagnostics& diag);

    const scene::ShaderNode& node(int index) const { return graph_.nodes[index]; }
    int node_count() const { return static_cast<int>(graph_.nodes.size()); }
    TextureCache* textures() const { return textures_; }
    Diagnostics& diag() { return diag_; }
    ShaderProgram& program() { return program_; }

    // The register holding input `id` of `node`, converted to `want` ('f' float, 'c' colour,
    // 'v' vector) as Cycles converts between socket types: a linked input compiles the node it
    // comes from first. A node without that input (another Blender version) gets `fallback`.
    int in(int node, const char* id, char want, float3 fallback = float3(0));
    // Whether the input exists and is linked.
    bool linked(int node, const char* id) const;
    // A constant register.
    int constant(float3 v);
    int constant(float v) { return constant(float3(v, 0, 0)); }
    // A fresh register for an operation's output.
    int fresh();
    void set_out(int node, const char* id, int reg);

    // Emits `op` (its fn, in, out, ints, floats and data filled): folded at once when every
    // input is constant and `foldable`, else appended to the program.
    void emit(const Op& op, bool foldable = true);
    // The closure tree node for a shader input, -1 when it is unlinked or gives nothing.
    int closure(int node, const char* id);
    int add_closure(const ClosureNode& n);
    bool varying(int reg) const { return reg >= 0 && !is_const_[reg]; }

    // Sequences of operations recorded apart (Bump's height): from mark() to the current end.
    size_t mark() const { return program_.ops_.size(); }
    std::vector<Op> cut(size_t from);
    // Keeps a table (ramps, curves) for the program's lifetime; ops point into it.
    const float* keep(const std::vector<float>& table);
    void program_keep(std::shared_ptr<const void> data) { program_.keep_.push_back(std::move(data)); }
    // The volume shader reads its object's grids (ShaderProgram::volume_grids).
    void reads_volume_grids() { program_.volume_grids_ = true; }

    // Node settings.
    std::string enum_prop(int node, const char* key, const std::string& fallback) const;
    double number_prop(int node, const char* key, double fallback) const;

    void unsupported(int node, const std::string& why = "");
    int compile_output();

    // The normal that unlinked Normal inputs read: N, or N bent by the material's
    // displacement (Cycles' bump_from_displacement).
    int normal() const { return normal_; }

private:
    int output_of(int node, const std::string& output);
    void compile_node(int node);
    int convert(int reg, scene::SocketType from, char want);

    const scene::ShaderGraph& graph_;
    ShaderProgram& program_;
    int normal_ = kRegN;
    TextureCache* textures_;
    Diagnostics& diag_;
    const NodeTables& tables_;
    std::vector<char> is_const_;
    std::vector<std::map<std::string, int>> outputs_;  // per node: output id -> register
    std::vector<int> shader_of_;                       // per node: its closure tree node
    std::vector<char> state_;                          // 0 new, 1 compiling, 2 done
    std::map<std::string, bool> warned_;
};

}  // namespace glint::render::shader
