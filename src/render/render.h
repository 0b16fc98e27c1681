// One call from IR to image: analyze the scene, prepare only what it uses, run the chosen
// integrator over the image with the tile driver.
#pragma once

#include <cstdint>
#include <string>

#include "core/log.h"
#include "image/image.h"
#include "render/options.h"
#include "scene/features.h"
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
    // Path tracer with RenderOptions::aovs / variance (otherwise empty): see PathFilm.
    Image albedo, normal, depth, variance;
};

RenderResult render(const scene::Scene& scene, const RenderOptions& options, Diagnostics& diag);

// Questions the scene language asks about one object while parsing: POV-Ray's trace() and
// min_extent()/max_extent(). The importer cannot see the renderer, so the application passes
// answer_object_query as ParseOptions::object_query; it builds the renderer's geometry for a
// scene holding only that object (object_query.cpp).
// kind 0 (bounds): lo/hi = the world bounding box; false when empty.
// kind 1 (trace): the first hit from `a` along `b` (any length); true on a hit with the point
// in lo and the surface normal (facing the ray's origin side as POV-Ray's trace returns the
// object's normal) in hi.
bool answer_object_query(const scene::Scene& one, int kind, const Vec3& a, const Vec3& b, Vec3& lo,
                         Vec3& hi);

// ParseOptions::pattern_hook: a pattern function's value (out[0]) or a pigment function's color
// (out = rgbft) when the scene calls one while parsing (shapes.inc's HF macros do). `user` is
// unused; functions called from inside such a pattern are not available there.
void parse_time_pattern(const void* user, const scene::Function& f, const Vec3& p, double out[5]);


}  // namespace glint::render
