#include "render/prepare/material_table.h"

#include "render/materials/opacity.h"
#include "render/textures/image_texture.h"

namespace glint::render {
namespace {

bool has_maps(const scene::Pbr& p) {
    return !p.derived &&
           (p.base_color_map.present() || p.specular_map.present() || p.emission_map.present() ||
            p.roughness_map.present() || p.metallic_map.present() || p.exponent_map.present() ||
            p.alpha_map.present() || p.bump_map.present());
}

// Every finish a texture can show: its own, its layers', its map entries'.
void collect_finishes(const scene::Texture& t, std::vector<const scene::Finish*>* out) {
    out->push_back(&t.finish);
    for (const scene::Texture& l : t.layers) collect_finishes(l, out);
    for (const scene::TextureMapEntry& e : t.texture_map) collect_finishes(e.texture[0], out);
    for (const scene::Texture& e : t.entries) collect_finishes(e, out);
}

bool lets_shadow_rays_through(const SurfacePbr& s) {
    return s.alpha < 1 || (s.bsdf.ior == 1.0 && s.bsdf.transmission > 0);
}

// The path tracer's view of material `m`; its maps, if any, are appended to `maps`.
// `sslt_mm`: the scene's mm_per_unit where subsurface light transport is on, else 0.
PathMaterial prepare_path(const scene::Material& m, TextureCache* textures,
                          std::vector<PbrMaps>* maps, double sslt_mm) {
    PathMaterial row;
    const scene::Pbr& p = m.pbr;
    if (!p.derived) {
        PbrMaps loaded;
        if (has_maps(p)) loaded = prepare_pbr_maps(p, *textures);
        if (loaded.any()) {
            // Where the maps leave emission and coverage constant, the emitter is still
            // light-sampled and shadow rays need not look for holes.
            const SurfacePbr c = pbr_surface(p, p.base_color);
            if (!loaded.emission && !loaded.alpha) row.emission = c.emission;
            row.has_alpha = loaded.alpha || lets_shadow_rays_through(c);
            row.maps = static_cast<int>(maps->size());
            maps->push_back(loaded);
        } else {
            row.constant = pbr_surface(p, p.base_color);
        }
    } else {
        const scene::Texture& t = base_texture(m.texture);
        if (t.pigment.kind == scene::PatternKind::Plain)
            row.constant = pov_to_pbr(t.finish, m.interior, t.pigment.color, sslt_mm);
    }
    if (row.constant) {
        row.emission = row.constant->emission;
        row.has_alpha = lets_shadow_rays_through(*row.constant);
        row.constant_bsdf = Bsdf::principled(row.constant->bsdf);
    }
    return row;
}

// A node graph's row: evaluated once where nothing in it varies (then its emission is
// light-sampled and its transparency known), else at every hit.
PathMaterial prepare_graph(const shader::ShaderProgram& program) {
    PathMaterial row;
    row.program = &program;
    row.has_alpha = program.can_be_transparent();
    if (program.normal_only()) {
        auto closures = std::make_shared<shader::ClosureList>();
        program.evaluate(shader::ShaderGlobals(), closures.get());
        // Its emission is the same everywhere (a Principled BSDF's Emission, an Emission mixed
        // with a BSDF): light-sampled, as Cycles samples every emitting mesh.
        row.emission = closures->emission;
        row.normal_closures = std::move(closures);
    }
    if (!program.constant()) return row;
    auto closures = std::make_shared<shader::ClosureList>();
    program.evaluate(shader::ShaderGlobals(), closures.get());
    row.emission = closures->emission;
    row.has_alpha = !closures->transparent.is_black();
    row.constant_closures = std::move(closures);
    return row;
}

}  // namespace

bool needs_pbr_maps(const scene::Scene& scene) {
    for (const scene::Material& m : scene.materials)
        if (has_maps(m.pbr)) return true;
    return false;
}

MaterialTable::MaterialTable(const scene::Scene& scene, const TextureCache* textures) {
    opaque_.reserve(scene.materials.size());
    for (const scene::Material& m : scene.materials) {
        // POV-Ray's OPAQUE_FLAG (Post_Process): both sides' textures must be opaque.
        bool clear = texture_can_be_transparent(m.texture, textures);
        for (const scene::Texture& t : m.interior_texture)
            clear = clear || texture_can_be_transparent(t, textures);
        opaque_.push_back(!clear);
    }
}

void MaterialTable::prepare_for(const scene::Scene& scene, IntegratorKind integrator,
                                TextureCache* textures, const shader::GraphShading* graphs) {
    const size_t n = scene.materials.size();
    if (integrator == IntegratorKind::Path) {
        path_.reserve(n);
        for (size_t i = 0; i < n; ++i) {
            const shader::ShaderProgram* program =
                graphs ? graphs->material(static_cast<int>(i)) : nullptr;
            path_.push_back(program ? prepare_graph(*program)
                                    : prepare_path(scene.materials[i], textures, &maps_,
                                                   scene.global.subsurface
                                                       ? scene.global.mm_per_unit
                                                       : 0));
            any_alpha_ = any_alpha_ || path_.back().has_alpha;
            any_holdout_ = any_holdout_ || (program && program->has_holdout());
        }
        return;
    }
    finishes_.reserve(n);
    base_finishes_.reserve(n);
    for (const scene::Material& m : scene.materials) {
        finishes_.emplace_back(m.texture.finish);
        base_finishes_.push_back(&m.texture.finish);
        std::vector<const scene::Finish*> all;
        collect_finishes(m.texture, &all);
        for (const scene::Texture& t : m.interior_texture) collect_finishes(t, &all);
        for (const scene::Finish* f : all) layer_finishes_.emplace(f, ClassicFinish(*f));
    }
}

const ClassicFinish& MaterialTable::classic_finish(const scene::Finish& f, int material) const {
    const ClassicFinish& own = finishes_[material];
    if (&f == base_finishes_[material]) return own;
    auto it = layer_finishes_.find(&f);
    return it != layer_finishes_.end() ? it->second : own;
}

std::vector<Color> MaterialTable::emission() const {
    std::vector<Color> out(opaque_.size());
    for (size_t i = 0; i < path_.size(); ++i) out[i] = path_[i].emission;
    return out;
}

}  // namespace glint::render
