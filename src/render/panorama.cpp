#include "render/panorama.h"

#include <algorithm>
#include <cmath>

namespace glint::render {

using scene::PanoramaType;

namespace {

// The fisheyes' common last step (projection.h): polar angle theta from the forward axis,
// azimuth from the image point's direction (a, b) on the sensor; a to the right, b up.
Vec3 fisheye_direction(double a, double b, double r, double theta) {
    double phi = std::acos(std::clamp(r != 0 ? a / r : 0.0, -1.0, 1.0));
    if (b < 0) phi = -phi;
    const double st = std::sin(theta);
    return Vec3(std::cos(theta), -std::cos(phi) * st, std::sin(phi) * st);
}

}  // namespace

Vec3 panorama_direction(const scene::Panorama& p, double u, double v) {
    switch (p.type) {
        case PanoramaType::Equirectangular: {
            // Cycles' equirectangular_range: longitude from -min at u = 0 to -max at u = 1
            // (to the right), latitude from min at the bottom to max at the top.
            const double phi = (p.longitude_min - p.longitude_max) * u - p.longitude_min;
            const double theta =
                (p.latitude_min - p.latitude_max) * v + kPi / 2 - p.latitude_min;
            const double st = std::sin(theta);
            return Vec3(st * std::cos(phi), st * std::sin(phi), std::cos(theta));
        }
        case PanoramaType::FisheyeEquidistant: {
            const double a = 2 * (u - 0.5), b = 2 * (v - 0.5);
            const double r = std::sqrt(a * a + b * b);
            if (r > 1) return Vec3(0, 0, 0);
            return fisheye_direction(a, b, r, r * p.fov * 0.5);
        }
        case PanoramaType::FisheyeEquisolid: {
            const double a = (u - 0.5) * p.sensor_width, b = (v - 0.5) * p.sensor_height;
            const double r = std::sqrt(a * a + b * b);
            const double rmax = 2 * p.lens * std::sin(p.fov * 0.25);
            if (r > rmax || !(p.lens > 0)) return Vec3(0, 0, 0);
            const double s = r / (2 * p.lens);
            if (s > 1) return Vec3(0, 0, 0);
            return fisheye_direction(a, b, r, 2 * std::asin(s));
        }
        case PanoramaType::FisheyeLensPolynomial: {
            const double a = (u - 0.5) * p.sensor_width, b = (v - 0.5) * p.sensor_height;
            const double r = std::sqrt(a * a + b * b);
            const double theta =
                -(p.k[0] + r * (p.k[1] + r * (p.k[2] + r * (p.k[3] + r * p.k[4]))));
            if (std::fabs(theta) > 0.5 * p.fov) return Vec3(0, 0, 0);
            return fisheye_direction(a, b, r, theta);
        }
        case PanoramaType::MirrorBall: {
            // The ball's normal under (u, v), seen from +y; the view ray (0, -1, 0) reflected.
            const double x = 2 * u - 1, z = 2 * v - 1;
            if (x * x + z * z > 1) return Vec3(0, 0, 0);
            const double y = -std::sqrt(std::max(1 - x * x - z * z, 0.0));
            const Vec3 n(x, y, z), i(0, -1, 0);
            return n * (2 * dot(n, i)) - i;
        }
        case PanoramaType::EquiangularCubemapFace: {
            const double a = std::tan((1 - u) * kPi / 2 - kPi / 4);
            const double b = std::tan(v * kPi / 2 - kPi / 4);
            return Vec3(1, a, b);
        }
    }
    return Vec3(0, 0, 0);
}

Vec3 panorama_to_world(PanoramaType type, const Vec3& d, const Vec3& forward, const Vec3& right,
                       const Vec3& up) {
    // blender_camera_matrix: the mirror ball's frame is (x, z, y) of the Blender camera's
    // local axes (X right, Y up, Z backward); every other panorama's is (-Z, -X, Y).
    if (type == PanoramaType::MirrorBall) return right * d.x + up * d.z - forward * d.y;
    return forward * d.x - right * d.y + up * d.z;
}

void panorama_lens(const Vec3& dir, double focal_distance, double lens_x, double lens_y,
                   Vec3* origin, Vec3* out_dir) {
    const Vec3 d = normalize(dir);
    const Vec3 focus = d * focal_distance;
    // The aperture's axes: the panorama's x made perpendicular to the ray, and their cross
    // product (Cycles' U and V). A ray along x itself has no such U: take y.
    Vec3 u = Vec3(1, 0, 0) - d * d.x;
    if (!(length_squared(u) > 1e-20)) u = Vec3(0, 1, 0) - d * d.y;
    u = normalize(u);
    const Vec3 v = normalize(cross(d, u));
    *origin = u * lens_x + v * lens_y;
    *out_dir = normalize(focus - *origin);
}

}  // namespace glint::render
