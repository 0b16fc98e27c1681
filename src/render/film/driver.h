// The tile driver: splits the image into POV-Ray-sized blocks, renders them on oneTBB worker
// threads, reports progress, honours cancellation and applies anti-aliasing. It only knows a
// per-ray radiance function, so any integrator (Whitted now, the path tracer later) plugs in.
// Every pixel depends only on its own samples (and, for adaptive AA, on its fixed block), so
// the image is bit-identical whatever the thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "core/error.h"
#include "image/image.h"
#include "render/camera.h"
#include "render/film/aov.h"
#include "render/film/film.h"
#include "render/film/pixel_filter.h"
#include "render/film/shutter.h"
#include "render/options.h"
#include "render/sampling/sampler.h"

namespace glint::render {

// Names one camera sample, so stochastic integrators (the path tracer) can seed their random
// numbers from it rather than from the thread: the same image whatever the thread count.
struct SampleId {
    int x = 0;           // pixel column (may be -1 for adaptive AA's border samples)
    int y = 0;           // pixel row
    uint32_t index = 0;  // sample number within the pixel, in the driver's fixed order
    // The image block (kBlockSize pixels square, numbered in rows over the whole image) the
    // sample is taken for; -1 outside run_tiles. Adaptive AA's border samples belong to the
    // block that traces them.
    int block = -1;
};

// Radiance along a camera ray. Must be thread-safe (called concurrently).
using RadianceFn = std::function<Color(const Ray& ray, const SampleId& id)>;

struct DriverSettings {
    // Working gamma of the colors the radiance function returns: adaptive AA compares colors
    // after POV-Ray's antialias_gamma (2.5) encoding of linear values.
    double working_gamma = 1.0;
};

// Throws Interrupted (an Error(ErrorKind::Cancelled)) when options.cancel is set during the
// render; it carries what was finished. Cancellation is checked before every row of a tile, so
// a render stops within a row's time; a tile cut short counts as not finished.
Image run_tiles(const Camera& camera, const RenderOptions& options,
                const DriverSettings& settings, const RadianceFn& radiance);

// The path tracer's radiance along a camera ray; `first` is null unless AOVs are wanted, and
// then receives what the ray sees at its first visible hit.
using PathRadianceFn =
    std::function<Color(const Ray& ray, const SampleId& id, FirstHit* first)>;

// The path tracer's loop: options.spp jittered samples per pixel (pixel jitter from pair 0 of
// the PixelSampler of (pixel, sample, options.seed)), averaged with a box filter. Samples are
// taken in progressive passes (1, 1, 2, 4, ... per pixel); with options.time_limit > 0 the
// render stops after the pass that crosses the limit. Each pixel sums its samples in sample
// order (the variance by Welford's update in the same order), so every output is
// bit-identical whatever the thread count. Returns the samples taken per pixel. With an
// active `shutter` (motion blur) each camera ray also gets a shutter time, from a pair of its
// own (so the other samples stay as they are).
int run_path_tiles(const Camera& camera, const RenderOptions& options,
                   const PathRadianceFn& radiance, PathFilm* film,
                   const Shutter* shutter = nullptr);
// The camera ray of the path tracer's sample `ps` at pixel (x, y): the pixel filter's offset
// from pair 0, the lens point and the shutter time (with an active `shutter`) from pairs no
// bounce uses. Empty where the camera sends no ray. A mesh_camera with several rays per
// pixel gives sample `index` its ray index mod rays.
std::optional<Ray> path_camera_ray(const Camera& camera, const PixelFilter& filter,
                                   const Shutter* shutter, const PixelSampler& ps, int x, int y,
                                   uint32_t index);
// The same without AOVs or variance, for a plain radiance function.
// Both check cancellation before every sample and throw Interrupted.
int run_path_tiles(const Camera& camera, const RenderOptions& options, const RadianceFn& radiance,
                   Image* image);

}  // namespace glint::render
