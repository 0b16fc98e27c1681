// POV-Ray 3.7's focal blur for the classic renderer (render/tracepixel.cpp, TracePixel's
// TraceRayWithFocalBlur, JitterCameraRay and FocalBlurData): a pixel averages rays whose eye
// points lie on the aperture (a hexagonal grid, topped up with a Halton disc) and meet the
// pinhole ray on the focal plane. Rays are taken in POV-Ray's batches until their variance
// passes its chi-square test or blur_samples is reached. Every random choice comes from
// POV-Ray's hash and jitter tables indexed by the raster position, so a pixel's colour does not
// depend on the thread that traces it. Used by the tile driver (render/film/driver.cpp).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "core/math.h"
#include "render/camera.h"
#include "render/ray.h"
#include "scene/camera.h"

namespace glint::render {

class FocalBlur {
  public:
    // `camera` must outlive this; its IR camera's focal_blur must be active.
    explicit FocalBlur(const Camera& camera);

    // The colour at raster position (x, y) (pixel centres at integers, as Camera::generate),
    // `trace` giving the radiance along each ray. `rays`, when given, receives how many rays
    // were taken.
    Color pixel(double x, double y, const std::function<Color(const Ray&)>& trace,
                int* rays = nullptr) const;

    // Ray `number` (an index into the aperture grid) through raster position (x, y), already
    // moved within the pixel. None where the camera sends no ray there.
    std::optional<Ray> ray(double x, double y, int number) const;

    // The aperture points (radius 0.5 disc, unit aperture) in the order rays take them.
    const std::vector<Vec2>& grid() const { return grid_; }
    // Entry i: the largest variance accepted after i + 1 rays.
    const std::vector<double>& thresholds() const { return thresholds_; }

  private:
    const Camera& camera_;
    scene::Camera ir_;
    std::vector<Vec2> grid_;
    std::vector<double> thresholds_;
    const int* batches_ = nullptr;  // rays per batch, 0-terminated; null: batches of 4
    double max_jitter_ = 0;
    Vec3 x_perp_, y_perp_;    // the aperture's axes
    double focal_scale_ = 1;  // focal distance over the direction's length
};

}  // namespace glint::render
