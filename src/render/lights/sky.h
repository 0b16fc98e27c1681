// The sky as a ray that leaves the scene sees it: the sky_sphere's pigment layers (last listed
// first, each filtering what lies behind it) over the background colour, times the sky's
// emission. One evaluation for both integrators; the path tracer's environment light
// (lights/environment.h) tabulates this same function.
#pragma once

#include "core/math.h"
#include "render/textures/pigment.h"
#include "scene/scene.h"

namespace glint::render {

// `dir` need not be unit length. legacy: POV-Ray before 3.7 (#version < 3.7), whose sky
// attenuates by the layers' combined filter and transmit instead.
Color sky_radiance(const scene::Scene& scene, const PigmentEvaluator& pigments, const Vec3& dir,
                   bool legacy = false);

}  // namespace glint::render
