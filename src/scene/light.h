// Light sources with POV-Ray's defaults (reference manual 3.4.7 "Light Sources").
#pragma once

#include <optional>

#include "core/error.h"
#include "core/math.h"

namespace glint::scene {

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
    std::optional<AreaLight> area;
    FileLoc loc;
};

}  // namespace glint::scene
