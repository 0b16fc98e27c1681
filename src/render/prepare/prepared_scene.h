// The prepare stage: everything a render needs from the IR, built in one step before the first
// ray and read-only after it. The integrators take a PreparedScene and nothing else of the
// scene's making: the IR itself (lights, sky, atmosphere, camera settings), what the scene
// uses (features), the one texture cache, the material table, the geometry (shapes, CSG trees,
// the BVH) and the camera.
#pragma once

#include <memory>
#include <vector>

#include "core/log.h"
#include "render/camera.h"
#include "render/film/shutter.h"
#include "render/options.h"
#include "render/prepare/geometry.h"
#include "render/prepare/material_table.h"
#include "render/shapes/object_node.h"
#include "render/shader/shading.h"
#include "render/textures/image_texture.h"
#include "render/textures/pattern.h"
#include "scene/features.h"
#include "scene/scene.h"

namespace glint::render {

struct PreparedScene {
    const scene::Scene& scene;  // must outlive this
    scene::Features features;
    // Every image a render reads (POV-Ray image maps, the sky's, PBR maps); null for scenes
    // without any, so that they never open the texture system.
    std::unique_ptr<TextureCache> textures;
    // The scene's node graphs compiled (Blender materials and world), for the path tracer;
    // null when it has none.
    std::unique_ptr<shader::GraphShading> graphs;
    MaterialTable materials;
    std::unique_ptr<Geometry> geometry;
    Camera camera;
    Shutter shutter;  // motion blur; inactive for scenes without motion
    // Object patterns' objects (PatternContext::objects); null without any.
    std::unique_ptr<PatternObjects> pattern_objects;
    // Per scene light: its projected_through object (scene::Light::projected_through), null
    // for lights without one; empty when no light has one.
    std::vector<std::unique_ptr<ObjectNode>> projected_through;
};

// Prepares `scene` for a render with `options` (its integrator and image size). Degenerate
// input is skipped with a warning in `diag`; invalid input throws glint::Error.
std::unique_ptr<PreparedScene> prepare(const scene::Scene& scene, const RenderOptions& options,
                                       Diagnostics& diag);
// The same around geometry built elsewhere (the integrator tests' stand-ins).
std::unique_ptr<PreparedScene> prepare(const scene::Scene& scene, const RenderOptions& options,
                                       std::unique_ptr<Geometry> geometry);

}  // namespace glint::render
