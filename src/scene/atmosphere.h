// Atmospheric effects of the IR (POV-Ray 3.7 manual 3.4.4 "Atmospheric Effects"): fog and
// rainbow, applied by the integrator to every ray that travels through open space. Fields are
// stored the way POV-Ray stores them after parsing (atmosph.cpp defaults, Parse_Fog and
// Parse_Rainbow adjustments), so the renderer applies them without re-deriving anything.
#pragma once

#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "scene/color.h"
#include "scene/texture.h"

namespace glint::scene {

enum class FogType { Constant = 1, Ground = 2 };

struct Fog {
    FogType type = FogType::Constant;
    double distance = 0;  // 0: the fog does nothing
    ColorFT color;
    // Ground fog: full density below `offset` along `up`, falling off as 1 / (1 + h^2) with
    // h = (height - offset) / alt above it.
    double offset = 0;
    double alt = 0;
    Vec3 up{0, 1, 0};  // unit; rotate/scale/matrix turn it, translate does not
    bool turbulent = false;
    Vec3 turbulence{0, 0, 0};  // the point scaling POV-Ray applies before the noise
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
    double turb_depth = 0.5;
    FileLoc loc;
};

struct Rainbow {
    // Radians, as Parse_Rainbow leaves them: `angle` is the inner edge (angle - width/2).
    double angle = 0;
    double width = 0;
    double distance = 1.0e7;  // POV-Ray's MAX_DISTANCE
    double jitter = 0;
    Vec3 antisolar{0, 0, 1};  // unit
    Vec3 up{0, 1, 0};         // unit, perpendicular to antisolar
    Vec3 right{1, 0, 0};      // unit
    // Half angles in radians when given; POV-Ray's defaults are the bare number 180.
    double arc_angle = 180;
    double falloff_angle = 180;
    double falloff_width = 0;
    std::vector<ColorMapEntry> color_map;  // indexed by the position across the bow, 0..1
    FileLoc loc;
};

}  // namespace glint::scene
