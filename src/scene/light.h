// Light sources with POV-Ray's defaults (reference manual 3.4.7 "Light Sources").
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/error.h"
#include "core/math.h"

namespace glint::scene {

struct Object;

enum class LightKind { Point, Spot, Cylinder };

// POV-Ray area_light: a grid of size1 x size2 point lights spanning axis1 x axis2.
struct AreaLight {
    Vec3 axis1{1, 0, 0};
    Vec3 axis2{0, 1, 0};
    int size1 = 1;
    int size2 = 1;
    int adaptive = 100;  // POV-Ray's LightSource default (point.cpp): the full grid
    bool jitter = false;
    bool circular = false;
    bool orient = false;
};

// A Blender 3.4 light (glint's `blender_light { ... }` block, which the Blender add-on
// writes): the path tracer renders it as Cycles 3.4 does, in Cycles' units (docs/pbr-mapping.md
// "Blender lights"). Its Light holds the location and the color; defaults are Blender's.
enum class BlenderLightType { Point, Spot, Sun, Area };

struct BlenderLight {
    BlenderLightType type = BlenderLightType::Point;
    Vec3 direction{0, -1, 0};  // unit: where it shines (spot, sun, area), Blender's object -Z
    double power = 10;         // W (point, spot, area); sun: W/m^2. Emits color * power.
    double radius = 0.25;      // point, spot: the emitting disc's radius (0: a point)
    double spot_size = 45;     // spot: full cone angle, degrees
    double spot_blend = 0.15;  // spot: 0..1
    double angle = 0.526;      // sun: angular diameter, degrees (0: parallel rays)
    bool ellipse = false;      // area: ellipse (else rectangle)
    double size_x = 0.25, size_y = 0.25;  // area: full extents along axis_x, axis_y
    Vec3 axis_x{1, 0, 0}, axis_y{0, 0, 1};  // area: unit local X and Y
    double spread = 180;       // area: degrees
    bool visible_camera = false;  // camera rays see it (Blender's default for lights: off)
};

struct Light {
    LightKind kind = LightKind::Point;
    Vec3 location{0, 0, 0};
    Color color{1, 1, 1};
    // `parallel`: rays arrive along (point_at - location) everywhere, like the sun.
    bool parallel = false;
    Vec3 point_at{0, 0, 1};
    double radius = 30;    // spot: full-intensity cone half-angle, degrees
    double falloff = 45;   // spot: zero-intensity cone half-angle, degrees
    double tightness = 0;  // spot: cosine exponent
    bool shadowless = false;
    double fade_distance = 0;  // 0 = no fading
    double fade_power = 0;
    // Participating media: `media_interaction off` leaves the light out of media scattering;
    // `media_attenuation on` dims it through the atmosphere's media (and fog) on the way.
    bool media_interaction = true;
    bool media_attenuation = false;
    // `photons { refraction B reflection B area_light }`: -1 unset, 0 off, 1 on.
    int photon_refraction = -1, photon_reflection = -1;
    bool photon_area_light = false;
    std::optional<AreaLight> area;
    std::optional<BlenderLight> blender;  // blender_light: only location and color used too
    // POV-Ray `light_group`: -1, a global light that lights every object (but those with
    // Object::no_global_lights); otherwise it lights only the objects whose light_group is
    // this. Every object casts shadows from it all the same.
    int group = -1;
    // A group light also lights the objects of these groups (POV-Ray lets a group's lights
    // into a group nested in it that is a copy of a declared one).
    std::vector<int> also_groups;
    // `projected_through { OBJECT }`: the light reaches a point only along a ray that meets
    // this object (world space, no textures), and only what lies before that meeting
    // shadows it (trace.cpp TracePointLightShadowRay). Null: none.
    std::shared_ptr<const Object> projected_through;
    FileLoc loc;
};

}  // namespace glint::scene
