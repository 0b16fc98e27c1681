// The whole scene as plain data: what an importer produces and what the renderer prepares
// from. Entities link by integer ids (materials, meshes). Defaults match POV-Ray 3.7.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "scene/atmosphere.h"
#include "scene/camera.h"
#include "scene/color.h"
#include "scene/function.h"
#include "scene/light.h"
#include "scene/mesh.h"
#include "scene/shader_graph.h"
#include "scene/shape.h"
#include "scene/texture.h"

namespace glint::scene {

// global_settings { radiosity { ... } } with POV-Ray 3.7's defaults (radiosity.h
// SceneRadiositySettings); the parser checks the ranges POV-Ray checks.
struct Radiosity {
    double brightness = 1;
    int count = 35;
    int direction_pool = 1600;  // count's second value
    double error_bound = 1.8;
    double gray_threshold = 0;
    double low_error_factor = 0.5;
    double minimum_reuse = 0.015;
    double maximum_reuse = 0.2;
    int nearest_count = 5;
    int nearest_count_pretrace = 0;  // nearest_count's second value: adaptive pretrace
    int recursion_limit = 2;
    double max_sample = -1;  // <= 0: no limit
    double adc_bailout = 0.01;
    bool normal = false, media = false, subsurface = false, always_sample = false;
    double pretrace_start = 0.08, pretrace_end = 0.04;
};

// global_settings { photons { ... } } with POV-Ray 3.7's defaults (parse.cpp).
struct Photons {
    double spacing = 1;  // surface separation at a target (times its own multiplier)
    int count = 0;       // > 0: spacing follows from this photon count instead
    int gather_min = 20, gather_max = 100;
    double radius = -1, radius_multiplier = 1;  // radius <= 0: estimated from the map
    double media_radius = -1, media_radius_multiplier = 1;
    double jitter = 0.4;
    double autostop = 0.5;
    double expand_tolerance = 0.2;
    int expand_min = 35;
    int max_trace_level = -1;  // < 0: global_settings max_trace_level
    double adc_bailout = -1;   // < 0: global_settings adc_bailout
    int media_steps = 0;       // media photons: max steps (0: off)
    double media_factor = 1;
    // save_file / load_file: write the photons shot to a file, or take them from one instead
    // of shooting (render/gi/photon_map.h, glint's own format); "" for neither.
    std::string save_file, load_file;
    FileLoc loc;  // the photons block, for errors while shooting
};

struct GlobalSettings {
    Color ambient_light{1, 1, 1};
    int max_trace_level = 5;
    double adc_bailout = 1.0 / 255.0;
    // assumed_gamma as given; unset means POV-Ray's default for the #version.
    std::optional<double> assumed_gamma;
    int noise_generator = 2;
    int number_of_waves = 10;
    // irid_wavelength: the "wavelengths" irid divides the film's phase by, per channel.
    Color irid_wavelength{0.70, 0.52, 0.48};  // POV-Ray 3.7's default (scene.cpp)
    // Scene units in millimetres, for subsurface light transport.
    double mm_per_unit = 10;
    // `subsurface { samples diffuse, single }`: present turns subsurface light transport on
    // for finishes that have it; the samples per shading point of its two terms.
    bool subsurface = false;
    int subsurface_samples_diffuse = 50, subsurface_samples_single = 50;
    // `radiosity { ... }`: POV-Ray's irradiance cache (render/gi/radiosity.h); absent: off.
    std::optional<Radiosity> radiosity;
    // `#default { radiosity { importance } }`: objects without their own importance.
    double radiosity_importance = 1;
    // `photons { ... }`: POV-Ray's caustic photon map (render/gi/photon_map.h); absent: off.
    std::optional<Photons> photons;
    FileLoc loc;
};

struct SkySphere {
    // Layered: pigments[0] is the bottom layer, later ones are laid over it.
    std::vector<Pigment> pigments;
    Transform transform;
    Color emission{1, 1, 1};
    FileLoc loc;
};

// Render settings a Blender scene carries (the add-on's exchange, formats/blender): the CLI
// uses them where its own flags are not given.
struct BlenderRender {
    int width = 0, height = 0;
    int samples = 64;
    int seed = 0;
    // Cycles' Light Paths > Max Bounces.
    int max_bounces = 12, diffuse_bounces = 4, glossy_bounces = 4, transmission_bounces = 12,
        transparent_bounces = 8, volume_bounces = 0;
    bool film_transparent = false;
    // Film > Transparent Glass: the Roughness Threshold under which a transmission keeps the
    // camera's view of the world transparent; negative when off.
    double film_transparent_glass = -1;
    std::string pixel_filter = "BLACKMAN_HARRIS";  // Cycles' BOX, GAUSSIAN, BLACKMAN_HARRIS
    double filter_width = 1.5;
    double clamp_direct = 0, clamp_indirect = 10;
    double filter_glossy = 1.0;
    bool caustics_reflective = true, caustics_refractive = true;
    // Cycles' Volumes panel: step rate (scales every object's ray-marching step) and the most
    // steps one segment takes.
    double volume_step_rate = 1.0;
    int volume_max_steps = 1024;
    // Sampling > Noise Threshold: adaptive sampling, its threshold and minimum samples
    // (0: Cycles derives them from the sample count).
    bool adaptive_sampling = false;
    double adaptive_threshold = 0.01;
    int adaptive_min_samples = 0;
};

struct Scene {
    double version = 3.7;  // the #version in force at the end of parsing
    Camera camera;
    std::vector<Light> lights;
    std::vector<Object> objects;
    std::deque<Material> materials;
    std::vector<Mesh> meshes;
    GlobalSettings global;
    ColorFT background{Color(0, 0, 0)};
    std::optional<SkySphere> sky_sphere;
    std::vector<Fog> fogs;
    std::vector<Rainbow> rainbows;
    // POV-Ray's atmospheric media: fills all space outside non-hollow objects.
    std::vector<Media> media;
    // User-defined functions (function patterns refer to them by index; calls between them too).
    std::vector<Function> functions;
    // The objects of object patterns (PatternParams::object), in pattern space; materials -1.
    std::vector<Object> pattern_objects;
    // Shader node graphs (Blender's materials, world and lights); Material::graph and
    // world_graph index them.
    std::vector<ShaderGraph> shader_graphs;
    int world_graph = -1;
    // The world's Volume settings in Cycles (World > Settings > Volume): the ray-marching step
    // of a world volume that varies in space, and Homogeneous (shade it once per segment).
    double world_volume_step = 1.0;
    bool world_volume_homogeneous = false;
    std::optional<BlenderRender> blender_render;
    // Files the scene was read from (main file first), for messages and `glint ir`.
    std::vector<std::string> source_files;
};

}  // namespace glint::scene
