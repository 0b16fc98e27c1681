// The film's public side: what a render's pixels are kept in, what an interrupted render had
// finished, and the block size the tile driver cuts the image into (parts of a render are cut
// on it). The driver that fills them is film/driver.h, inside the renderer.
#pragma once

#include <cstddef>
#include <memory>
#include <utility>

#include "core/error.h"
#include "image/image.h"

namespace glint::render {

// POV-Ray's render_block_size default: adaptive AA compares pixels within such blocks.
constexpr int kBlockSize = 32;

// What run_path_tiles fills: the image, and with options.aovs / options.variance the
// per-pixel outputs (each width x height RGBA, alpha 1; left empty when not asked for).
struct PathFilm {
    Image image;
    Image albedo;    // mean over the pixel's samples of FirstHit::albedo (misses count 0)
    Image normal;    // mean of FirstHit::normal, -1..1 (not normalized again; misses 0)
    Image depth;     // mean of FirstHit::depth in R, G and B (misses count 0)
    Image variance;  // per channel: the variance of the pixel's mean, s^2 / n (0 when n < 2)
};

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
