#include "render/camera.h"

namespace glint::render {

Camera::Camera(const scene::Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height) {}

void Camera::screen(double x, double y, double* sx, double* sy) const {
    // POV-Ray moves to the pixel centre with x += 0.5, y -= 0.5 and then maps
    // x0 = x / width - 0.5, y0 = ((height - 1) - y) / height - 0.5 (tracepixel.cpp).
    *sx = (x + 0.5) / width_ - 0.5;
    *sy = ((height_ - 1) - (y - 0.5)) / height_ - 0.5;
}

Ray Camera::generate(double x, double y) const {
    double sx, sy;
    screen(x, y, &sx, &sy);
    Ray ray;
    if (camera_.kind == scene::CameraKind::Orthographic) {
        ray.origin = camera_.location + camera_.right * sx + camera_.up * sy;
        ray.dir = normalize(camera_.direction);
    } else {
        ray.origin = camera_.location;
        ray.dir = normalize(camera_.direction + camera_.right * sx + camera_.up * sy);
    }
    return ray;
}

}  // namespace glint::render
