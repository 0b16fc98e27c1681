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
#include <utility>

#include "core/error.h"
#include "render/camera.h"
#include "render/integrators/aov.h"
#include "image/image.h"
#include "render/render.h"

namespace glint::render {

// Names one camera sample, so stochastic integrators (the path tracer) can seed their random
// numbers from it rather than from the thread: the same image whatever the thread count.
struct SampleId {
    int x = 0;           // pixel column (may be -1 for adaptive AA's border samples)
    int y = 0;           // pixel row
    uint32_t index = 0;  // sample number within the pixel, in the driver's fixed order
};

// Radiance along a camera ray. Must be thread-safe (called concurrently).
using RadianceFn = std::function<Color(const Ray& ray, const SampleId& id)>;

// POV-Ray's render_block_size default: adaptive AA compares pixels within such blocks.
constexpr int kBlockSize = 32;

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

// What run_path_tiles fills: the image, and with options.aovs / options.variance the
// per-pixel outputs (each width x height RGBA, alpha 1; left empty when not asked for).
struct PathFilm {
    Image image;
    Image albedo;    // mean over the pixel's samples of FirstHit::albedo (misses count 0)
    Image normal;    // mean of FirstHit::normal, -1..1 (not normalized again; misses 0)
    Image depth;     // mean of FirstHit::depth in R, G and B (misses count 0)
    Image variance;  // per channel: the variance of the pixel's mean, s^2 / n (0 when n < 2)
};

// The path tracer's loop: options.spp jittered samples per pixel (pixel jitter from pair 0 of
// the PixelSampler of (pixel, sample, options.seed)), averaged with a box filter. Samples are
// taken in progressive passes (1, 1, 2, 4, ... per pixel); with options.time_limit > 0 the
// render stops after the pass that crosses the limit. Each pixel sums its samples in sample
// order (the variance by Welford's update in the same order), so every output is
// bit-identical whatever the thread count. Returns the samples taken per pixel.
int run_path_tiles(const Camera& camera, const RenderOptions& options,
                   const PathRadianceFn& radiance, PathFilm* film);
// The same without AOVs or variance, for a plain radiance function.
// Both check cancellation before every sample and throw Interrupted.
int run_path_tiles(const Camera& camera, const RenderOptions& options, const RadianceFn& radiance,
                   Image* image);

// What an interrupted render had finished (glint render --save-partial writes it). The images
// are complete, width x height:
// - Whitted (samples_per_pixel 0): the finished tiles as rendered; every other pixel is
//   transparent black (RGBA 0, 0, 0, 0).
// - Path tracer, after at least one finished progressive pass: every pixel at the
//   samples_per_pixel of the last finished pass, bit-identical to a full render with
//   --spp samples_per_pixel (the same sums in the same order); alpha 1 everywhere.
// - Path tracer interrupted during its first pass (samples_per_pixel 0): the tiles that
//   finished it at 1 sample, the rest transparent black, like Whitted.
// AOVs and variance follow the image (empty when not asked for).
struct PartialRender {
    PathFilm film;
    int samples_per_pixel = 0;  // path tracer: of the last finished pass; 0: see tiles
    int spp_requested = 0;      // path tracer: options.spp; 0 for Whitted
    size_t tiles_done = 0;      // tiles whose pixels are kept (all of them after a pass)
    size_t tiles_total = 0;
};

class Interrupted : public Error {
public:
    explicit Interrupted(std::shared_ptr<const PartialRender> partial)
        : Error(ErrorKind::Cancelled, {}, "render cancelled"), partial_(std::move(partial)) {}
    const PartialRender& partial() const { return *partial_; }

private:
    std::shared_ptr<const PartialRender> partial_;
};

}  // namespace glint::render
