// The camera as the importer resolved it: POV-Ray's order-dependent camera statements
// (look_at, angle, sky, right/up/direction, transforms) are already applied, so a ray through
// normalized screen coordinates (sx, sy) in [-0.5, 0.5] is
//   perspective:  origin = location,                     dir = direction + sx*right + sy*up
//   orthographic: origin = location + sx*right + sy*up,  dir = direction
// with sx growing to the right and sy growing upwards.
#pragma once

#include "core/error.h"
#include "core/math.h"

namespace glint::scene {

enum class CameraKind { Perspective, Orthographic };

struct Camera {
    CameraKind kind = CameraKind::Perspective;
    Vec3 location{0, 0, 0};
    Vec3 direction{0, 0, 1};
    Vec3 right{1.33, 0, 0};
    Vec3 up{0, 1, 0};
    Vec3 sky{0, 1, 0};       // kept for printing; already applied to right/up
    double angle = 0;        // horizontal field of view in degrees if given, else 0
    FileLoc loc;
};

}  // namespace glint::scene
