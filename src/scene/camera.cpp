#include "scene/camera.h"

namespace glint::scene {

const char* camera_kind_name(CameraKind kind) {
    switch (kind) {
        case CameraKind::Perspective: return "perspective";
        case CameraKind::Orthographic: return "orthographic";
        case CameraKind::Fisheye: return "fisheye";
        case CameraKind::UltraWideAngle: return "ultra_wide_angle";
        case CameraKind::Omnimax: return "omnimax";
        case CameraKind::Panoramic: return "panoramic";
        case CameraKind::Cylinder1: return "cylinder 1";
        case CameraKind::Cylinder2: return "cylinder 2";
        case CameraKind::Cylinder3: return "cylinder 3";
        case CameraKind::Cylinder4: return "cylinder 4";
        case CameraKind::Spherical: return "spherical";
        case CameraKind::BlenderPanorama: return "blender_panorama";
        case CameraKind::Mesh: return "mesh_camera";
    }
    return "?";
}

}  // namespace glint::scene
