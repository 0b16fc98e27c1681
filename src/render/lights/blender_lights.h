// Blender lights (scene::BlenderLight, the `blender_light` block) as Cycles 3.4 renders them
// (kernel/light/light.h, scene/light.cpp; docs/pbr-mapping.md "Blender lights"):
// - point, spot: a disc of radius r around the location that always faces the shading point,
//   sampled uniformly by area; radiance strength / (4 pi) / (pi r^2), so a light of power P
//   gives the irradiance P / (4 pi d^2) at distance d (r = 0: a point, a delta light). Spots
//   multiply by Cycles 3.4's spot attenuation: cos(angle to the axis), zero outside the cone,
//   times a smoothstep over the blend band.
// - sun: the cone of half-angle angle/2 around its direction, sampled uniformly over the disc
//   of radius tan(angle/2) at unit distance; irradiance strength (W/m^2) on a surface facing it
//   (angle 0: parallel rays).
// - area: a one-sided rectangle (sampled by solid angle, the spherical rectangle of Urena et
//   al. 2013) or ellipse (sampled uniformly by area) with radiance strength / (4 A), times the
//   spread attenuation (a soft-box grid, normalised as Cycles does) when spread < 180 degrees;
//   with spread the rectangle is first clipped to the part that can light the point.
// BSDF rays see the discs, areas and the sun's disc (Multiple Importance on, Cycles'
// default), camera rays only with visible_camera (off by default in Blender 3.4), neither
// sees points (r = 0) or angle-0 suns; rays pass through lights, lights cast no shadows.
#pragma once

#include <vector>

#include "core/math.h"
#include "render/sampling/sampler.h"
#include "scene/light.h"

namespace glint::render {

// One Blender light in Cycles' kernel terms.
class CyclesLight {
public:
    explicit CyclesLight(const scene::Light& light);

    struct Sample {
        Vec3 wi;          // unit direction from the shading point to the light
        double dist = 0;  // to the sampled point (kInfinity: the sun)
        Color value;      // radiance / pdf (delta lights: irradiance on a surface facing it)
        double pdf = 0;   // solid-angle pdf; 0 for delta lights (no MIS)
    };
    // Next-event estimation from the shading point p (Cycles' light_sample).
    bool sample(const Vec3& p, Sample2 u, Sample* out) const;

    // Whether BSDF rays can hit the light (not a point or an angle-0 sun).
    bool visible() const { return visible_; }
    bool visible_camera() const { return visible_ && camera_; }
    // The ray from `from` along the unit `dir`, up to tmax (kInfinity: it left the scene):
    // whether it meets the light at a distance in (tmin, tmax], with the radiance it sees
    // there and the solid-angle pdf with which sample() from `from` picks that direction.
    // Visibility (camera or BSDF ray) is the caller's test.
    bool intersect(const Vec3& from, const Vec3& dir, double tmin, double tmax, double* t,
                   Color* radiance, double* pdf) const;

    // For the Whitted integrator: the light color that POV-Ray's lighting model needs at p
    // (lit from the light's centre; the sun: along its direction) for Cycles' irradiance
    // there: irradiance / pi on a surface facing the light. False where none reaches p.
    bool whitted_color(const Vec3& p, Color* color) const;

    scene::BlenderLightType type() const { return type_; }

private:
    double spot_attenuation(const Vec3& from_light) const;
    double spread_attenuation(const Vec3& from_light) const;
    // The rectangle (centre, full-extent axes) that sample() uses from p: the whole light, or
    // with spread the part of it that can reach p. False when none can.
    bool sample_rect(const Vec3& p, Vec3* centre, Vec3* au, Vec3* av) const;

    scene::BlenderLightType type_;
    Vec3 co_;         // location
    Vec3 dir_;        // unit: where it shines
    Color strength_;  // color * power
    // point, spot
    double radius_ = 0, invarea_ = 1;
    double spot_cos_ = 0, spot_smooth_ = 0;
    // sun
    double tan_half_ = 0, cos_half_ = 1;
    // area: full-extent axes
    Vec3 axis_u_, axis_v_;
    bool round_ = false;
    double tan_spread_ = 0, normalize_spread_ = 1;
    bool visible_ = false;
    bool camera_ = false;
};

// Solid angle and a uniformly distributed direction (by solid angle) over the rectangle
// corner + [0,1] ex + [0,1] ey seen from p (Urena, Fajardo, King, "An Area-Preserving
// Parametrization for Spherical Rectangles", EGSR 2013). Returns the solid angle (0 when
// degenerate); with `q`, the point on the rectangle for the sample u.
double spherical_rectangle(const Vec3& p, const Vec3& corner, const Vec3& ex, const Vec3& ey,
                           Sample2 u, Vec3* q);

// The POV-Ray light the Whitted integrator shades a Blender light with: a point light at the
// light's location (the sun: a parallel light), with soft shadows from an area_light grid over
// the disc, rectangle or ellipse (the sun: over its cone). The `blender` field stays set: the
// color comes from CyclesLight::whitted_color.
scene::Light whitted_light(const scene::Light& light);
std::vector<scene::Light> whitted_lights(const std::vector<scene::Light>& lights);
// CyclesLight(light).whitted_color(p, color) for a light from whitted_light().
bool whitted_blender_color(const scene::Light& light, const Vec3& p, Color* color);

}  // namespace glint::render
