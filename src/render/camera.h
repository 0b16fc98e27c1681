// Primary rays from the resolved IR camera with POV-Ray 3.7's screen mapping
// (render/tracepixel.cpp, CreateCameraRay): the integrator driver asks for rays at continuous
// raster positions; pixel (x, y), top row first, has its centre at (x, y).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "render/mesh_camera.h"
#include "render/ray.h"
#include "render/textures/pattern.h"
#include "scene/camera.h"

namespace glint::render {

class Camera {
public:
    // `meshes`: the scene's, for a mesh_camera (scene::CameraKind::Mesh; without them it
    // traces no ray). `normal_context`: what a camera `normal` pattern sees (the scene's noise
    // generator, functions, images); the pointers must outlive the camera.
    Camera(const scene::Camera& camera, int width, int height,
           const std::vector<scene::Mesh>* meshes = nullptr,
           const PatternContext& normal_context = {});

    // Ray through raster position (x, y): integer values are pixel centres, x grows to the right
    // and y downwards (so supersamples at x +- 0.3 stay inside pixel x). Direction normalized.
    // None where the projection traces no ray (outside a fisheye's circle): POV-Ray leaves
    // such pixels black.
    std::optional<Ray> generate(double x, double y) const;
    // The same through a thin lens (scene::Lens): (lens_u, lens_v) in [0, 1)^2 pick the point
    // on the aperture, as Cycles samples it (a concentric disc, or a polygon of `blades`);
    // the ray passes the point the pinhole ray meets on the focal plane. Perspective,
    // orthographic and Blender panoramic cameras; the others ignore the lens.
    std::optional<Ray> generate(double x, double y, double lens_u, double lens_v) const;
    bool has_lens() const { return camera_.lens.radius > 0; }
    // The IR camera the rays come from (focal blur reads its settings and axes).
    const scene::Camera& ir() const { return camera_; }
    // A mesh_camera's rays per pixel (1 for every other camera) and ray `ray_number` of a
    // raster position; the pixel is the mean of the rays it has.
    int rays_per_pixel() const { return mesh_ ? mesh_->rays_per_pixel() : 1; }
    std::optional<Ray> generate(double x, double y, int ray_number) const;
    // Whether every primary ray starts at the camera location (not orthographic, not the
    // cylinder projections that are orthographic along one axis).
    bool rays_start_at_location() const;
    // Normalized screen coordinates of a raster position, as in scene/camera.h.
    void screen(double x, double y, double* sx, double* sy) const;

private:
    std::optional<Ray> pinhole(double x, double y) const;
    // Blender's clipping (scene::Camera::clip_start, clip_end) of a ray whose direction
    // without the lens was `pinhole`, as Cycles' camera_sample_* clip.
    void clip(const Vec3& pinhole, Ray* ray) const;
    // Moves a perspective or orthographic ray through the thin lens (scene::Lens).
    void with_lens(double lens_u, double lens_v, Ray* ray) const;
    std::optional<Ray> generate_panorama(double x, double y, double lens_u, double lens_v) const;
    // Bends a POV-Ray ray's direction by the camera `normal` evaluated at `at`.
    void perturb(const Vec3& at, Ray* ray) const;

    scene::Camera camera_;
    PatternContext normal_ctx_;
    std::shared_ptr<const MeshCameraRays> mesh_;
    double width_;
    double height_;
    double aspect_ = 1;
    double length_right_ = 1, length_up_ = 1;
    bool clips_ = false;
    Vec3 forward_;  // the unit view axis (clipping distances are along it)
};

}  // namespace glint::render
