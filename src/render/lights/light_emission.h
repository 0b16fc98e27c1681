// Where light leaves the lights, for the photon integrator (gi/sppm.h): a photon's start
// point, direction and flux, for every light PathLights samples towards a point. POV-Ray's
// point, spot and area lights emit from their points with the intensity pi * colour in each
// direction (times the spot's cone), as PathLights delivers it; parallel lights and the
// environment send parallel photons over a disc the size of the scene's bounding sphere;
// emitting triangles, discs and spheres emit cosine-weighted from uniformly chosen points
// (triangles and discs from both faces, as PathLights sees them). POV-Ray's lights do not
// dim with distance (first_flight() makes up for it). A light is chosen in
// proportion to its power. Blender lights do not emit photons yet (unsupported()).
#pragma once

#include <string>
#include <vector>

#include "render/lights/path_lights.h"

namespace glint::render {

struct EmissionSample {
    Vec3 origin;
    Vec3 dir;          // unit
    Color power;       // flux carried: emitted radiance x cos / (the densities of this start)
    // The POV-Ray light it left (not a parallel one), whose photon changes over its first
    // flight (first_flight()); -1 for other lights.
    int pov_light = -1;
};

class LightEmission {
public:
    // `environment`: the environment's radiance along a direction (towards the sky); the
    // scene lies within the sphere (`center`, `radius`).
    LightEmission(const scene::Scene& scene, const PathLights& lights,
                  const EnvironmentDistribution::Radiance& environment, const Vec3& center,
                  double radius);

    // "" when every light can emit photons, else what cannot.
    std::string unsupported() const { return unsupported_; }
    // The total power of the lights (0: nothing to emit).
    double total_power() const { return total_; }
    // One photon start from five uniform numbers.
    bool sample(double u_light, Sample2 u_pos, Sample2 u_dir, EmissionSample* out) const;
    // The factor on a photon of POV-Ray light `light` (-1: none, 1) that lands `dist` away
    // from it: POV-Ray's lights do not dim with distance, unless they fade, so the photon
    // carries dist^2 times the fade (intensity pi x colour x dist^2 x fade delivers the
    // irradiance pi x colour x fade that light sampling delivers).
    double first_flight(int light, double dist) const;

private:
    double slot_power(int slot) const;
    bool sample_slot(int slot, Sample2 u_pos, Sample2 u_dir, EmissionSample* out) const;

    const scene::Scene& scene_;
    const PathLights& lights_;
    EnvironmentDistribution::Radiance environment_;
    Vec3 center_;
    double radius_;
    std::vector<double> slot_cdf_;  // over PathLights' slots, by power
    std::vector<double> slot_prob_;
    // Emitting shapes: one CDF over PathLights' triangles then shapes, by power.
    std::vector<double> emitter_cdf_;
    double emitter_total_ = 0;
    double total_ = 0;
    std::string unsupported_;
};

}  // namespace glint::render
