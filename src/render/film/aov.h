// What the path tracer's camera ray sees at its first visible hit (alpha pass-throughs
// skipped): the auxiliary outputs (AOVs) `glint render --aov` writes beside the image, the
// kind of guides denoisers and compositors read. Filled by PathIntegrator::li, averaged per
// pixel by run_path_tiles.
#pragma once

#include "core/math.h"

namespace glint::render {

struct FirstHit {
    bool hit = false;  // false: the camera ray left the scene (everything below stays 0)
    Color albedo;      // base color (diffuse reflectance); an emitter with a black base: emission
    Vec3 normal;       // world-space shading normal, turned toward the camera (as Cycles' pass)
    double depth = 0;  // distance along the camera ray (across alpha pass-throughs)
    // The share of the camera's view that is background (Blender's transparent film: the
    // world seen through nothing but transparent surfaces) or holdout: 1 - alpha, as Cycles
    // accumulates it (the average over RGB of the path's throughput there). Filled whether
    // or not the hit fields are.
    double transparent = 0;
};

}  // namespace glint::render
