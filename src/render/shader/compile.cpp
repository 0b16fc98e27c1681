// The compiler's framework (compiler.h) and the program's interpreter (program.h). Nodes are
// taught in compile_nodes.cpp (inputs, converters, colour, vector), compile_textures.cpp and
// compile_closures.cpp.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "render/shader/color_nodes.h"
#include "render/shader/compiler.h"
#include "render/shader/converter_nodes.h"

namespace glint::render::shader {

namespace {

const NodeTables& node_tables() {
    static const NodeTables tables = [] {
        NodeTables t;
        add_basic_nodes(t);
        add_texture_nodes(t);
        add_shader_nodes(t);
        return t;
    }();
    return tables;
}

// Blender's node types that draw nothing and need no warning when they are left unconnected
// or reached (frames and the like never reach the compiler).
bool is_output(const std::string& type) {
    return type == "ShaderNodeOutputMaterial" || type == "ShaderNodeOutputWorld" ||
           type == "ShaderNodeOutputLight";
}

}  // namespace

bool ShaderProgram::has_holdout() const {
    for (const ClosureNode& n : closures_)
        if (n.kind == ClosureNode::Kind::Holdout) return true;
    return false;
}

void load_globals(const ShaderGlobals& sg, float3* r) {
    r[kRegP] = sg.P;
    r[kRegN] = sg.N;
    r[kRegNg] = sg.Ng;
    r[kRegI] = sg.I;
    r[kRegUV] = sg.uv;
    r[kRegGenerated] = sg.generated;
    r[kRegObject] = sg.object;
    r[kRegTangent] = sg.tangent;
    r[kRegUVTangent] = sg.uv_tangent;
    r[kRegBackfacing] = float3(sg.backfacing ? 1.0f : 0.0f, 0, 0);
    r[kRegObjectLocation] = sg.object_location;
    r[kRegObjectColor] = sg.object_color;
    r[kRegObjectInfo] = float3(sg.object_pass_index, sg.object_random, 0);
    r[kRegRay] = float3(sg.camera_ray ? 1.0f : 0.0f, sg.shadow_ray ? 1.0f : 0.0f, sg.ray_length);
    r[kRegRay2] = float3(sg.diffuse_ray ? 1.0f : 0.0f, sg.glossy_ray ? 1.0f : 0.0f,
                         sg.singular_ray ? 1.0f : 0.0f);
    r[kRegRay3] = float3(sg.reflection_ray ? 1.0f : 0.0f, sg.transmission_ray ? 1.0f : 0.0f,
                         static_cast<float>(sg.ray_depth));
    r[kRegDepths] = float3(static_cast<float>(sg.diffuse_depth),
                           static_cast<float>(sg.glossy_depth),
                           static_cast<float>(sg.transmission_depth));
    r[kRegTransparentDepth] = float3(static_cast<float>(sg.transparent_depth), 0, 0);
    r[kRegCamera] = sg.camera_position;
    r[kRegWindow] = sg.window;
    r[kRegViewDistance] = float3(sg.view_distance, 0, 0);
    r[kRegReflection] = sg.N * (2.0f * dot(sg.N, sg.I)) - sg.I;
}

Compiler::Compiler(const scene::ShaderGraph& graph, ShaderProgram& program,
                   TextureCache* textures, Diagnostics& diag)
    : graph_(graph),
      program_(program),
      textures_(textures),
      diag_(diag),
      tables_(node_tables()),
      outputs_(graph.nodes.size()),
      shader_of_(graph.nodes.size(), -2),
      state_(graph.nodes.size(), 0) {
    program_.init_.assign(kGlobalCount, float3());
    is_const_.assign(kGlobalCount, 0);
}

int Compiler::constant(float3 v) {
    // Constants are few; sharing equal ones keeps the register file small.
    for (size_t i = kGlobalCount; i < program_.init_.size(); ++i)
        if (is_const_[i] && program_.init_[i] == v) return static_cast<int>(i);
    program_.init_.push_back(v);
    is_const_.push_back(1);
    return static_cast<int>(program_.init_.size()) - 1;
}

int Compiler::fresh() {
    program_.init_.push_back(float3());
    is_const_.push_back(0);
    return static_cast<int>(program_.init_.size()) - 1;
}

void Compiler::set_out(int node, const char* id, int reg) { outputs_[node][id] = reg; }

void Compiler::emit(const Op& op, bool foldable) {
    bool all_const = foldable && op.sub_end == 0;
    for (int r : op.in)
        if (r >= 0 && !is_const_[r]) all_const = false;
    if (all_const) {
        // Folded: run now on the constant registers; the outputs become constants. (An op
        // reads only its own input registers, so the globals' zeros do not matter.)
        ShaderGlobals none;
        op.fn(op, program_.init_.data(), none);
        for (int r : op.out)
            if (r >= 0) is_const_[r] = 1;
        return;
    }
    for (int r : op.out)
        if (r >= 0) is_const_[r] = 0;
    program_.ops_.push_back(op);
}

std::vector<Op> Compiler::cut(size_t from) {
    std::vector<Op> ops(program_.ops_.begin() + static_cast<std::ptrdiff_t>(from),
                        program_.ops_.end());
    program_.ops_.resize(from);
    return ops;
}

const float* Compiler::keep(const std::vector<float>& table) {
    program_.tables_.push_back(std::make_unique<std::vector<float>>(table));
    return program_.tables_.back()->data();
}

std::string Compiler::enum_prop(int node, const char* key, const std::string& fallback) const {
    const scene::ShaderProp* p = graph_.nodes[node].prop(key);
    return p && p->is_text ? p->text : fallback;
}

double Compiler::number_prop(int node, const char* key, double fallback) const {
    const scene::ShaderProp* p = graph_.nodes[node].prop(key);
    return p && !p->is_text && !p->numbers.empty() ? p->numbers[0] : fallback;
}

void Compiler::unsupported(int node, const std::string& why) {
    const scene::ShaderNode& n = graph_.nodes[node];
    const std::string key = n.type + "|" + why;
    if (warned_[key]) return;
    warned_[key] = true;
    std::string what = "node '" + n.name + "' (" + n.type + ")";
    diag_.warning(graph_.loc, "'" + graph_.name + "': " + what +
                                  (why.empty() ? " is not supported yet: its outputs are "
                                                 "their defaults (zero), it adds no shader"
                                               : ": " + why));
}

bool Compiler::linked(int node, const char* id) const {
    const scene::ShaderInput* in = graph_.nodes[node].input(id);
    return in && in->link.linked();
}

int Compiler::convert(int reg, scene::SocketType from, char want) {
    using S = scene::SocketType;
    const bool from_float = from == S::Value || from == S::Int || from == S::Boolean;
    const bool from_color = from == S::Rgba;
    if (want == 'f') {
        if (from_float) return reg;
        Op op;
        op.in[0] = reg;
        op.out[0] = fresh();
        if (from_color)
            op.fn = [](const Op& o, float3* r, const ShaderGlobals&) {
                r[o.out[0]] = float3(rgb_to_bw_node(r[o.in[0]]), 0, 0);
            };
        else
            op.fn = [](const Op& o, float3* r, const ShaderGlobals&) {
                const float3 v = r[o.in[0]];
                r[o.out[0]] = float3((v.x + v.y + v.z) * (1.0f / 3.0f), 0, 0);
            };
        emit(op);
        return op.out[0];
    }
    if (from_float) {
        Op op;
        op.in[0] = reg;
        op.out[0] = fresh();
        op.fn = [](const Op& o, float3* r, const ShaderGlobals&) {
            r[o.out[0]] = float3(r[o.in[0]].x);
        };
        emit(op);
        return op.out[0];
    }
    return reg;  // colour <-> vector: the same three numbers
}

int Compiler::in(int node, const char* id, char want, float3 fallback) {
    const scene::ShaderInput* in = graph_.nodes[node].input(id);
    if (!in) return constant(fallback);
    if (in->link.linked()) {
        const int from = in->link.node;
        const int reg = output_of(from, in->link.output);
        scene::SocketType type = scene::SocketType::Value;
        for (const scene::ShaderOutput& o : graph_.nodes[from].outputs)
            if (o.id == in->link.output) type = o.type;
        if (type == scene::SocketType::Shader) {
            unsupported(node, "input '" + std::string(id) + "' is fed by a shader: read as 0");
            return constant(float3(0));
        }
        return convert(reg, type, want);
    }
    const double* v = in->value;
    switch (in->type) {
        case scene::SocketType::Rgba:
        case scene::SocketType::Vector:
            return convert(constant(float3(static_cast<float>(v[0]), static_cast<float>(v[1]),
                                           static_cast<float>(v[2]))),
                           in->type, want);
        default:
            return convert(constant(static_cast<float>(v[0])), scene::SocketType::Value, want);
    }
}

int Compiler::output_of(int node, const std::string& output) {
    compile_node(node);
    auto it = outputs_[node].find(output);
    if (it != outputs_[node].end()) return it->second;
    return constant(float3(0));
}

void Compiler::compile_node(int node) {
    if (state_[node] == 2) return;
    if (state_[node] == 1) {
        unsupported(node, "is part of a cycle of links: cut there");
        return;
    }
    state_[node] = 1;
    const scene::ShaderNode& n = graph_.nodes[node];
    auto v = tables_.values.find(n.type);
    if (v != tables_.values.end()) {
        v->second(*this, node);
    } else if (tables_.shaders.find(n.type) == tables_.shaders.end() && !is_output(n.type)) {
        unsupported(node);
    }
    state_[node] = 2;
}

int Compiler::closure(int node, const char* id) {
    const scene::ShaderInput* in = graph_.nodes[node].input(id);
    if (!in || !in->link.linked()) return -1;
    const int from = in->link.node;
    if (shader_of_[from] != -2) return shader_of_[from];
    shader_of_[from] = -1;  // a cycle through shaders ends here
    const scene::ShaderNode& n = graph_.nodes[from];
    auto s = tables_.shaders.find(n.type);
    if (s == tables_.shaders.end()) {
        // A value node plugged into a shader socket: Cycles renders it as emission of its
        // colour. Anything else glint lacks is warned.
        if (tables_.values.count(n.type) && !n.outputs.empty()) {
            ClosureNode e;
            e.kind = ClosureNode::Kind::Emission;
            e.in[0] = output_of(from, in->link.output);
            e.in[1] = constant(1.0f);
            shader_of_[from] = add_closure(e);
        } else {
            compile_node(from);  // warns
            unsupported(from);
        }
        return shader_of_[from];
    }
    shader_of_[from] = s->second(*this, from);
    return shader_of_[from];
}

int Compiler::add_closure(const ClosureNode& n) {
    program_.closures_.push_back(n);
    return static_cast<int>(program_.closures_.size()) - 1;
}

int Compiler::compile_output() {
    const int out = graph_.output;
    if (out < 0) return -1;
    if (linked(out, "Displacement")) {
        // Displacement as bump (Cycles' "Bump Only", its default): the height is the
        // displacement along N, and the bent normal is what every unlinked Normal reads.
        const int d = in(out, "Displacement", 'v');
        const int h = fresh();
        Op op;
        op.fn = [](const Op& o, float3* r, const ShaderGlobals&) {
            r[o.out[0]] = float3(dot(r[o.in[0]], r[o.in[1]]), 0, 0);
        };
        op.in[0] = d;
        op.in[1] = kRegN;
        op.out[0] = h;
        emit(op, false);
        normal_ = bump_normal(*this, h, kRegN, constant(1.0f), constant(1.0f), false);
    }
    return closure(out, "Surface");
}

std::unique_ptr<ShaderProgram> ShaderProgram::compile(const scene::ShaderGraph& graph,
                                                      TextureCache* textures,
                                                      Diagnostics& diag) {
    auto program = std::make_unique<ShaderProgram>();
    program->name_ = graph.name;
    Compiler c(graph, *program, textures, diag);
    program->root_ = c.compile_output();
    program->normal_reg_ = c.normal();
    if (graph.output >= 0) program->volume_root_ = c.closure(graph.output, "Volume");
    program->main_end_ = program->ops_.size();
    program->varying_ops_ = static_cast<int>(program->ops_.size());
    for (const ClosureNode& n : program->closures_)
        for (int r : n.in)
            if (c.varying(r)) program->closure_varying_ = true;
    for (const ClosureNode& n : program->closures_)
        if (c.varying(n.fac)) program->closure_varying_ = true;
    // Transparency, from the surface's closures (a Mix's factor is not followed: any mixed-in
    // transparency counts).
    {
        auto opaque_reg = [&](int reg, float opaque_value) {
            return reg >= 0 && !c.varying(reg) &&
                   program->init_[static_cast<size_t>(reg)].x == opaque_value;
        };
        bool transparent = program->root_ < 0 && program->volume_root_ >= 0;
        std::vector<int> stack{program->root_};
        std::vector<bool> visited(program->closures_.size(), false);
        while (!stack.empty() && !transparent) {
            const int i = stack.back();
            stack.pop_back();
            if (i < 0 || visited[static_cast<size_t>(i)]) continue;
            visited[static_cast<size_t>(i)] = true;
            const ClosureNode& n = program->closures_[static_cast<size_t>(i)];
            if (n.kind == ClosureNode::Kind::Transparent) {
                const int col = n.in[0];
                transparent = !(col >= 0 && !c.varying(col) &&
                                program->init_[static_cast<size_t>(col)] == float3(0.0f));
            } else if (n.kind == ClosureNode::Kind::Bsdf &&
                       n.bsdf == ClosureKind::Principled && n.in[ClosureNode::kAlpha] >= 0) {
                transparent = !opaque_reg(n.in[ClosureNode::kAlpha], 1.0f);
            }
            stack.push_back(n.a);
            stack.push_back(n.b);
        }
        program->can_be_transparent_ = transparent;
    }
    // Constant but for the normal: no operation varies, and the only varying values the
    // surface's closures read are N itself (unlinked Normal inputs, no bump) and the default
    // tangent where walk() leaves it unread (no anisotropy, not a Glossy BSDF).
    if (program->varying_ops_ == 0 && program->normal_reg_ == kRegN) {
        bool ok = true;
        std::vector<int> stack{program->root_};
        std::vector<bool> visited(program->closures_.size(), false);
        while (!stack.empty() && ok) {
            const int i = stack.back();
            stack.pop_back();
            if (i < 0 || visited[static_cast<size_t>(i)]) continue;
            visited[static_cast<size_t>(i)] = true;
            const ClosureNode& n = program->closures_[static_cast<size_t>(i)];
            ok = !c.varying(n.fac);
            const int aniso = n.in[ClosureNode::kAnisotropy];
            const bool tangent_unread =
                n.bsdf != ClosureKind::Glossy &&
                (aniso < 0 || (!c.varying(aniso) &&
                               program->init_[static_cast<size_t>(aniso)].x == 0.0f));
            for (int slot = 0; slot < ClosureNode::kSlots && ok; ++slot) {
                const int r = n.in[slot];
                if (!c.varying(r)) continue;
                const bool normal = (slot == ClosureNode::kNormal ||
                                     slot == ClosureNode::kClearcoatNormal) && r == kRegN;
                const bool tangent = slot == ClosureNode::kTangent && tangent_unread;
                ok = n.kind == ClosureNode::Kind::Bsdf && (normal || tangent);
            }
            stack.push_back(n.a);
            stack.push_back(n.b);
        }
        program->normal_only_ = ok && !program->constant();
    }
    // The volume varies where any value its closures read does.
    std::vector<int> todo{program->volume_root_};
    std::vector<bool> seen(program->closures_.size(), false);
    while (!todo.empty()) {
        const int i = todo.back();
        todo.pop_back();
        if (i < 0 || seen[static_cast<size_t>(i)]) continue;
        seen[static_cast<size_t>(i)] = true;
        const ClosureNode& n = program->closures_[static_cast<size_t>(i)];
        for (int r : n.in) program->volume_varying_ = program->volume_varying_ || c.varying(r);
        program->volume_varying_ = program->volume_varying_ || c.varying(n.fac);
        todo.push_back(n.a);
        todo.push_back(n.b);
    }
    return program;
}

void ShaderProgram::run(const Op* begin, const Op* end, float3* regs,
                        const ShaderGlobals& sg) const {
    for (const Op* op = begin; op != end; ++op) op->fn(*op, regs, sg);
}

namespace {
Color to_color(float3 v) { return Color(v.x, v.y, v.z); }
}  // namespace

void ShaderProgram::walk(int index, const Color& weight, const float3* r,
                         ClosureList* out) const {
    if (index < 0 || weight.is_black()) return;
    const ClosureNode& n = closures_[static_cast<size_t>(index)];
    switch (n.kind) {
        case ClosureNode::Kind::Mix: {
            const float fac = std::clamp(r[n.fac].x, 0.0f, 1.0f);
            walk(n.a, weight * (1.0 - fac), r, out);
            walk(n.b, weight * static_cast<double>(fac), r, out);
            return;
        }
        case ClosureNode::Kind::Add:
            walk(n.a, weight, r, out);
            walk(n.b, weight, r, out);
            return;
        case ClosureNode::Kind::Emission:
            out->emission += weight * to_color(r[n.in[0]]) * static_cast<double>(r[n.in[1]].x);
            return;
        case ClosureNode::Kind::Transparent:
            out->transparent += weight * to_color(r[n.in[0]]);
            return;
        case ClosureNode::Kind::Holdout:
            out->holdout += weight;
            return;
        case ClosureNode::Kind::Volume: return;  // only the volume shader reads them
        case ClosureNode::Kind::Bsdf: break;
    }
    // A BSDF: its inputs by slot.
    using S = ClosureNode;
    auto value = [&](int slot, double fallback) {
        return n.in[slot] >= 0 ? static_cast<double>(r[n.in[slot]].x) : fallback;
    };
    auto vec = [&](int slot) { return n.in[slot] >= 0 ? r[n.in[slot]].to_vec3() : Vec3(); };
    Closure c;
    c.kind = n.bsdf;
    c.distribution = n.distribution;
    c.glossy = n.glossy;
    Color w = weight;
    const bool principled = n.bsdf == ClosureKind::Principled;
    if (principled && n.in[S::kAlpha] >= 0) {
        // Alpha: the uncovered part passes straight through (Cycles' transparent closure).
        const double alpha = std::clamp(value(S::kAlpha, 1), 0.0, 1.0);
        if (alpha < 1) out->transparent += weight * (1 - alpha);
        w = weight * alpha;
        if (n.in[S::kEmission] >= 0)
            out->emission += w * to_color(r[n.in[S::kEmission]]) * value(S::kEmissionStrength, 1);
    }
    c.weight = w;
    c.color = n.in[S::kColor] >= 0 ? to_color(r[n.in[S::kColor]]) : Color(1, 1, 1);
    c.N = vec(S::kNormal);
    c.n_from_globals = n.in[S::kNormal] == kRegN;
    c.roughness = std::clamp(value(S::kRoughness, 0), 0.0, 1.0);
    if (n.bsdf == ClosureKind::Velvet) c.roughness = value(S::kRoughness, 1);  // sigma
    c.ior = std::max(value(S::kIor, 1.45), 1e-5);
    c.metallic = std::clamp(value(S::kMetallic, 0), 0.0, 1.0);
    c.specular = std::max(value(S::kSpecular, 0.5), 0.0);
    c.transmission = std::clamp(value(S::kTransmission, 0), 0.0, 1.0);
    c.specular_tint = value(S::kSpecularTint, 0);
    c.anisotropy = value(S::kAnisotropy, 0);
    c.sheen = value(S::kSheen, 0);
    c.sheen_tint = value(S::kSheenTint, 0.5);
    c.clearcoat = value(S::kClearcoat, 0);
    c.clearcoat_roughness = value(S::kClearcoatRoughness, 0.03);
    c.clearcoat_N = vec(S::kClearcoatNormal);
    c.clearcoat_n_from_globals = n.in[S::kClearcoatNormal] == kRegN;
    c.transmission_roughness = value(S::kTransmissionRoughness, 0);
    c.smooth = value(S::kSmooth, 0);
    if (principled || n.bsdf == ClosureKind::Subsurface) {
        // Principled: the amount; Subsurface Scattering: the scale.
        c.subsurface = value(S::kSubsurface, n.bsdf == ClosureKind::Subsurface ? 1 : 0);
        if (n.in[S::kSubsurfaceRadius] >= 0)
            c.subsurface_radius = to_color(r[n.in[S::kSubsurfaceRadius]]);
        if (n.in[S::kSubsurfaceColor] >= 0)
            c.subsurface_color = to_color(r[n.in[S::kSubsurfaceColor]]);
        c.subsurface_ior = value(S::kSubsurfaceIor, 1.4);
        c.subsurface_anisotropy = value(S::kSubsurfaceAnisotropy, 0);
        c.subsurface_method = n.subsurface;
    }
    if (n.in[S::kTangent] >= 0 && (c.anisotropy != 0 || n.bsdf == ClosureKind::Glossy)) {
        c.T = vec(S::kTangent);
        // Rotation turns the tangent about the normal by that many full turns.
        const double turns = value(S::kRotation, 0);
        const Vec3 axis = length_squared(c.N) > 0 ? normalize(c.N) : Vec3();
        if (turns != 0 && length_squared(axis) > 0) {
            const double a = turns * 2 * kPi, ca = std::cos(a), sa = std::sin(a);
            c.T = c.T * ca + cross(axis, c.T) * sa + axis * (dot(axis, c.T) * (1 - ca));
        }
    }
    // Cycles' sample weight: the closure's weight with its colour multiplied in (a Principled
    // BSDF keeps its specular lobe whatever its base colour).
    const Color sw = principled ? w : w * c.color;
    c.sample_weight = std::fabs((sw.r + sw.g + sw.b) / 3);
    // A Principled BSDF without any lobe (black base, no metal, specular, transmission or
    // clearcoat) gets no closure in Cycles 3.4: it must take no samples from the rest
    // (transparency included).
    // (Its diffuse part is the base colour mixed with the subsurface colour.)
    if (principled && c.metallic == 0 && c.specular == 0 && c.transmission == 0 &&
        !(c.clearcoat > 1e-5)) {
        const double ss = c.subsurface;
        if ((c.subsurface_color * ss + c.color * (1 - ss)).is_black()) return;
    }
    if (c.sample_weight > 0) out->add(c);
}

void ShaderProgram::rerun(size_t end, float3* regs, const ShaderGlobals& sg) const {
    load_globals(sg, regs);
    run(ops_.data(), ops_.data() + std::min(end, ops_.size()), regs, sg);
}

void ShaderProgram::evaluate(const ShaderGlobals& sg, ClosureList* out) const {
    *out = ClosureList();
    thread_local std::vector<float3> regs;
    regs.assign(init_.begin(), init_.end());
    load_globals(sg, regs.data());
    run(ops_.data(), ops_.data() + main_end_, regs.data(), sg);
    out->N = regs[static_cast<size_t>(normal_reg_)].to_vec3();
    walk(root_, Color(1, 1, 1), regs.data(), out);
    // A material with a volume and no surface has none to stop at (Cycles'
    // SD_HAS_ONLY_VOLUME): rays pass its boundary.
    if (root_ < 0 && volume_root_ >= 0) out->transparent = Color(1, 1, 1);
}

void ShaderProgram::evaluate_volume(const ShaderGlobals& sg, VolumeClosures* out) const {
    *out = VolumeClosures();
    if (volume_root_ < 0) return;
    thread_local std::vector<float3> regs;
    regs.assign(init_.begin(), init_.end());
    load_globals(sg, regs.data());
    run(ops_.data(), ops_.data() + main_end_, regs.data(), sg);
    walk_volume(volume_root_, Color(1, 1, 1), regs.data(), sg, out);
}

void ShaderProgram::walk_volume(int index, const Color& weight, const float3* r,
                                const ShaderGlobals& sg, VolumeClosures* out) const {
    // svm_node_closure_volume and svm_node_principled_volume (Cycles 3.4, kernel/svm/
    // closure.h), in the volume shader's context: BSDFs, transparency and holdouts do nothing
    // there.
    if (index < 0 || weight.is_black()) return;
    const ClosureNode& n = closures_[static_cast<size_t>(index)];
    switch (n.kind) {
        case ClosureNode::Kind::Mix: {
            const float fac = std::clamp(r[n.fac].x, 0.0f, 1.0f);
            walk_volume(n.a, weight * (1.0 - fac), r, sg, out);
            walk_volume(n.b, weight * static_cast<double>(fac), r, sg, out);
            return;
        }
        case ClosureNode::Kind::Add:
            walk_volume(n.a, weight, r, sg, out);
            walk_volume(n.b, weight, r, sg, out);
            return;
        case ClosureNode::Kind::Emission:
            out->emission += weight * to_color(r[n.in[0]]) * static_cast<double>(r[n.in[1]].x);
            return;
        case ClosureNode::Kind::Volume: break;
        default: return;
    }
    using S = ClosureNode;
    constexpr double kCutoff = 1e-5;  // CLOSURE_WEIGHT_CUTOFF
    auto value = [&](int slot, double fallback) {
        return n.in[slot] >= 0 ? static_cast<double>(r[n.in[slot]].x) : fallback;
    };
    auto colour = [&](int slot, const Color& fallback) {
        return n.in[slot] >= 0 ? to_color(r[n.in[slot]]) : fallback;
    };
    // The mix weight scales the density (Cycles keeps it a float: the channels' mean).
    const double mix = (weight.r + weight.g + weight.b) / 3;
    double density = mix * std::max(value(S::kDensity, 1), 0.0);
    Color color = colour(S::kColor, Color(0.5, 0.5, 0.5));
    // Principled Volume's grids (Volume objects), where the object has them, each looked up
    // only where Cycles looks it up.
    Vec3 gv;
    auto grid = [&](int k) {
        return n.grids[k] && sg.grids && sg.grids->grid(*n.grids[k], sg.P.to_vec3(), &gv);
    };
    if (density > kCutoff && grid(0)) density = std::max(density * gv.x, 0.0);
    if (density > kCutoff && grid(1)) color = color * Color(gv.x, gv.y, gv.z);
    auto add_lobe = [&](const Color& sigma_s) {
        if (out->count == VolumeClosures::kMax) return;
        double g = value(S::kAnisotropy, 0);
        g = std::copysign(std::min(std::fabs(g), 1.0 - 1e-3), g);  // no delta lobes
        out->lobes[out->count++] = {sigma_s, g};
    };
    switch (n.volume) {
        case S::VolumeKind::Scatter:
            add_lobe(color * density);
            out->extinction += color * density;
            return;
        case S::VolumeKind::Absorption:
            out->extinction += (Color(1, 1, 1) - color) * density;
            return;
        case S::VolumeKind::Principled: break;
    }
    if (density > kCutoff) {
        add_lobe(color * density);
        const Color ac = colour(S::kAbsorptionColor, Color(0, 0, 0));
        auto one = [](double c, double a) {
            return std::max(1 - c, 0.0) * std::max(1 - std::sqrt(std::max(a, 0.0)), 0.0);
        };
        const Color absorption(one(color.r, ac.r), one(color.g, ac.g), one(color.b, ac.b));
        out->extinction += (color + absorption) * density;
    }
    // Emission and blackbody light are not scaled by the density or the mix weight.
    const double emission = value(S::kEmissionStrength, 0);
    if (emission > kCutoff) out->emission += colour(S::kEmission, Color(1, 1, 1)) * emission;
    const double blackbody = value(S::kBlackbody, 0);
    if (blackbody > kCutoff) {
        double t = std::max(value(S::kTemperature, 1000), 0.0);
        if (grid(2)) t *= std::max(gv.x, 0.0);
        const double t4 = (t * t) * (t * t);
        const double sigma = 5.670373e-8 * 1e-6 / kPi;  // Stefan-Boltzmann, per steradian
        const double intensity = sigma * (1 + (t4 - 1) * blackbody);
        if (intensity > kCutoff) {
            const float3 bb = blackbody_rec709(static_cast<float>(t));
            out->emission += colour(S::kBlackbodyTint, Color(1, 1, 1)) * intensity *
                             Color(bb.x, bb.y, bb.z);
        }
    }
}

}  // namespace glint::render::shader
