// Lights as the path tracer sees them, prepared once per render from the IR:
// - POV-Ray point, spot (the radius/falloff/tightness cone of POV-Ray's spot attenuation, a
//   smooth cubic between radius and falloff), parallel lights, and area lights (a rectangle
//   axis1 x axis2 around the location, sampled uniformly; like POV-Ray's grid of point lights
//   it emits the same in every direction and is invisible to camera and BSDF rays; with
//   `circular`, the ellipse inscribed in that rectangle). A POV-Ray light of color C delivers the irradiance pi * C * cos * fade, so a white Lambert surface
//   shows C * cos as POV-Ray's diffuse 1.0 shows it (docs/pbr-mapping.md).
// - Emissive triangles (meshes and triangles whose material emits), sampled by area times
//   emitted power; BSDF rays that hit them are weighted by MIS (power heuristic).
// - The environment (background color, with the sky_sphere laid over it as POV-Ray 3.7 does),
//   sampled uniformly over the sphere; the integrator evaluates its radiance.
#pragma once

#include <vector>

#include "render/ray.h"
#include "render/sampling/sampler.h"
#include "scene/scene.h"

namespace glint::render {

struct PathLightSample {
    Vec3 wi;                // unit direction from the shading point towards the light
    double dist = 0;        // distance to the light sample along wi (kInfinity: far away)
    Color value;            // radiance / pdf (delta lights: the irradiance factor)
    double pdf = 0;         // solid-angle pdf of this sample; 0 for lights BSDFs cannot hit
    bool environment = false;  // value is 1 / pdf: multiply by the environment along wi
};

class PathLights {
public:
    // `emission[m]`: the emitted radiance of material m where it is constant (black otherwise).
    PathLights(const scene::Scene& scene, const std::vector<Color>& emission);

    // Light slots: each POV-Ray light, all emissive triangles together, the environment.
    int count() const { return static_cast<int>(slots_.size()); }
    // The probability a slot is chosen for one shading point (1 when all are sampled).
    double select_prob() const { return sample_all() ? 1.0 : 1.0 / std::max(1, count()); }
    bool sample_all() const { return count() <= kSampleAllMax; }
    bool sample(int slot, const Vec3& p, Sample2 u, PathLightSample* out) const;

    bool has_environment() const { return has_env_; }
    double environment_pdf() const { return has_env_ ? select_prob() / (4 * kPi) : 0.0; }
    // Whether BSDF rays hitting this object could have been light-sampled.
    bool emitter_object(int object) const {
        return object >= 0 && object < static_cast<int>(emitter_object_.size()) &&
               emitter_object_[object];
    }
    // Solid-angle pdf with which light sampling would have chosen a point with emission `le`
    // seen at distance `dist` under cosine `cos_light` on an emitter object.
    double triangle_pdf(const Color& le, double dist, double cos_light) const;

    static constexpr int kSampleAllMax = 8;

private:
    enum class SlotKind { Pov, Triangles, Environment };
    struct Slot {
        SlotKind kind;
        int light = -1;
    };
    struct Tri {
        Vec3 p0, e1, e2, n;  // n: unit geometric normal
        double area;
        Color le;
    };
    Color pov_factor(const scene::Light& l, const Vec3& from_light, double dist) const;

    const scene::Scene& scene_;
    std::vector<Slot> slots_;
    std::vector<Tri> tris_;
    std::vector<double> tri_cdf_;  // normalized cumulative area * average emission
    double tri_total_ = 0;
    std::vector<char> emitter_object_;
    bool has_env_ = false;
};

}  // namespace glint::render
