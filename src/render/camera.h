// Primary rays from the resolved IR camera with POV-Ray 3.7's screen mapping
// (render/tracepixel.cpp, CreateCameraRay): the integrator driver asks for rays at continuous
// raster positions; pixel (x, y), top row first, has its centre at (x, y).
#pragma once

#include "render/ray.h"
#include "scene/camera.h"

namespace glint::render {

class Camera {
public:
    Camera(const scene::Camera& camera, int width, int height);

    // Ray through raster position (x, y): integer values are pixel centres, x grows to the right
    // and y downwards (so supersamples at x +- 0.3 stay inside pixel x). Direction normalized.
    Ray generate(double x, double y) const;
    // Normalized screen coordinates of a raster position, as in scene/camera.h.
    void screen(double x, double y, double* sx, double* sy) const;

private:
    scene::Camera camera_;
    double width_;
    double height_;
};

}  // namespace glint::render
