// POV-Ray focal blur: the camera keywords to IR (formats/pov/camera.cpp) and the classic
// renderer's aperture sampling (render/focal_blur.h) through the tile driver.
#include "render/focal_blur.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "render/film/driver.h"
#include "tests/unit/pov_test_util.h"

namespace glint {
namespace {

using pov::testing::error_of;
using pov::testing::parse;
using render::Ray;

TEST(FocalBlurParse, KeywordsToIr) {
    auto s = parse(
        "camera { location <0, 0, -10> look_at 0 aperture 0.5 focal_point <0, 3, -6>\n"
        "  blur_samples 7, 37 confidence 0.95 variance 1/255 translate x }\n");
    const scene::FocalBlur& f = s.camera.focal_blur;
    EXPECT_TRUE(f.active());
    EXPECT_EQ(f.aperture, 0.5);
    EXPECT_EQ(f.focal_distance, 5.0);  // |focal_point - location|, before the translate
    EXPECT_EQ(f.samples_min, 7);
    EXPECT_EQ(f.samples, 37);
    EXPECT_EQ(f.confidence, 0.95);
    EXPECT_EQ(f.variance, 1.0 / 255);
}

TEST(FocalBlurParse, DefaultsFollowParseCamera) {
    // One blur_samples value is the maximum; the focal distance is the direction's length
    // as look_at found it; out-of-range confidence and variance keep the defaults.
    auto s = parse(
        "camera { location <0, 0, -10> direction 2*z look_at 0 aperture 1 blur_samples 19\n"
        "  confidence 1.5 variance -1 }\n");
    const scene::FocalBlur& f = s.camera.focal_blur;
    EXPECT_EQ(f.samples, 19);
    EXPECT_EQ(f.samples_min, 0);
    EXPECT_EQ(f.focal_distance, 2.0);
    EXPECT_EQ(f.confidence, 0.9);
    EXPECT_EQ(f.variance, 1.0 / 10000);
    auto plain = parse("camera { location -5*z aperture 1 }\n");
    EXPECT_FALSE(plain.camera.focal_blur.active());  // no blur_samples: in focus
    EXPECT_EQ(error_of("camera { blur_samples 0 }"), "1:10: illegal number of focal blur samples");
    EXPECT_EQ(error_of("camera { blur_samples 9, 4 }"),
              "1:10: focal blur samples minimum must not be larger than maximum");
}

scene::Camera blur_camera(int samples) {
    scene::Camera c;
    c.location = Vec3(0, 0, -10);
    c.direction = Vec3(0, 0, 2);
    c.right = Vec3(4.0 / 3.0, 0, 0);
    c.focal_blur.aperture = 1.5;
    c.focal_blur.focal_distance = 10;
    c.focal_blur.samples = samples;
    return c;
}

TEST(FocalBlur, ApertureGridIsPovRaysHexGridThenFreeCellsOfTheDisc) {
    render::Camera cam(blur_camera(120), 40, 30);
    render::FocalBlur blur(cam);
    const auto& g = blur.grid();
    ASSERT_EQ(g.size(), 120u);
    EXPECT_EQ(g[0], Vec2(0, 0));         // HexGrid4's centre first
    EXPECT_EQ(g[36], Vec2(0.0, -0.25));  // and its last point
    std::set<std::pair<int, int>> cells;
    for (size_t i = 37; i < g.size(); ++i) {
        EXPECT_LE(g[i].x * g[i].x + g[i].y * g[i].y, 0.25 + 1e-12);
        cells.insert({std::min(static_cast<int>((g[i].x + 0.5) * 15), 14),
                      std::min(static_cast<int>((g[i].y + 0.5) * 15), 14)});
    }
    EXPECT_EQ(cells.size(), 83u);  // each added point in a cell of its own (15 x 15 grid)
    // Thresholds grow with the ray count; the one for all but the last ray is the variance.
    EXPECT_NEAR(blur.thresholds()[118], 1e-4, 1e-12);
    EXPECT_LT(blur.thresholds()[5], blur.thresholds()[50]);
}

TEST(FocalBlur, RaysOfAPositionMeetOnTheFocalPlane) {
    render::Camera cam(blur_camera(37), 40, 30);
    render::FocalBlur blur(cam);
    // The pinhole ray's point at the focal distance: location + D * 10 / |direction|.
    double sx, sy;
    cam.screen(12.3, 7.6, &sx, &sy);
    const Vec3 d = Vec3(0, 0, 2) + Vec3(4.0 / 3.0, 0, 0) * sx + Vec3(0, 1, 0) * sy;
    const Vec3 focus = Vec3(0, 0, -10) + d * 5.0;
    std::set<std::pair<double, double>> origins;
    for (int n = 0; n < 37; ++n) {
        const Ray r = *blur.ray(12.3, 7.6, n);
        EXPECT_NEAR(r.origin.z, -10, 1e-12);
        origins.insert({r.origin.x, r.origin.y});
        const double t = (focus.z - r.origin.z) / r.dir.z;
        const Vec3 p = r.origin + r.dir * t;
        EXPECT_NEAR(p.x, focus.x, 1e-9);
        EXPECT_NEAR(p.y, focus.y, 1e-9);
    }
    EXPECT_EQ(origins.size(), 37u);  // the eye moves to every grid point
}

TEST(FocalBlur, UniformRadianceStopsAfterTheFirstBatch) {
    render::Camera cam(blur_camera(37), 40, 30);
    render::FocalBlur blur(cam);
    int rays = 0;
    const Color c = blur.pixel(
        5, 5, [](const Ray&) { return Color(0.25, 0.5, 1); }, &rays);
    EXPECT_EQ(rays, 7);  // HexGrid4's first batch; zero variance passes the test
    EXPECT_NEAR(c.g, 0.5, 1e-15);
    // A noisy scene takes every ray.
    blur.pixel(
        5, 5, [](const Ray& r) { return Color(r.origin.x > 0 ? 1 : 0, 0, 0); }, &rays);
    EXPECT_EQ(rays, 37);
}

TEST(FocalBlur, ImageIsIdenticalWhateverTheThreadCount) {
    render::Camera cam(blur_camera(40), 37, 29);
    auto radiance = [](const Ray& r, const render::SampleId&) {
        const double v = std::sin(r.origin.x * 40.0 + r.dir.x * 91.7) * std::cos(r.dir.y * 57.3);
        return Color(0.5 + 0.5 * v, v > 0.2 ? 1.0 : 0.0, r.origin.y * r.origin.y);
    };
    render::RenderOptions o;
    o.width = 37;
    o.height = 29;
    o.threads = 1;
    const Image a = render::run_tiles(cam, o, {}, radiance);
    o.threads = 3;
    const Image b = render::run_tiles(cam, o, {}, radiance);
    EXPECT_EQ(a.rgba, b.rgba);
    // And it is blurred: not what the pinhole camera sees.
    o.threads = 1;
    scene::Camera sharp = blur_camera(40);
    sharp.focal_blur.aperture = 0;
    const Image c = render::run_tiles(render::Camera(sharp, 37, 29), o, {}, radiance);
    EXPECT_NE(a.rgba, c.rgba);
}

}  // namespace
}  // namespace glint
