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
#include "scene/texture.h"

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
    // Blender's panoramic camera as Cycles 3.4 renders it (Camera::panorama).
    BlenderPanorama,
    // POV-Ray 3.7's mesh_camera: rays from the faces of meshes (Camera::mesh_camera).
    Mesh,
};

// One mesh of a mesh_camera: a Scene::meshes index and the transform it was given there.
struct MeshCameraMesh {
    int mesh = -1;
    Transform transform;
};

// POV-Ray's mesh_camera { rays distribution [max_distance] mesh {...}... [smooth] }: each
// pixel's rays leave a face's centroid along its normal (distributions 0-2: the faces by pixel
// index, 0 one mesh per ray, 1 the meshes summed, 2 the meshes side by side), or, for 3, the
// point of the first mesh whose uv coordinates hold the pixel's. `location`.z moves the origin
// along the normal, a negative `direction`.z reverses the rays (tracepixel.cpp).
struct MeshCamera {
    int rays_per_pixel = 1;
    int distribution = 0;
    double max_distance = 0;  // > 0: camera rays see nothing further
    bool smooth = false;      // distribution 3: interpolated vertex normals
    std::vector<MeshCameraMesh> meshes;
};

// Cycles' panorama projections (Blender camera type PANO, camera.cycles.panorama_type).
enum class PanoramaType {
    Equirectangular,
    FisheyeEquidistant,
    FisheyeEquisolid,
    MirrorBall,
    FisheyeLensPolynomial,
    EquiangularCubemapFace,
};

// What a Cycles panorama needs (intern/cycles/kernel/camera/projection.h). Angles in radians,
// lengths in millimetres. The camera's frame is direction (forward), right and up, unit length.
struct Panorama {
    PanoramaType type = PanoramaType::FisheyeEquisolid;
    double fov = kPi;            // fisheye_fov: the image circle's full angle
    double lens = 10.5;          // fisheye_lens (equisolid)
    // The sensor as Cycles fits it to the image (sensor fit applied): equisolid, polynomial.
    double sensor_width = 36, sensor_height = 24;
    double latitude_min = -kPi / 2, latitude_max = kPi / 2;
    double longitude_min = -kPi, longitude_max = kPi;
    double k[5] = {0, 0, 0, 0, 0};  // fisheye_polynomial_k0..k4
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

// POV-Ray's focal blur (camera aperture, focal_point, blur_samples, confidence, variance):
// each pixel averages up to `samples` rays from points of the aperture that meet on the focal
// plane, stopping early once their variance is small enough (render/focal_blur.h). Off while
// aperture or samples is 0. Defaults are POV-Ray 3.7's Camera::Init.
struct FocalBlur {
    double aperture = 0;
    double focal_distance = 1;  // from the location, resolved by the importer
    int samples = 0;            // blur_samples' maximum
    int samples_min = 0;        // blur_samples' minimum (0: one value was given)
    double confidence = 0.9;
    double variance = 1.0 / 10000.0;
    bool active() const { return aperture != 0 && samples > 0; }
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
    FocalBlur focal_blur;    // POV-Ray cameras only
    Panorama panorama;       // kind BlenderPanorama only
    MeshCamera mesh_camera;  // kind Mesh only
    // POV-Ray's camera `normal`: bends every primary ray's direction as a surface normal,
    // evaluated at the projection's screen point (x0, y0, 0). Plain: rays are not bent.
    Normal normal;
    // Blender's Clip Start / End: camera rays start clip_start in front of the camera (along
    // its axis for perspective and orthographic views, along the ray for panoramas) and see
    // nothing past clip_end, as Cycles clips them. POV-Ray cameras never clip.
    double clip_start = 0;
    double clip_end = kInfinity;
    // Motion blur (Blender): the camera's matrix (scale cleared) at evenly spaced shutter
    // times 0 ... 1, beside `centre`, the one the fields above were resolved from. Empty: the
    // camera stays put.
    std::vector<Matrix4> motion;
    Matrix4 centre;
    FileLoc loc;
};

}  // namespace glint::scene
