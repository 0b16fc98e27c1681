#include "render/prepare/prepared_scene.h"

#include "render/prepare/pattern_objects.h"

#include <algorithm>
#include <utility>

namespace glint::render {
namespace {

// The images first (the material table asks which have alpha), then the materials' opacity
// (the geometry asks which are opaque), the geometry, and the integrator's half of the table.
std::unique_ptr<PreparedScene> prepare_with(const scene::Scene& scene,
                                            const RenderOptions& options, Diagnostics* diag,
                                            std::unique_ptr<Geometry> geometry) {
    scene::Features features = scene::analyze(scene);
    std::unique_ptr<TextureCache> textures;
    const bool path = options.integrator == IntegratorKind::Path;
    const bool graphs = path && !scene.shader_graphs.empty();
    const bool pbr_maps = path && needs_pbr_maps(scene);
    if (features.image_textures || pbr_maps || graphs) {
        // (A cache opens the image library only when an image is added.)
        textures = std::make_unique<TextureCache>(image_gamma(scene));
        if (features.image_textures) textures->preload(scene);
    }
    Diagnostics quiet;
    std::unique_ptr<shader::GraphShading> programs;
    if (graphs)
        programs = std::make_unique<shader::GraphShading>(scene, options.width, options.height,
                                                          textures.get(), diag ? *diag : quiet);
    MaterialTable materials(scene, textures.get());
    if (!geometry) geometry = build_geometry(scene, features, materials, diag ? *diag : quiet);
    materials.prepare_for(scene, options.integrator, textures.get(), programs.get());
    std::unique_ptr<PatternObjects> objects = build_pattern_objects(scene, diag ? *diag : quiet);
    // A POV-Ray camera `normal` sees what the surfaces' patterns see.
    const PatternContext camera_patterns{scene.global.noise_generator,
                                         scene.global.number_of_waves, &scene.functions,
                                         objects.get(), textures.get()};
    Camera camera(scene.camera, options.width, options.height, &scene.meshes, camera_patterns);
    const bool any_projected =
        std::any_of(scene.lights.begin(), scene.lights.end(),
                    [](const scene::Light& l) { return l.projected_through != nullptr; });
    std::vector<std::unique_ptr<ObjectNode>> projected(any_projected ? scene.lights.size() : 0);
    for (size_t i = 0; i < projected.size(); ++i)
        if (const auto& o = scene.lights[i].projected_through)
            projected[i] = ObjectNode::build(*o, scene, diag ? *diag : quiet);
    return std::unique_ptr<PreparedScene>(new PreparedScene{
        scene, std::move(features), std::move(textures), std::move(programs),
        std::move(materials), std::move(geometry), std::move(camera), Shutter(scene),
        std::move(objects), std::move(projected)});
}

}  // namespace

std::unique_ptr<PreparedScene> prepare(const scene::Scene& scene, const RenderOptions& options,
                                       Diagnostics& diag) {
    return prepare_with(scene, options, &diag, nullptr);
}

std::unique_ptr<PreparedScene> prepare(const scene::Scene& scene, const RenderOptions& options,
                                       std::unique_ptr<Geometry> geometry) {
    return prepare_with(scene, options, nullptr, std::move(geometry));
}

}  // namespace glint::render
