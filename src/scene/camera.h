// The camera as the importer resolved it: POV-Ray's order-dependent camera statements
// (look_at, angle, sky, right/up/direction, transforms) are already applied, so a ray through
// normalized screen coordinates (sx, sy) in [-0.5, 0.5] is
//   perspective:  origin = location,                     dir = direction + sx*right + sy*up
//   orthographic: origin = location + sx*right + sy*up,  dir = direction
// with sx growing to the right and sy growing upwards. The other kinds are POV-Ray's
// non-linear projections (render/camera.cpp); for them `angle` is always set (POV-Ray's
// default 90) and right/up/direction keep their lengths (the renderer normalizes them).
#pragma once

#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "core/transform.h"

namespace glint::scene {

enum class CameraKind {
    Perspective,
    Orthographic,
    Fisheye,
    UltraWideAngle,
    Omnimax,
    Panoramic,
    Cylinder1,  // vertical cylinder, `angle` horizontally
    Cylinder2,  // horizontal cylinder, `angle` vertically
    Cylinder3,  // vertical cylinder, orthographic vertically
    Cylinder4,  // horizontal cylinder, orthographic horizontally
    Spherical,  // `angle H [, V]`
};

// A thin lens in front of the camera (Blender's depth of field): rays start on the aperture
// and meet at the focal distance along the view direction. Off when radius is 0.
struct Lens {
    double radius = 0;          // aperture radius, scene units
    double focal_distance = 1;  // along `direction`
    int blades = 0;             // 0: a round aperture, else a polygon of that many blades
    double rotation = 0;        // blade rotation, radians
    double ratio = 1;           // anamorphic: aperture width / height
};

// The keyword of a camera kind ("cylinder 1" for Cylinder1).
const char* camera_kind_name(CameraKind kind);

struct Camera {
    CameraKind kind = CameraKind::Perspective;
    Vec3 location{0, 0, 0};
    Vec3 direction{0, 0, 1};
    Vec3 right{1.33, 0, 0};
    Vec3 up{0, 1, 0};
    Vec3 sky{0, 1, 0};       // kept for printing; already applied to right/up
    double angle = 0;        // field of view in degrees if given, else 0 (perspective/ortho)
    double h_angle = 360;    // spherical camera: horizontal and vertical field of view
    double v_angle = 180;
    Lens lens;
    // Motion blur (Blender): the camera's matrix (scale cleared) at evenly spaced shutter
    // times 0 ... 1, beside `centre`, the one the fields above were resolved from. Empty: the
    // camera stays put.
    std::vector<Matrix4> motion;
    Matrix4 centre;
    FileLoc loc;
};

}  // namespace glint::scene
