// Fog and rainbow (POV-Ray 3.7 trace.cpp ComputeRainbow, ComputeFog, ComputeConstantFogColour,
// ComputeGroundFogColour): applied by the Whitted integrator to the color of every ray that
// travels through open space (not inside a solid, non-hollow object), after the surface or
// sky color is known.
#pragma once

#include <vector>

#include "core/math.h"
#include "render/textures/pigment.h"
#include "scene/scene.h"

namespace glint::render {

class Atmosphere {
public:
    // The distance POV-Ray assigns to a ray that hits nothing (BOUND_HUGE).
    static constexpr double kMissDepth = 2.0e10;

    explicit Atmosphere(const scene::Scene& scene);

    bool empty() const { return fogs_.empty() && rainbows_.empty(); }
    bool has_fog() const { return !fogs_.empty(); }

    // `dir` unit; `depth` the distance to the hit (kMissDepth for none). Rainbow first, then
    // the fogs, as TraceRay applies them.
    Color apply(const Vec3& origin, const Vec3& dir, double depth, const Color& color) const;
    // The two halves of apply(), for the atmospheric media that come between them.
    Color apply_rainbow(const Vec3& dir, double depth, const Color& color) const {
        return rainbows_.empty() ? color : rainbow(dir, depth, color);
    }
    Color apply_fog(const Vec3& origin, const Vec3& dir, double depth, const Color& color) const {
        return fogs_.empty() ? color : fog(origin, dir, depth, color);
    }

private:
    Color rainbow(const Vec3& dir, double depth, const Color& color) const;
    Color fog(const Vec3& origin, const Vec3& dir, double depth, const Color& color) const;
    // Transmittance of one fog over [0, width] along the ray (before the minimum transmit).
    double fog_attenuation(const scene::Fog& fog, const Vec3& origin, const Vec3& dir,
                           double width) const;

    std::vector<scene::Fog> fogs_;
    std::vector<scene::Rainbow> rainbows_;
    std::vector<scene::Pigment> rainbow_maps_;  // gradient x with each rainbow's color_map
    int noise_generator_;
    PigmentEvaluator pigments_{nullptr};
};

}  // namespace glint::render
