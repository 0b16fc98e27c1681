// Camera rays: POV-Ray's pixel-centre mapping (tracepixel.cpp CreateCameraRay) for perspective
// and orthographic cameras, and its non-linear projections.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "render/camera.h"

namespace glint::render {
namespace {

scene::Camera basic_camera() {
    scene::Camera c;
    c.location = Vec3(0, 0, -5);
    c.direction = Vec3(0, 0, 1);
    c.right = Vec3(4.0 / 3.0, 0, 0);
    c.up = Vec3(0, 1, 0);
    return c;
}

TEST(Camera, CentrePixelOfOddImageLooksAlongDirection) {
    Camera cam(basic_camera(), 5, 3);
    Ray r = *cam.generate(2, 1);
    EXPECT_NEAR(r.dir.x, 0.0, 1e-15);
    EXPECT_NEAR(r.dir.y, 0.0, 1e-15);
    EXPECT_NEAR(r.dir.z, 1.0, 1e-15);
    EXPECT_EQ(r.origin, Vec3(0, 0, -5));
}

TEST(Camera, TopLeftPixelCentre) {
    const int w = 320, h = 240;
    Camera cam(basic_camera(), w, h);
    double sx, sy;
    cam.screen(0, 0, &sx, &sy);
    EXPECT_DOUBLE_EQ(sx, -0.5 + 0.5 / w);
    EXPECT_DOUBLE_EQ(sy, 0.5 - 0.5 / h);
    Ray r = *cam.generate(0, 0);
    Vec3 expected = normalize(Vec3((4.0 / 3.0) * sx, sy, 1.0));
    EXPECT_NEAR(r.dir.x, expected.x, 1e-14);
    EXPECT_NEAR(r.dir.y, expected.y, 1e-14);
    EXPECT_NEAR(r.dir.z, expected.z, 1e-14);
    EXPECT_LT(r.dir.x, 0);  // left
    EXPECT_GT(r.dir.y, 0);  // top
}

TEST(Camera, BottomRightPixelCentre) {
    const int w = 320, h = 240;
    Camera cam(basic_camera(), w, h);
    double sx, sy;
    cam.screen(w - 1, h - 1, &sx, &sy);
    EXPECT_DOUBLE_EQ(sx, 0.5 - 0.5 / w);
    EXPECT_DOUBLE_EQ(sy, -0.5 + 0.5 / h);
}

TEST(Camera, DirectionsAreUnitLength) {
    Camera cam(basic_camera(), 64, 48);
    for (int y = 0; y < 48; y += 7)
        for (int x = 0; x < 64; x += 9) EXPECT_NEAR(length(cam.generate(x, y)->dir), 1.0, 1e-14);
}

TEST(Camera, OrthographicMovesOriginNotDirection) {
    scene::Camera c = basic_camera();
    c.kind = scene::CameraKind::Orthographic;
    c.right = Vec3(8, 0, 0);
    c.up = Vec3(0, 6, 0);
    Camera cam(c, 4, 4);
    Ray r = *cam.generate(0, 3);
    // sx = 0.5/4 - 0.5 = -0.375, sy = (3 - 2.5)/4 - 0.5 = -0.375
    EXPECT_NEAR(r.origin.x, -3.0, 1e-14);
    EXPECT_NEAR(r.origin.y, -2.25, 1e-14);
    EXPECT_NEAR(r.origin.z, -5.0, 1e-14);
    EXPECT_EQ(r.dir, Vec3(0, 0, 1));
}

// Blender's Clip Start / End, as Cycles' camera_sample_perspective clips: distances along the
// view axis, so a ray at angle a to it starts at clip_start / cos a and reaches
// (clip_end - clip_start) / cos a further.
TEST(Camera, PerspectiveClipIsMeasuredAlongTheViewAxis) {
    scene::Camera c = basic_camera();
    c.clip_start = 0.5;
    c.clip_end = 10;
    Camera cam(c, 64, 48);
    for (const auto& [x, y] : {std::pair{31.5, 23.5}, std::pair{0.0, 0.0}, std::pair{63.0, 10.0}}) {
        const Ray r = *cam.generate(x, y);
        const double cos_a = r.dir.z;  // the view axis is +z
        EXPECT_NEAR(r.origin.z - (-5), 0.5, 1e-12) << x << "," << y;
        EXPECT_NEAR(length(r.origin - c.location), 0.5 / cos_a, 1e-12);
        EXPECT_NEAR(r.tmax, 9.5 / cos_a, 1e-12);
        // The far end lies on the plane clip_end ahead.
        EXPECT_NEAR((r.origin + r.dir * r.tmax).z - (-5), 10, 1e-12);
    }
}

TEST(Camera, ClipWithALensKeepsThePinholeRaysDistances) {
    // Through a thin lens the ray leaves from the aperture, but Cycles moves it by the pinhole
    // ray's 1 / cos a (not its own).
    scene::Camera c = basic_camera();
    c.clip_start = 0.25;
    c.clip_end = 4;
    c.lens.radius = 0.2;
    c.lens.focal_distance = 3;
    Camera cam(c, 64, 48);
    const Ray pin = *cam.generate(5, 7);
    const Ray r = *cam.generate(5, 7, 0.9, 0.2);
    const double k = 1 / pin.dir.z;
    EXPECT_NEAR(r.tmax, 3.75 * k, 1e-12);
    EXPECT_GT(length(r.dir - pin.dir), 1e-3);  // the lens turned it
    // Its start: on the aperture, then 0.25 k along its own direction.
    const Ray lens_only = [&] {
        scene::Camera u = c;
        u.clip_start = 0;
        u.clip_end = kInfinity;
        return *Camera(u, 64, 48).generate(5, 7, 0.9, 0.2);
    }();
    EXPECT_TRUE(std::isinf(lens_only.tmax));
    const Vec3 expected = lens_only.origin + lens_only.dir * (0.25 * k);
    EXPECT_NEAR(length(r.origin - expected), 0, 1e-12);
}

TEST(Camera, OrthographicClipStartsEveryRayOnOnePlane) {
    scene::Camera c = basic_camera();
    c.kind = scene::CameraKind::Orthographic;
    c.right = Vec3(8, 0, 0);
    c.up = Vec3(0, 6, 0);
    c.clip_start = 1;
    c.clip_end = 3;
    Camera cam(c, 4, 4);
    for (int x = 0; x < 4; ++x) {
        const Ray r = *cam.generate(x, 3);
        EXPECT_NEAR(r.origin.z, -4, 1e-14);
        EXPECT_NEAR(r.tmax, 2, 1e-14);
    }
}

TEST(Camera, PovRayCamerasDoNotClip) {
    Camera cam(basic_camera(), 64, 48);
    const Ray r = *cam.generate(3, 40);
    EXPECT_EQ(r.origin, Vec3(0, 0, -5));
    EXPECT_TRUE(std::isinf(r.tmax));
}

TEST(Camera, FisheyeTracesNoRayOutsideItsCircle) {
    scene::Camera c = basic_camera();
    c.kind = scene::CameraKind::Fisheye;
    c.angle = 180;
    c.right = Vec3(1, 0, 0);  // square view: the circle touches the image edges
    Camera cam(c, 101, 101);
    EXPECT_FALSE(cam.generate(0, 0).has_value());  // corner
    std::optional<Ray> centre = cam.generate(50, 50);
    ASSERT_TRUE(centre.has_value());
    EXPECT_NEAR(centre->dir.z, 1.0, 1e-12);
    // The angle off axis grows linearly with the distance from the centre: angle/2 at the
    // circle's edge. Pixel 75's centre lies at radius 2 * (75.5 / 101 - 0.5).
    std::optional<Ray> mid = cam.generate(75, 50);
    ASSERT_TRUE(mid.has_value());
    EXPECT_NEAR(std::acos(mid->dir.z) * 180 / kPi, 2 * (75.5 / 101 - 0.5) * 90, 1e-9);
    EXPECT_GT(mid->dir.x, 0);
}

TEST(Camera, SphericalCoversTheFullSphereHorizontally) {
    scene::Camera c = basic_camera();
    c.kind = scene::CameraKind::Spherical;
    c.h_angle = 360;
    c.v_angle = 180;
    Camera cam(c, 360, 180);
    // Right of centre turns towards +x (POV-Ray's rotation about `up`), the far left and right
    // edges look backwards.
    Ray right = *cam.generate(269.5, 89.5);
    EXPECT_NEAR(right.dir.x, 1.0, 1e-9);
    Ray back = *cam.generate(-0.5, 89.5);
    EXPECT_NEAR(back.dir.z, -1.0, 1e-9);
    Ray top = *cam.generate(179.5, -0.5);
    EXPECT_NEAR(top.dir.y, 1.0, 1e-9);
}

TEST(Camera, CylinderThreeIsOrthographicVertically) {
    scene::Camera c = basic_camera();
    c.kind = scene::CameraKind::Cylinder3;
    c.angle = 90;
    Camera cam(c, 64, 64);
    Ray a = *cam.generate(31.5, 0), b = *cam.generate(31.5, 63);
    EXPECT_NEAR(a.dir.z, b.dir.z, 1e-15);
    EXPECT_GT(a.origin.y, b.origin.y);
    EXPECT_FALSE(cam.rays_start_at_location());
}

TEST(Camera, NormalBendsRaysAlongThePatternsSlope) {
    // POV-Ray's camera `normal`: a gradient x slope adds a vector along x to each unit
    // direction, so the rays' y : z proportion stays while x changes; a normal of amount 0
    // leaves the rays as they were.
    scene::Camera c = basic_camera();
    c.normal.kind = scene::PatternKind::Gradient;
    c.normal.params.vector = Vec3(1, 0, 0);
    c.normal.amount = 0.5;
    Camera bent(c, 64, 48), plain(basic_camera(), 64, 48);
    for (const auto& [x, y] : {std::pair{3.0, 5.0}, std::pair{40.0, 30.0}}) {
        const Ray a = *bent.generate(x, y), b = *plain.generate(x, y);
        EXPECT_NEAR(length(a.dir), 1.0, 1e-14);
        EXPECT_NEAR(a.dir.y / a.dir.z, b.dir.y / b.dir.z, 1e-7);  // a numeric slope
        EXPECT_GT(std::fabs(a.dir.x - b.dir.x), 1e-3);
    }
    c.normal.amount = 0;
    Camera flat(c, 64, 48);
    const Ray a = *flat.generate(10, 10), b = *plain.generate(10, 10);
    EXPECT_NEAR(a.dir.x, b.dir.x, 1e-14);
}

}  // namespace
}  // namespace glint::render
