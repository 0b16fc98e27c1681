// One call from IR to image: analyze the scene, prepare only what it uses, run the chosen
// integrator over the image with the tile driver.
#pragma once

#include <cstdint>
#include <string>

#include "core/log.h"
#include "image/image.h"
#include "render/options.h"
#include "scene/features.h"
#include "scene/object_query.h"
#include "scene/scene.h"

namespace glint::render {

struct RenderResult {
    Image image;
    scene::Features features;
    double prepare_seconds = 0;
    double render_seconds = 0;
    int samples_per_pixel = 0;      // path tracer: samples each pixel got
    uint64_t nonfinite_paths = 0;   // path tracer: NaN/Inf paths dropped
    uint64_t rays = 0;              // path tracer: rays traced (camera, bounce, shadow)
    bool alpha = false;             // the image's alpha means something (RenderOptions::alpha)
    // Path tracer with RenderOptions::aovs / variance (otherwise empty): see PathFilm.
    Image albedo, normal, depth, variance;
};

RenderResult render(const scene::Scene& scene, const RenderOptions& options, Diagnostics& diag);

// The scene language's questions about one object while parsing (POV-Ray's trace(), inside(),
// min_extent(), max_extent(); scene/object_query.h), answered with the renderer's geometry for
// a scene holding only that object (object_query.cpp), built once. The application passes it
// to the importer as ParseOptions::prepare_object.
std::shared_ptr<const scene::PreparedObject> prepare_object_query(const scene::Scene& one);

// ParseOptions::pattern_hook: a pattern function's value (out[0]) or a pigment function's color
// (out = rgbft) when the scene calls one while parsing (shapes.inc's HF macros do). `user` is
// the parser's scene::FunctionEnv: its noise_generator and the functions declared so far.
void parse_time_pattern(const void* user, const scene::Function& f, const Vec3& p, double out[5]);

}  // namespace glint::render
