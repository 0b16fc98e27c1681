// Light sources as the Whitted integrator sees them: for a surface point, the direction to the
// light, how far the shadow ray must go and the light's color after spot and distance
// attenuation (POV-Ray 3.7: Trace::ComputeOneWhiteLightRay, lighting/point.cpp Attenuate_Light).
#pragma once

#include <cstdint>
#include <vector>

#include "scene/light.h"

namespace glint::render {

struct LightSample {
    Vec3 dir;         // unit vector from the point towards the light
    double distance;  // along dir to the light (for parallel lights: to the light's plane)
    Color color;      // attenuated light color
};

class PreparedLight {
public:
    explicit PreparedLight(const scene::Light& light);

    // False when the light cannot reach the point (outside a spot cone, behind a cylinder
    // light), in which case POV-Ray skips it entirely.
    bool sample(const Vec3& p, LightSample* out) const;
    // Direction and shadow-ray length from `p` to the light centre moved by `offset` (an area
    // light sample), without attenuation: POV-Ray's ComputeOneWhiteLightRay.
    void white_ray(const Vec3& p, const Vec3& offset, Vec3* dir, double* depth) const;
    bool casts_shadows() const { return !light_.shadowless; }
    // The share of the light a photon leaving `origin` along unit `dir` carries: the spot
    // or cylinder beam's falloff (POV-Ray's PhotonShootingTask::computeAttenuation).
    double beam(const Vec3& origin, const Vec3& dir) const;
    const scene::Light& light() const { return light_; }
    // Whether it lights a surface whose hit carries `object_flags` (render/ray.h
    // ObjectFlags): light_group's rules (scene::Light::group).
    bool lights_object(uint32_t object_flags) const;

private:
    scene::Light light_;
    Vec3 direction_;      // normalized point_at - location (spot, parallel, cylinder)
    double cos_radius_;   // spot: cosine of the full-intensity half-angle
    double cos_falloff_;  // spot: cosine of the zero-intensity half-angle
};

std::vector<PreparedLight> prepare_lights(const std::vector<scene::Light>& lights);

}  // namespace glint::render
