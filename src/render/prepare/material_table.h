// The material table: what each IR material means to the integrators, worked out once per
// render before any ray is traced. One row per scene::Material, indexed like Hit::material.
// Whitted renders read the classic half (POV-Ray's finish model), path renders the PBR half
// (constant surfaces, emission, alpha, OBJ/MTL image maps); both read the opacity, which the
// geometry's shadow queries use too.
#pragma once

#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "render/bsdf/bsdf.h"
#include "render/bsdf/pov_to_pbr.h"
#include "render/materials/classic_finish.h"
#include "render/options.h"
#include "render/shader/shading.h"
#include "scene/scene.h"

namespace glint::render {

class TextureCache;

// The path tracer's view of one material.
struct PathMaterial {
    // The surface and its BSDF where no hit can change them (a POV-Ray texture with a plain
    // pigment, a PBR material without maps): shading copies them.
    std::optional<SurfacePbr> constant;
    std::optional<Bsdf> constant_bsdf;
    Color emission;         // emitted radiance where constant (black otherwise): light-sampled
    bool has_alpha = true;  // shadow rays may pass: alpha below 1, or a transmissive IOR 1
    int maps = -1;          // its OBJ/MTL image maps (MaterialTable::maps), -1 for none
    // A node graph (Blender), and its closures where they are the same everywhere.
    const shader::ShaderProgram* program = nullptr;
    std::shared_ptr<const shader::ClosureList> constant_closures;
    // Its closures where only the shading normal varies (ShaderProgram::normal_only): the
    // point's N goes into those that read it.
    std::shared_ptr<const shader::ClosureList> normal_closures;
};

// Per material, each half in an array of its own, so that a render keeps only what its
// integrator reads (a scene of 66,000 one-sphere materials holds 200 bytes a material for
// Whitted, not the path tracer's 400 more).
class MaterialTable {
public:
    MaterialTable() = default;
    // The opacity of every material of `scene` (`textures`, which may be null, tell which
    // image maps have alpha): what the geometry needs.
    MaterialTable(const scene::Scene& scene, const TextureCache* textures);
    // The half that `integrator` reads. PBR maps are loaded into `textures`, which must be
    // non-null when needs_pbr_maps() says so. Called after the geometry is built, so that
    // its build's temporaries are gone before these arrays are made.
    void prepare_for(const scene::Scene& scene, IntegratorKind integrator,
                     TextureCache* textures, const shader::GraphShading* graphs = nullptr);

    size_t size() const { return opaque_.size(); }
    // No pigment of the material's POV-Ray texture can ever let light through
    // (materials/opacity.h). Ids outside the table (no material) are opaque.
    bool opaque(int material) const {
        return material < 0 || static_cast<size_t>(material) >= opaque_.size() ||
               opaque_[material];
    }

    // Whitted: the prepared form of finish `f`, which belongs to material `material` (its
    // base texture's, or a layer's or a texture map entry's).
    const ClassicFinish& classic_finish(const scene::Finish& f, int material) const;

    // Path tracer: material `material`, or null for ids outside the table.
    const PathMaterial* path(int material) const {
        return material >= 0 && static_cast<size_t>(material) < path_.size() ? &path_[material]
                                                                            : nullptr;
    }
    const PbrMaps& maps(const PathMaterial& m) const { return maps_[m.maps]; }
    // Some material may let shadow rays through.
    bool any_alpha() const { return any_alpha_; }
    // Some material's node graph has a Holdout closure.
    bool any_holdout() const { return any_holdout_; }
    // Per material, its constant emission (the light sampler's emitters).
    std::vector<Color> emission() const;

private:
    std::vector<char> opaque_;
    // Whitted: each material's own finish, the IR finish it comes from (asked for most: no
    // lookup), and the finishes of layers and texture map entries keyed by their IR finish.
    std::vector<ClassicFinish> finishes_;
    std::vector<const scene::Finish*> base_finishes_;
    std::unordered_map<const scene::Finish*, ClassicFinish> layer_finishes_;
    // Path tracer.
    std::vector<PathMaterial> path_;
    std::vector<PbrMaps> maps_;
    bool any_alpha_ = false;
    bool any_holdout_ = false;
};

// Whether a path render of `scene` reads image files for its PBR maps (so needs a texture
// cache even without POV-Ray image maps).
bool needs_pbr_maps(const scene::Scene& scene);

}  // namespace glint::render
