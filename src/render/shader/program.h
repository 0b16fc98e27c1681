// A shader graph compiled into a flat program, Cycles' SVM being the model: the nodes the
// output reaches, in dependency order, each an operation over a register file of float3
// values (float sockets use .x); constant inputs folded at compile time, so a graph whose
// result does not vary over the surface is evaluated once. Shader sockets form a closure tree
// (Mix and Add Shader nodes over BSDFs, emission, transparency, holdout) walked with weights
// after the values are computed, as Cycles' closure array is filled.
#pragma once

#include <algorithm>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "core/log.h"
#include "render/shader/closures.h"
#include "scene/shader_graph.h"

namespace glint::render {
class TextureCache;
}

namespace glint::render::shader {

// Registers the globals occupy, in this order, at the start of every register file.
enum GlobalRegister : int {
    kRegP, kRegN, kRegNg, kRegI, kRegUV, kRegGenerated, kRegObject, kRegTangent, kRegUVTangent,
    kRegBackfacing, kRegObjectLocation, kRegObjectColor, kRegObjectInfo /* pass, random */,
    kRegRay /* is_camera, is_shadow, ray_length */, kRegRay2 /* diffuse, glossy, singular */,
    kRegRay3 /* reflection, transmission, depth */, kRegDepths /* diffuse, glossy, transmission */,
    kRegTransparentDepth, kRegCamera, kRegWindow, kRegViewDistance, kRegReflection,
    kGlobalCount
};

class ShaderProgram;

// One operation: a node's work. Inputs and outputs are register indices; ints, floats and
// `data` carry the node's settings (enums, flags, a table).
struct Op {
    void (*fn)(const Op& op, float3* regs, const ShaderGlobals& sg) = nullptr;
    int in[12] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
    int out[6] = {-1, -1, -1, -1, -1, -1};
    int i[6] = {0, 0, 0, 0, 0, 0};
    float f[6] = {0, 0, 0, 0, 0, 0};
    const void* data = nullptr;
    // Bump: how many of the program's first operations to re-run at two shifted points.
    int sub_begin = 0, sub_end = 0;
};

// A node of the closure tree.
struct ClosureNode {
    enum class Kind { Bsdf, Emission, Transparent, Holdout, Mix, Add, Volume } kind = Kind::Bsdf;
    // Volume: Cycles' Volume Scatter, Volume Absorption and Principled Volume.
    enum class VolumeKind { Scatter, Absorption, Principled } volume = VolumeKind::Scatter;
    ClosureKind bsdf = ClosureKind::Diffuse;
    int a = -1, b = -1;  // Mix: shader 1 and 2; Add: both
    int fac = -1;        // Mix: the factor register
    // Bsdf: the registers of its inputs, by Slot (-1: not given); Emission: color, strength.
    enum Slot {
        kColor, kNormal, kRoughness /* Toon: size; Velvet: sigma */, kIor, kMetallic,
        kSpecular, kTransmission, kAlpha, kEmission, kEmissionStrength, kSpecularTint,
        kAnisotropy, kRotation, kSheen, kSheenTint, kClearcoat, kClearcoatRoughness,
        kClearcoatNormal, kTransmissionRoughness, kTangent, kSmooth,
        // Subsurface (Principled, Subsurface Scattering: scale in kSubsurface).
        kSubsurface, kSubsurfaceRadius, kSubsurfaceColor, kSubsurfaceIor,
        kSubsurfaceAnisotropy,
        // Volumes (colour, emission and its strength use the slots above).
        kDensity, kAbsorptionColor, kBlackbody, kBlackbodyTint, kTemperature,
        kSlots
    };
    int in[kSlots];
    Distribution distribution = Distribution::GGX;
    bool glossy = false;  // Toon's glossy component
    SubsurfaceMethod subsurface = SubsurfaceMethod::RandomWalk;
    // Principled Volume's Density, Color and Temperature Attributes: the grids it reads where
    // the volume's object has them (null: none), looked up only when needed, as in Cycles.
    const std::string* grids[3] = {nullptr, nullptr, nullptr};
    ClosureNode() { std::fill(std::begin(in), std::end(in), -1); }
};

class ShaderProgram {
public:
    // Compiles `graph`; each node kind glint lacks is one warning naming it and the graph (the
    // node then gives its outputs' default values, or no closure). `textures` opens images.
    static std::unique_ptr<ShaderProgram> compile(const scene::ShaderGraph& graph,
                                                  TextureCache* textures, Diagnostics& diag);

    // Runs the program at `sg`, adding the closures it leaves to `out` (cleared first).
    void evaluate(const ShaderGlobals& sg, ClosureList* out) const;
    // Whether no value depends on the shading point: one evaluation holds everywhere.
    bool constant() const { return varying_ops_ == 0 && !closure_varying_; }
    // Whether the closures depend on the shading point only through its shading normal (a
    // Diffuse or Principled BSDF with constant inputs, no bump): one evaluation holds
    // everywhere once the closures that read the normal (Closure::n_from_globals) get the
    // point's N (ShaderGlobals::N), and the list's N too.
    bool normal_only() const { return normal_only_; }
    // Whether the graph has a surface at all (an output with a linked Surface).
    bool has_surface() const { return root_ >= 0; }
    // Whether a Holdout closure is in the graph (the film then carries alpha).
    bool has_holdout() const;
    // Whether the surface can let shadow rays through anywhere: a Transparent BSDF that is not
    // black, a Principled BSDF whose Alpha is linked or below 1, or no surface but a volume.
    // False lets shadow rays stop at the first surface they meet (an any-hit query).
    bool can_be_transparent() const { return can_be_transparent_; }
    // The volume shader (the output's Volume socket): whether there is one, whether it is
    // the same everywhere, and its closures at `sg` (the program's values run first).
    bool has_volume() const { return volume_root_ >= 0; }
    bool volume_constant() const { return !volume_varying_; }
    // Whether the volume shader reads its object's grids (then it varies in space inside a
    // Volume object, whatever volume_constant() says for other objects).
    bool volume_grids() const { return volume_grids_; }
    void evaluate_volume(const ShaderGlobals& sg, VolumeClosures* out) const;
    const std::string& name() const { return name_; }
    // Re-runs the first `end` operations on `regs` for the shading point `sg` (Bump's height at
    // a shifted point: the ops before a Bump are all that its height can depend on).
    void rerun(size_t end, float3* regs, const ShaderGlobals& sg) const;
    size_t op_count() const { return ops_.size(); }
    size_t register_count() const { return init_.size(); }

private:
    friend class Compiler;
    void run(const Op* begin, const Op* end, float3* regs, const ShaderGlobals& sg) const;
    void walk(int node, const Color& weight, const float3* regs, ClosureList* out) const;
    void walk_volume(int node, const Color& weight, const float3* regs, const ShaderGlobals& sg,
                     VolumeClosures* out) const;

    std::string name_;
    std::vector<float3> init_;  // the register file's start: globals' slots, then constants
    std::vector<Op> ops_;       // the main sequence; bump height sequences follow it
    size_t main_end_ = 0;
    int normal_reg_ = kRegN;  // the surface's normal: N, or N bent by displacement
    std::vector<std::unique_ptr<std::vector<float>>> tables_;  // ramps and curves
    std::vector<std::shared_ptr<const void>> keep_;            // images and other data ops read
    std::vector<ClosureNode> closures_;
    int root_ = -1;
    int volume_root_ = -1;
    bool volume_varying_ = false;
    bool volume_grids_ = false;
    bool can_be_transparent_ = true;
    bool normal_only_ = false;
    int varying_ops_ = 0;
    bool closure_varying_ = false;
};

// Writes the globals into the first kGlobalCount registers.
void load_globals(const ShaderGlobals& sg, float3* regs);

}  // namespace glint::render::shader
