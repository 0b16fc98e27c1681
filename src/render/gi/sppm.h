// Stochastic progressive photon mapping (Hachisuka and Jensen 2009) for the physically based
// renderer: `--integrator sppm`. Each pass shoots photons from the lights (light_emission.h)
// through the scene's BSDFs, then traces one camera path per pixel through delta bounces to
// its first other vertex (PathIntegrator::li with a VisiblePoint), adds the direct light
// there by light sampling, and gathers the photons within the pixel's radius; the radius
// shrinks as photons accumulate (alpha 2/3), so the estimate is consistent: it converges to
// the path tracer's image, and it renders what the path tracer cannot sample (a point
// light's caustic through glass seen on a diffuse floor). Photons are stored after their
// first bounce only, the direct light coming from light sampling. Deterministic: photon j of
// pass i and pixel (x, y) of pass i each draw from their own sampler, and the photons are
// kept in a fixed order, so the image is the same whatever the thread count, and a region
// renders exactly the whole image's pixels.
#pragma once

#include "core/log.h"
#include "image/image.h"
#include "render/integrators/path.h"
#include "render/options.h"
#include "render/prepare/prepared_scene.h"

namespace glint::render {

struct SppmSettings {
    int max_depth = 8;      // bounces, as the path tracer counts them
    int passes = 16;        // camera passes (options.spp), fewer with a time limit
    long photons = 0;       // photons per pass; 0: one per pixel of the whole image
    double radius = 2.0;    // initial gather radius, in pixel footprints at the first hit
    double alpha = 2.0 / 3.0;  // the share of each pass's photons kept (radius reduction)
};

struct SppmResult {
    Image image;        // the region, linear RGB, alpha 1
    int passes = 0;     // passes done
    long photons = 0;   // photons shot per pass
    uint64_t stored = 0;  // photons stored over all passes
};

// Throws Error(Render) when the scene needs what the photons do not carry
// (PathIntegrator::photon_limits, LightEmission::unsupported), Interrupted on cancellation
// (with the last finished pass).
SppmResult render_sppm(const PreparedScene& prepared, const PathIntegrator& path,
                       const RenderOptions& options, const SppmSettings& settings,
                       Diagnostics& diag);

}  // namespace glint::render
