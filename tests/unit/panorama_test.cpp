// Blender's panoramic cameras as Cycles 3.4 projects them (render/panorama.h): known image
// points give known directions, the image circle's outside gives no ray, the raster's
// orientation, the camera frame, depth of field on a panorama, and the importer's settings.
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.h"
#include "render/panorama.h"

namespace glint::render {
namespace {

using scene::Panorama;
using scene::PanoramaType;

constexpr double kDeg = kPi / 180;

void expect_dir(const Vec3& got, const Vec3& want, const char* what) {
    const Vec3 w = normalize(want);
    const Vec3 g = length_squared(got) > 0 ? normalize(got) : got;
    EXPECT_NEAR(g.x, w.x, 1e-12) << what;
    EXPECT_NEAR(g.y, w.y, 1e-12) << what;
    EXPECT_NEAR(g.z, w.z, 1e-12) << what;
}

// The panorama frame: x forward, y left, z up. Longitude phi grows to the left, latitude up.
Vec3 spherical(double lon, double lat) {
    return Vec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
}

TEST(Panorama, EquirectangularFullSphere) {
    Panorama p;
    p.type = PanoramaType::Equirectangular;
    expect_dir(panorama_direction(p, 0.5, 0.5), Vec3(1, 0, 0), "centre: forward");
    expect_dir(panorama_direction(p, 0.75, 0.5), Vec3(0, -1, 0), "three quarters: right");
    expect_dir(panorama_direction(p, 0.25, 0.5), Vec3(0, 1, 0), "one quarter: left");
    expect_dir(panorama_direction(p, 0.0, 0.5), Vec3(-1, 0, 0), "left edge: behind");
    expect_dir(panorama_direction(p, 0.5, 1.0), Vec3(0, 0, 1), "top: up");
    expect_dir(panorama_direction(p, 0.5, 0.0), Vec3(0, 0, -1), "bottom: down");
}

TEST(Panorama, EquirectangularRange) {
    Panorama p;
    p.type = PanoramaType::Equirectangular;
    p.longitude_min = -150 * kDeg;
    p.longitude_max = 120 * kDeg;
    p.latitude_min = -50 * kDeg;
    p.latitude_max = 70 * kDeg;
    // Blender's longitude is to the right, the panorama frame's to the left.
    expect_dir(panorama_direction(p, 0, 0), spherical(150 * kDeg, -50 * kDeg), "lower left");
    expect_dir(panorama_direction(p, 1, 1), spherical(-120 * kDeg, 70 * kDeg), "upper right");
    const double u = 150.0 / 270.0, v = 50.0 / 120.0;  // longitude 0, latitude 0
    expect_dir(panorama_direction(p, u, v), Vec3(1, 0, 0), "the zero point");
}

TEST(Panorama, FisheyeEquidistantAngleGrowsWithRadius) {
    Panorama p;
    p.type = PanoramaType::FisheyeEquidistant;
    p.fov = 200 * kDeg;
    expect_dir(panorama_direction(p, 0.5, 0.5), Vec3(1, 0, 0), "centre");
    // At the circle's edge the angle from forward is fov / 2 = 100 degrees.
    expect_dir(panorama_direction(p, 1.0, 0.5), Vec3(std::cos(100 * kDeg), -std::sin(100 * kDeg), 0),
               "right edge");
    expect_dir(panorama_direction(p, 0.5, 1.0), Vec3(std::cos(100 * kDeg), 0, std::sin(100 * kDeg)),
               "top edge");
    // Half way to the left edge: 50 degrees.
    expect_dir(panorama_direction(p, 0.25, 0.5), Vec3(std::cos(50 * kDeg), std::sin(50 * kDeg), 0),
               "half way left");
    EXPECT_EQ(panorama_direction(p, 0.9, 0.9), Vec3(0, 0, 0)) << "outside the circle";
    EXPECT_EQ(panorama_direction(p, 0.0, 0.0), Vec3(0, 0, 0)) << "corner";
}

TEST(Panorama, FisheyeEquisolidFollowsTheLensFormula) {
    Panorama p;
    p.type = PanoramaType::FisheyeEquisolid;
    p.lens = 10.5;
    p.fov = kPi;
    p.sensor_width = 36;
    p.sensor_height = 27;
    // r = 2 f sin(theta / 2) on the sensor: 60 degrees lies 10.5 mm right of the centre.
    const double u = 0.5 + 2 * 10.5 * std::sin(30 * kDeg) / 36;
    expect_dir(panorama_direction(p, u, 0.5), Vec3(std::cos(60 * kDeg), -std::sin(60 * kDeg), 0),
               "60 degrees right");
    const double v = 0.5 - 2 * 10.5 * std::sin(20 * kDeg) / 27;
    expect_dir(panorama_direction(p, 0.5, v), Vec3(std::cos(40 * kDeg), 0, -std::sin(40 * kDeg)),
               "40 degrees down");
    // The circle's radius is 2 f sin(fov / 4) = 14.85 mm: the sensor's edge (18 mm) is outside.
    EXPECT_EQ(panorama_direction(p, 1.0, 0.5), Vec3(0, 0, 0));
    EXPECT_NE(panorama_direction(p, 0.5 + 14.8 / 36, 0.5), Vec3(0, 0, 0));
}

TEST(Panorama, FisheyeLensPolynomial) {
    Panorama p;
    p.type = PanoramaType::FisheyeLensPolynomial;
    p.fov = kPi;
    p.sensor_width = 36;
    p.sensor_height = 24;
    p.k[1] = -0.05;  // theta = 0.05 r (radians per mm)
    const double r = 9;  // 0.45 rad
    expect_dir(panorama_direction(p, 0.5 + r / 36, 0.5), Vec3(std::cos(0.45), -std::sin(0.45), 0),
               "right");
    p.fov = 0.8;  // half of it, 0.4 rad, is less than 0.45: no ray
    EXPECT_EQ(panorama_direction(p, 0.5 + r / 36, 0.5), Vec3(0, 0, 0));
}

TEST(Panorama, MirrorBallReflectsTheViewRay) {
    Panorama p;
    p.type = PanoramaType::MirrorBall;
    // The ball's frame: x right, y backward (the view ray runs along -y), z up.
    expect_dir(panorama_direction(p, 0.5, 0.5), Vec3(0, -1, 0), "centre: straight back along the view");
    // At 45 degrees on the ball the view ray turns by 90 degrees.
    const double s = std::sin(45 * kDeg);
    expect_dir(panorama_direction(p, 0.5 + s / 2, 0.5), Vec3(1, 0, 0), "45 degrees: right");
    expect_dir(panorama_direction(p, 0.5, 0.5 + s / 2), Vec3(0, 0, 1), "45 degrees: up");
    EXPECT_EQ(panorama_direction(p, 0.0, 0.0), Vec3(0, 0, 0));
    // In the world: the centre looks where the camera looks.
    const Vec3 fwd(0, 1, 0), right(1, 0, 0), up(0, 0, 1);
    expect_dir(panorama_to_world(p.type, panorama_direction(p, 0.5, 0.5), fwd, right, up), fwd,
               "world centre");
}

TEST(Panorama, EquiangularCubemapFace) {
    Panorama p;
    p.type = PanoramaType::EquiangularCubemapFace;
    expect_dir(panorama_direction(p, 0.5, 0.5), Vec3(1, 0, 0), "centre");
    expect_dir(panorama_direction(p, 1.0, 0.5), Vec3(1, -1, 0), "right edge: 45 degrees");
    expect_dir(panorama_direction(p, 0.5, 0.0), Vec3(1, 0, -1), "bottom edge: 45 degrees");
}

// A camera at (1, 2, 3) looking along +Y with +Z up (Blender's camera rotated 90 degrees
// about X), as the importer makes it.
scene::Camera pano_camera(PanoramaType type) {
    scene::Camera c;
    c.kind = scene::CameraKind::BlenderPanorama;
    c.location = Vec3(1, 2, 3);
    c.direction = Vec3(0, 1, 0);
    c.right = Vec3(1, 0, 0);
    c.up = Vec3(0, 0, 1);
    c.panorama.type = type;
    c.panorama.fov = kPi;
    return c;
}

TEST(Panorama, CameraRasterAndFrame) {
    const int w = 65, h = 33;  // odd: a pixel centre on the image's centre
    Camera cam(pano_camera(PanoramaType::Equirectangular), w, h);
    const Ray centre = *cam.generate(32, 16);
    EXPECT_EQ(centre.origin, Vec3(1, 2, 3));
    expect_dir(centre.dir, Vec3(0, 1, 0), "centre pixel: forward");
    // Raster x grows to the right, raster y downwards.
    EXPECT_GT(cam.generate(40, 16)->dir.x, 0.1);
    EXPECT_LT(cam.generate(24, 16)->dir.x, -0.1);
    EXPECT_GT(cam.generate(32, 8)->dir.z, 0.1);
    EXPECT_LT(cam.generate(32, 24)->dir.z, -0.1);
    // The left edge of the image (raster x -0.5) looks straight back.
    expect_dir(cam.generate(-0.5, 16)->dir, Vec3(0, -1, 0), "left edge: behind");
    for (int y = 0; y < h; y += 5)
        for (int x = 0; x < w; x += 7) EXPECT_NEAR(length(cam.generate(x, y)->dir), 1, 1e-12);
}

TEST(Panorama, FisheyeCameraHasNoRayOutsideItsCircle) {
    Camera cam(pano_camera(PanoramaType::FisheyeEquidistant), 64, 48);
    EXPECT_FALSE(cam.generate(0, 0).has_value());
    EXPECT_FALSE(cam.generate(63, 47).has_value());
    EXPECT_FALSE(cam.generate(0, 0, 0.3, 0.7).has_value());
    EXPECT_TRUE(cam.generate(32, 24).has_value());
    // The circle fills the height: the middle of the top row is inside, at nearly 90 degrees.
    const Ray top = *cam.generate(31.5, 0);
    EXPECT_GT(top.dir.z, 0.99);
}

TEST(Panorama, DepthOfFieldFocusesOnTheFocalDistance) {
    scene::Camera c = pano_camera(PanoramaType::Equirectangular);
    c.lens.radius = 0.05;
    c.lens.focal_distance = 4;
    Camera with_lens(c, 64, 32);
    Camera pinhole(pano_camera(PanoramaType::Equirectangular), 64, 32);
    for (double x : {3.0, 20.0, 40.0}) {
        const Ray p = *pinhole.generate(x, 10);
        const Vec3 focus = p.origin + p.dir * 4.0;
        double spread = 0;
        for (double lu : {0.1, 0.5, 0.9})
            for (double lv : {0.2, 0.7}) {
                const Ray r = *with_lens.generate(x, 10, lu, lv);
                // The ray starts on the aperture and passes the pinhole ray's focal point.
                const Vec3 to = focus - r.origin;
                EXPECT_NEAR(length(cross(to, r.dir)), 0, 1e-9);
                EXPECT_GT(dot(to, r.dir), 0);
                EXPECT_LE(length(r.origin - c.location), 0.05 + 1e-12);
                spread = std::max(spread, length(r.origin - c.location));
            }
        EXPECT_GT(spread, 0.01) << "the lens moves the origin";
    }
}

}  // namespace
}  // namespace glint::render
