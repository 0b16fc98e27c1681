// Cycles 3.4's panoramic projections (Blender camera type PANO): a point (u, v) of the image,
// both in [0, 1] from the lower left corner, to a direction in the panorama's own frame, and
// that frame to the camera's. Used by render::Camera for scene::CameraKind::BlenderPanorama;
// formulas from intern/cycles/kernel/camera/projection.h and blender/camera.cpp (3.4).
#pragma once

#include "core/math.h"
#include "scene/camera.h"

namespace glint::render {

// The direction through image point (u, v) in the panorama frame: x looks forward, y to the
// left, z up (the mirror ball's frame: x right, y backward, z up). The zero vector where the
// projection has no ray (outside a fisheye's image circle or the mirror ball's disc): Cycles
// traces nothing there, so the pixel stays black (and opaque).
Vec3 panorama_direction(const scene::Panorama& p, double u, double v);

// A panorama-frame vector in world space, for a camera with unit `forward`, `right` and `up`
// (Cycles turns the frame so that its forward axis is the Blender camera's -Z).
Vec3 panorama_to_world(scene::PanoramaType type, const Vec3& d, const Vec3& forward,
                       const Vec3& right, const Vec3& up);

// Depth of field on a panorama as Cycles does it (camera_sample_panorama): the ray through
// (lens_x, lens_y), a point on the aperture in the plane perpendicular to `dir`, aimed at the
// point `focal_distance` along `dir`. In and out in the panorama frame; *origin is the offset
// from the camera.
void panorama_lens(const Vec3& dir, double focal_distance, double lens_x, double lens_y,
                   Vec3* origin, Vec3* out_dir);

}  // namespace glint::render
