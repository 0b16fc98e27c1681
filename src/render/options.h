// What a render is asked for: the image size and region, anti-aliasing, the integrator and its
// settings, progress and cancellation. Shared by the facade (render.h), the film's tile driver
// and the integrators.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "render/film/pixel_filter.h"

namespace glint::render {

enum class AaMode {
    None,      // one ray through each pixel centre (POV-Ray -A)
    Adaptive,  // POV-Ray's sampling method 1 with threshold (+A0.3)
    Adaptive2, // POV-Ray's sampling method 2: recursive corner subdivision (+AM2 +A0.3)
    Grid,      // N x N regular grid per pixel, box filtered
};

enum class IntegratorKind {
    Whitted,  // POV-Ray's classic model
    Path,     // Monte Carlo path tracer (spp samples per pixel, averaged)
    Sppm,     // stochastic progressive photon mapping (spp passes; gi/sppm.h)
};

// A rectangle of pixels, [x0, x1) x [y0, y1), row 0 at the top.
struct Region {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    bool operator==(const Region&) const = default;
};

struct RenderOptions {
    int width = 320;
    int height = 240;
    // Only these pixels of the width x height image (empty: all of them); the result is that
    // rectangle, each pixel bit for bit as the whole image's render has it (the driver's
    // tiles are blocks of the whole image, so adaptive AA compares the same neighbours, and
    // the path tracer's random numbers depend on the pixel alone).
    Region region;
    AaMode aa = AaMode::None;
    double aa_threshold = 0.3;  // POV-Ray's +A default
    int aa_depth = 3;           // POV-Ray's +R default
    // Adaptive modes: the sub-samples' jitter as a fraction of their spacing (POV-Ray's +J
    // amount: on with 1.0 by default; 0 is -J). Position-hashed, so deterministic.
    double aa_jitter = 1.0;
    int grid_n = 2;
    int threads = 0;  // 0 = all hardware threads
    IntegratorKind integrator = IntegratorKind::Whitted;
    // Path tracer: samples per pixel (with a time limit: at most), bounces, sampler seed, and
    // a wall-clock limit in seconds (0: none) checked between progressive passes.
    int spp = 16;
    int max_depth = 8;
    uint32_t seed = 0;
    double time_limit = 0;
    // Path tracer: Cycles' adaptive sampling (Noise Threshold): past a minimum, a pixel stops
    // taking samples once its noise estimate is under the threshold (checked every 16
    // samples). 0: Cycles' automatic threshold (1 / spp, at least 0.001) and minimum
    // (16 / threshold^0.3, at least 4).
    bool adaptive = false;
    double adaptive_threshold = 0;
    int adaptive_min_samples = 0;
    // Photon integrator (IntegratorKind::Sppm): photons per pass (0: one per pixel) and the
    // initial gather radius in pixel footprints.
    long photons = 0;
    double photon_radius = 2.0;
    // Path tracer: also average the first hit's albedo, normal and depth per pixel, and
    // estimate the variance of each pixel's mean (RenderResult::albedo ... variance).
    bool aovs = false;
    bool variance = false;
    // Path tracer: the pixel filter samples follow (film/pixel_filter.h): glint's box over the
    // pixel unless a Blender scene brings Cycles' filter and width.
    PixelFilterKind pixel_filter = PixelFilterKind::GlintBox;
    double filter_width = 1.5;
    // Path tracer: Cycles' clamping and Filter Glossy (0: off; integrators/path.h).
    double clamp_direct = 0, clamp_indirect = 0, filter_glossy = 0;
    // Path tracer: emitters are picked per shading point by the light tree (lights/
    // light_tree.h); off, by their power alone (Cycles' Light Tree unchecked).
    bool light_tree = true;
    // Path tracer: Cycles' bounce limits per kind (Light Paths > Max Bounces; -1: none, the
    // CLI's default: max_depth alone limits the path).
    int diffuse_bounces = -1, glossy_bounces = -1, transmission_bounces = -1,
        transparent_bounces = -1, volume_bounces = -1;
    // Path tracer, Blender's Film > Transparent: a camera ray that reaches the world through
    // nothing but transparent surfaces adds no world colour, only transparency. With `alpha`
    // the film's alpha is 1 - the camera's mean transparency (FirstHit::transparent), as
    // Cycles' combined pass; without it alpha is 1 (render() sets it for transparent film
    // and for holdouts).
    bool film_transparent = false;
    // Film > Transparent Glass's roughness threshold (negative: off): a transmission sampled
    // from a lobe whose alpha_x alpha_y is at most the threshold to the fourth (Cycles'
    // background.cpp squares it twice) leaves the view transparent, as a transparent surface
    // does.
    double film_transparent_glass = -1;
    // Path tracer, Cycles' Volumes panel (RenderOptions from a Blender scene): ray marching of
    // volumes that vary in space.
    double volume_step_rate = 1.0;
    int volume_max_steps = 1024;
    bool alpha = false;
    // Called with the finished fraction in [0, 1], from any thread, at most every tile.
    std::function<void(double)> progress;
    const std::atomic<bool>* cancel = nullptr;  // render throws Error(Cancelled) when set
};

}  // namespace glint::render
