// One call from IR to image: analyze the scene, prepare only what it uses, run the chosen
// integrator over the image with the tile driver.
#pragma once

#include <atomic>
#include <functional>
#include <string>

#include "core/log.h"
#include "render/image.h"
#include "scene/features.h"
#include "scene/scene.h"

namespace glint::render {

enum class AaMode {
    None,      // one ray through each pixel centre (POV-Ray -A)
    Adaptive,  // POV-Ray's sampling method 1 with threshold (+A0.3)
    Grid,      // N x N regular grid per pixel, box filtered
};

struct RenderOptions {
    int width = 320;
    int height = 240;
    AaMode aa = AaMode::None;
    double aa_threshold = 0.3;  // POV-Ray's +A default
    int aa_depth = 3;           // POV-Ray's +R default
    int grid_n = 2;
    int threads = 0;  // 0 = all hardware threads
    // Called with the finished fraction in [0, 1], from any thread, at most every tile.
    std::function<void(double)> progress;
    const std::atomic<bool>* cancel = nullptr;  // render throws Error(Cancelled) when set
};

struct RenderResult {
    Image image;
    scene::Features features;
    double prepare_seconds = 0;
    double render_seconds = 0;
};

RenderResult render(const scene::Scene& scene, const RenderOptions& options, Diagnostics& diag);

}  // namespace glint::render
