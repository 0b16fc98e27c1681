#include "render/camera.h"

#include <cmath>

#include "render/panorama.h"
#include "render/textures/normal.h"

namespace glint::render {

using scene::CameraKind;

Camera::Camera(const scene::Camera& camera, int width, int height,
               const std::vector<scene::Mesh>* meshes, const PatternContext& normal_context)
    : camera_(camera), normal_ctx_(normal_context), width_(width), height_(height) {
    if (camera.kind == CameraKind::Mesh && meshes)
        mesh_ = std::make_shared<const MeshCameraRays>(camera.mesh_camera, *meshes,
                                                       camera.location.z,
                                                       camera.direction.z < -1e-10);
    // TracePixel::SetupCamera: the aspect ratio each projection uses, from the vectors'
    // lengths, and the projections other than perspective/orthographic/panoramic/spherical
    // work with unit vectors.
    const double lr = length(camera.right), lu = length(camera.up);
    bool unit = true;
    switch (camera.kind) {
        case CameraKind::Cylinder1:
        case CameraKind::Cylinder3: aspect_ = lu; break;
        case CameraKind::Cylinder2:
        case CameraKind::Cylinder4: aspect_ = lr; break;
        case CameraKind::UltraWideAngle: aspect_ = lu / lr; break;
        case CameraKind::Omnimax:
        case CameraKind::Fisheye: aspect_ = lr / lu; break;
        case CameraKind::BlenderPanorama: break;  // a frame of unit vectors
        default:
            aspect_ = lu > 0 ? lr / lu : 1;
            unit = false;
            break;
    }
    length_right_ = lr;
    length_up_ = lu;
    forward_ = cross(camera.up, camera.right);
    if (dot(forward_, camera.direction) < 0) forward_ = -forward_;  // either handedness
    forward_ = length_squared(forward_) > 0 ? normalize(forward_) : normalize(camera.direction);
    clips_ = camera.clip_start > 0 || std::isfinite(camera.clip_end);
    if (unit) {
        camera_.right = normalize(camera_.right);
        camera_.up = normalize(camera_.up);
        camera_.direction = normalize(camera_.direction);
    }
}

void Camera::screen(double x, double y, double* sx, double* sy) const {
    // POV-Ray moves to the pixel centre with x += 0.5, y -= 0.5 and then maps
    // x0 = x / width - 0.5, y0 = ((height - 1) - y) / height - 0.5 (tracepixel.cpp).
    *sx = (x + 0.5) / width_ - 0.5;
    *sy = ((height_ - 1) - (y - 0.5)) / height_ - 0.5;
}

namespace {

// Polar angle of (x, y) as POV-Ray's fisheye/omnimax compute it (asin based).
double polar_angle(double x, double y, double rad) {
    if (rad == 0.0) return 0.0;
    return x < 0.0 ? kPi - std::asin(y / rad) : std::asin(y / rad);
}

// Rotation of v about the unit axis by `angle` radians (right-handed, as
// Compute_Axis_Rotation_Transform followed by MTransPoint).
Vec3 rotate_about(const Vec3& v, const Vec3& axis, double angle) {
    Vec3 a = normalize(axis);
    double c = std::cos(angle), s = std::sin(angle);
    return v * c + cross(a, v) * s + a * (dot(a, v) * (1 - c));
}

}  // namespace

std::optional<Ray> Camera::generate(double x, double y, int ray_number) const {
    if (camera_.kind == CameraKind::Mesh) {
        if (!mesh_) return std::nullopt;
        std::optional<Ray> ray = mesh_->generate(x, y, ray_number, width_, height_);
        // POV-Ray's mesh camera leaves (x0, y0) at 0 for a camera `normal`.
        if (ray && camera_.normal.kind != scene::PatternKind::Plain) perturb(Vec3(0, 0, 0), &*ray);
        return ray;
    }
    return generate(x, y);
}

std::optional<Ray> Camera::generate(double x, double y) const {
    if (camera_.kind == CameraKind::Mesh) return generate(x, y, 0);
    std::optional<Ray> ray = pinhole(x, y);
    if (ray && clips_) clip(ray->dir, &*ray);
    return ray;
}

void Camera::clip(const Vec3& pinhole, Ray* ray) const {
    // Perspective: the distances are along the view axis, so a ray off-centre starts and
    // stops further out by 1 / cos of its angle to the axis (that of the pinhole ray, with a
    // lens too). Orthographic: every ray starts on the plane clip_start ahead. Panoramas:
    // along the ray itself.
    const scene::Camera& c = camera_;
    const double length = c.clip_end - c.clip_start;  // inf without a clip end
    if (c.kind == CameraKind::Perspective) {
        const double z = dot(normalize(pinhole), forward_);
        if (!(z > 0)) return;
        ray->origin = ray->origin + ray->dir * (c.clip_start / z);
        ray->tmax = length / z;
    } else if (c.kind == CameraKind::Orthographic) {
        ray->origin = ray->origin + forward_ * c.clip_start;
        ray->tmax = length;
    } else {
        ray->origin = ray->origin + ray->dir * c.clip_start;
        ray->tmax = length;
    }
}

std::optional<Ray> Camera::pinhole(double x, double y) const {
    double sx, sy;
    screen(x, y, &sx, &sy);
    const scene::Camera& c = camera_;
    Ray ray;
    ray.origin = c.location;
    const double deg = kPi / 180.0;
    // (x0, y0) as POV-Ray's projection leaves them: the point where a camera `normal` is
    // evaluated (CreateCameraRay).
    double x0n = sx, y0n = sy;
    switch (c.kind) {
        case CameraKind::Perspective:
            ray.dir = c.direction + c.right * sx + c.up * sy;
            break;
        case CameraKind::Orthographic:
            ray.origin = c.location + c.right * sx + c.up * sy;
            ray.dir = c.direction;
            break;
        case CameraKind::Fisheye: {
            double x0 = 2 * sx * length_right_, y0 = 2 * sy * length_up_;
            double rad = std::sqrt(x0 * x0 + y0 * y0);
            if (rad > 1.0) return std::nullopt;  // outside the image circle: no ray
            double phi = polar_angle(x0, y0, rad);
            double theta = rad * c.angle * kPi / 360.0;
            x0n = phi;
            y0n = theta;
            ray.dir = c.right * (std::cos(phi) * std::sin(theta)) +
                      c.up * (std::sin(phi) * std::sin(theta)) + c.direction * std::cos(theta);
            break;
        }
        case CameraKind::Omnimax: {
            double x0 = 2 * sx, y0 = 2 * sy;
            if (aspect_ > 1.0) {
                if (aspect_ > 1.283458) {
                    x0 *= aspect_ / 1.283458;
                    y0 = (y0 - 1.0) / 1.283458 + 1.0;
                } else {
                    y0 = (y0 - 1.0) / aspect_ + 1.0;
                }
            } else {
                y0 /= aspect_;
            }
            double rad = std::sqrt(x0 * x0 + y0 * y0);
            if (rad > 1.0) return std::nullopt;
            double phi = polar_angle(x0, y0, rad);
            double theta = 1.411269 * rad - 0.09439 * rad * rad * rad +
                           0.25674 * rad * rad * rad * rad * rad;
            x0n = phi;
            y0n = theta;
            double cx = std::cos(phi), sxp = std::sin(phi);
            double cy = std::cos(theta), sy2 = std::sin(theta);
            // Nothing below 45 degrees under the projection axis.
            if (sxp * sy2 < std::tan(135.0 * deg) * cy) return std::nullopt;
            ray.dir = c.right * (cx * sy2) + c.up * (sxp * sy2) + c.direction * cy;
            break;
        }
        case CameraKind::Panoramic: {
            double x0 = (1.0 - (sx + 0.5)) * kPi;
            double y0 = 0.5 * kPi * (2 * sy);
            double ty;
            if (std::fabs(0.5 * kPi - std::fabs(y0)) < kPovEpsilon)
                ty = y0 > 0 ? 1e10 : -1e10;  // BOUND_HUGE
            else
                ty = std::tan(y0);
            x0n = x0;
            y0n = y0;
            ray.dir = c.right * std::cos(x0) + c.up * ty + c.direction * std::sin(x0);
            break;
        }
        case CameraKind::UltraWideAngle: {
            double x0 = sx * c.angle * deg, y0 = sy * c.angle * aspect_ * deg;
            x0n = x0;
            y0n = y0;
            ray.dir = c.right * std::sin(x0) + c.up * std::sin(y0) +
                      c.direction * (std::cos(x0) * std::cos(y0));
            break;
        }
        case CameraKind::Cylinder1: {
            double x0 = sx * c.angle * deg, y0 = sy * aspect_;
            x0n = x0;
            y0n = y0;
            ray.dir = c.right * std::sin(x0) + c.up * y0 + c.direction * std::cos(x0);
            break;
        }
        case CameraKind::Cylinder2: {
            double y0 = sy * c.angle * deg, x0 = sx * aspect_;
            x0n = x0;
            y0n = y0;
            ray.dir = c.right * x0 + c.up * std::sin(y0) + c.direction * std::cos(y0);
            break;
        }
        case CameraKind::Cylinder3: {
            double x0 = sx * c.angle * deg, y0 = sy * aspect_;
            x0n = x0;
            y0n = y0;
            ray.dir = c.right * std::sin(x0) + c.direction * std::cos(x0);
            ray.origin = c.location + c.up * y0;
            break;
        }
        case CameraKind::Cylinder4: {
            double y0 = sy * c.angle * deg, x0 = sx * aspect_;
            x0n = x0;
            y0n = y0;
            ray.dir = c.up * std::sin(y0) + c.direction * std::cos(y0);
            ray.origin = c.location + c.right * x0;
            break;
        }
        case CameraKind::Spherical: {
            double y0 = sy * c.v_angle * deg, x0 = sx * c.h_angle * deg;
            x0n = x0;
            y0n = y0;
            // Latitude about `right`, then longitude about `up`.
            Vec3 v = rotate_about(c.direction, c.right, -y0);
            ray.dir = rotate_about(v, c.up, x0);
            break;
        }
        case CameraKind::Mesh:
            return std::nullopt;  // generate() asks the mesh camera
        case CameraKind::BlenderPanorama: {
            // Cycles' raster-to-camera for panoramas is the whole image onto [0, 1]^2 from
            // the lower left corner, which is (sx, sy) + 0.5.
            const Vec3 d = panorama_direction(c.panorama, sx + 0.5, sy + 0.5);
            if (!(length_squared(d) > 0)) return std::nullopt;
            ray.dir = panorama_to_world(c.panorama.type, d, c.direction, c.right, c.up);
            break;
        }
    }
    if (!(length_squared(ray.dir) > 0) || !std::isfinite(length_squared(ray.dir)))
        return std::nullopt;
    ray.dir = normalize(ray.dir);
    if (c.normal.kind != scene::PatternKind::Plain) perturb(Vec3(x0n, y0n, 0), &ray);
    return ray;
}

void Camera::perturb(const Vec3& at, Ray* ray) const {
    // The unit direction is bent like a surface normal by the pattern evaluated at `at`
    // (POV-Ray's Perturb_Normal on the ray direction).
    PatternPoint point;
    point.p = at;
    ray->dir = normalize(perturb_normal(camera_.normal, point, ray->dir, normal_ctx_,
                                             normal_ctx_.textures));
}

namespace {

// Shirley and Chiu's concentric map of the unit square onto the unit disc (Cycles'
// concentric_sample_disk).
void concentric_disc(double u, double v, double* x, double* y) {
    const double a = 2 * u - 1, b = 2 * v - 1;
    if (a == 0 && b == 0) {
        *x = *y = 0;
        return;
    }
    double r, phi;
    if (a * a > b * b) {
        r = a;
        phi = (kPi / 4) * (b / a);
    } else {
        r = b;
        phi = kPi / 2 - (kPi / 4) * (a / b);
    }
    *x = r * std::cos(phi);
    *y = r * std::sin(phi);
}

// A uniform point in a regular polygon with `corners` corners on the unit circle, the first
// at `rotation` (Cycles' regular_polygon_sample): a corner's triangle, then a point in it.
void polygon_sample(int corners, double rotation, double u, double v, double* x, double* y) {
    const double corner = std::floor(u * corners);
    u = u * corners - corner;
    u = std::sqrt(u);
    v = v * u;
    u = 1 - u;
    const double angle = kPi / corners;
    const double px = (u + v) * std::cos(angle), py = (u - v) * std::sin(angle);
    rotation += corner * 2 * angle;
    const double cr = std::cos(rotation), sr = std::sin(rotation);
    *x = cr * px - sr * py;
    *y = sr * px + cr * py;
}

}  // namespace

std::optional<Ray> Camera::generate(double x, double y, double lens_u, double lens_v) const {
    const scene::Camera& c = camera_;
    std::optional<Ray> ray;
    if (c.kind == CameraKind::Mesh) return generate(x, y, 0);
    if (c.kind == CameraKind::BlenderPanorama) {
        ray = generate_panorama(x, y, lens_u, lens_v);
        if (ray && clips_) clip(ray->dir, &*ray);
        return ray;
    }
    ray = pinhole(x, y);
    if (!ray) return ray;
    const Vec3 pinhole_dir = ray->dir;
    with_lens(lens_u, lens_v, &*ray);
    if (clips_) clip(pinhole_dir, &*ray);
    return ray;
}

void Camera::with_lens(double lens_u, double lens_v, Ray* ray) const {
    const scene::Camera& c = camera_;
    const bool linear = c.kind == CameraKind::Perspective || c.kind == CameraKind::Orthographic;
    if (!linear || !(c.lens.radius > 0)) return;
    const Vec3 r = normalize(c.right), u = normalize(c.up);
    const Vec3 fwd = forward_;
    double lx, ly;
    if (c.lens.blades >= 3)
        polygon_sample(c.lens.blades, c.lens.rotation, lens_u, lens_v, &lx, &ly);
    else
        concentric_disc(lens_u, lens_v, &lx, &ly);
    lx *= c.lens.radius / c.lens.ratio;
    ly *= c.lens.radius;
    const double along = dot(ray->dir, fwd);
    if (!(along > 0)) return;
    const Vec3 focus = ray->origin + ray->dir * (c.lens.focal_distance / along);
    ray->origin = ray->origin + r * lx + u * ly;
    const Vec3 d = focus - ray->origin;
    if (!(length_squared(d) > 0)) return;
    ray->dir = normalize(d);
}

// Cycles samples the aperture as for the other cameras and moves the ray in the panorama's
// own frame (panorama_lens); the direction without the lens is generate()'s.
std::optional<Ray> Camera::generate_panorama(double x, double y, double lens_u,
                                             double lens_v) const {
    const scene::Camera& c = camera_;
    double sx, sy;
    screen(x, y, &sx, &sy);
    const Vec3 d = panorama_direction(c.panorama, sx + 0.5, sy + 0.5);
    if (!(length_squared(d) > 0) || !std::isfinite(length_squared(d))) return std::nullopt;
    Vec3 o(0, 0, 0), dir = d;
    if (c.lens.radius > 0) {
        double lx, ly;
        if (c.lens.blades >= 3)
            polygon_sample(c.lens.blades, c.lens.rotation, lens_u, lens_v, &lx, &ly);
        else
            concentric_disc(lens_u, lens_v, &lx, &ly);
        panorama_lens(d, c.lens.focal_distance, lx * c.lens.radius / c.lens.ratio,
                      ly * c.lens.radius, &o, &dir);
    }
    const scene::PanoramaType t = c.panorama.type;
    Ray ray;
    ray.origin = c.location + panorama_to_world(t, o, c.direction, c.right, c.up);
    ray.dir = normalize(panorama_to_world(t, dir, c.direction, c.right, c.up));
    return ray;
}

bool Camera::rays_start_at_location() const {
    return camera_.kind != CameraKind::Orthographic && camera_.kind != CameraKind::Cylinder3 &&
           camera_.kind != CameraKind::Cylinder4;
}

}  // namespace glint::render
