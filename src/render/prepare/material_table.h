// The material table: what each IR material means to the integrators, worked out once per
// render before any ray is traced. One row per scene::Material, indexed like Hit::material.
// Whitted renders read the classic half (POV-Ray's finish model), path renders the PBR half
// (constant surfaces, emission, alpha, OBJ/MTL image maps); both read the opacity, which the
// geometry's shadow queries use too.
#pragma once

#include <optional>
#include <unordered_map>
#include <vector>

#include "render/bsdf/bsdf.h"
#include "render/bsdf/pov_to_pbr.h"
#include "render/materials/classic_finish.h"
#include "render/options.h"
#include "scene/scene.h"

namespace glint::render {

class TextureCache;

struct PreparedMaterial {
    // No pigment of the POV-Ray texture can ever let light through (materials/opacity.h).
    bool opaque = true;

    // Whitted only: the base texture's finish with POV-Ray's parse-time conversions done.
    std::optional<ClassicFinish> finish;

    // Path tracer only. The surface and its BSDF where no hit can change them (a POV-Ray
    // texture with a plain pigment, a PBR material without maps): shading copies them.
    std::optional<SurfacePbr> constant;
    std::optional<Bsdf> constant_bsdf;
    Color emission;         // emitted radiance where constant (black otherwise): light-sampled
    bool has_alpha = true;  // shadow rays may pass: alpha below 1, or a transmissive IOR 1
    PbrMaps maps;           // OBJ/MTL image maps (none for POV-Ray textures)
};

class MaterialTable {
public:
    MaterialTable() = default;
    // Rows for every material of `scene`, the half that `integrator` reads filled in. PBR
    // maps are loaded into `textures`, which must be non-null when needs_pbr_maps() says so.
    MaterialTable(const scene::Scene& scene, IntegratorKind integrator, TextureCache* textures);

    size_t size() const { return rows_.size(); }
    const PreparedMaterial& operator[](size_t i) const { return rows_[i]; }
    const PreparedMaterial* get(int material) const {
        return material >= 0 && static_cast<size_t>(material) < rows_.size() ? &rows_[material]
                                                                           : nullptr;
    }

    // Whitted: the prepared form of finish `f`, which belongs to material `material` (its
    // base texture's, or a layer's or a texture map entry's).
    const ClassicFinish& classic_finish(const scene::Finish& f, int material) const;
    // Path tracer: some material may let shadow rays through.
    bool any_alpha() const { return any_alpha_; }
    // Path tracer: per material, its constant emission (the light sampler's emitters).
    std::vector<Color> emission() const;

private:
    std::vector<PreparedMaterial> rows_;
    // Each material's own finish (the one asked for most): its row's, without a lookup.
    std::vector<const scene::Finish*> base_finishes_;
    // The finishes of layers and texture map entries, keyed by the IR finish they come from.
    std::unordered_map<const scene::Finish*, ClassicFinish> layer_finishes_;
    bool any_alpha_ = false;
};

// Whether a path render of `scene` reads image files for its PBR maps (so needs a texture
// cache even without POV-Ray image maps).
bool needs_pbr_maps(const scene::Scene& scene);

}  // namespace glint::render
