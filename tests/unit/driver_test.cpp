// The tile driver: thread-count independence, progress, cancellation, anti-aliasing modes.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <mutex>

#include "core/error.h"
#include "render/integrators/driver.h"

namespace glint::render {
namespace {

scene::Camera test_camera() {
    scene::Camera c;
    c.location = Vec3(0, 0, -5);
    return c;
}

// A radiance function with structure at every scale: bits would differ if sampling changed.
Color busy(const Ray& r, const SampleId& = {}) {
    double v = std::sin(r.dir.x * 91.7) * std::cos(r.dir.y * 57.3);
    return Color(0.5 + 0.5 * v, r.dir.x * r.dir.x * 7.0, v > 0.3 ? 1.0 : 0.0);
}

TEST(Driver, OneAndTwoThreadsGiveIdenticalBits) {
    Camera cam(test_camera(), 97, 61);
    for (AaMode aa : {AaMode::None, AaMode::Adaptive, AaMode::Grid}) {
        RenderOptions o;
        o.width = 97;
        o.height = 61;
        o.aa = aa;
        o.threads = 1;
        Image a = run_tiles(cam, o, {}, busy);
        o.threads = 2;
        Image b = run_tiles(cam, o, {}, busy);
        ASSERT_EQ(a.rgba.size(), b.rgba.size());
        EXPECT_EQ(a.rgba, b.rgba) << "aa mode " << static_cast<int>(aa);
    }
}

TEST(Driver, NoAaTracesPixelCentres) {
    Camera cam(test_camera(), 40, 30);
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    Image img = run_tiles(cam, o, {}, busy);
    Color expect = busy(*cam.generate(17, 11));
    EXPECT_EQ(img.pixel(17, 11)[0], static_cast<float>(expect.r));
    EXPECT_EQ(img.pixel(17, 11)[1], static_cast<float>(expect.g));
    EXPECT_EQ(img.pixel(17, 11)[3], 1.0f);
}

TEST(Driver, ProgressReachesOneAndIsMonotonicPerCall) {
    Camera cam(test_camera(), 100, 70);
    RenderOptions o;
    o.width = 100;
    o.height = 70;
    o.threads = 2;
    std::mutex m;
    double last = 0;
    int calls = 0;
    o.progress = [&](double f) {
        std::lock_guard<std::mutex> lock(m);
        EXPECT_GT(f, 0.0);
        EXPECT_LE(f, 1.0);
        last = std::max(last, f);
        ++calls;
    };
    run_tiles(cam, o, {}, busy);
    EXPECT_DOUBLE_EQ(last, 1.0);
    EXPECT_EQ(calls, 4 * 3);  // 32-pixel blocks
}

TEST(Driver, CancellationThrowsCancelled) {
    Camera cam(test_camera(), 200, 200);
    RenderOptions o;
    o.width = 200;
    o.height = 200;
    o.threads = 2;
    std::atomic<bool> cancel{false};
    std::atomic<int> traced{0};
    o.cancel = &cancel;
    o.progress = [&](double) { cancel = true; };
    RadianceFn counting = [&](const Ray& r, const SampleId&) {
        ++traced;
        return busy(r);
    };
    try {
        run_tiles(cam, o, {}, counting);
        FAIL() << "expected cancellation";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Cancelled);
    }
    EXPECT_LT(traced.load(), 200 * 200);  // stopped early
}

TEST(Driver, NonFiniteRadianceNeverReachesTheImage) {
    Camera cam(test_camera(), 8, 8);
    RenderOptions o;
    o.width = 8;
    o.height = 8;
    RadianceFn bad = [](const Ray& r, const SampleId&) {
        return r.dir.x < 0 ? Color(NAN, INFINITY, -1.0) : Color(1e300, 0.5, 0.25);
    };
    Image img = run_tiles(cam, o, {}, bad);
    for (float v : img.rgba) {
        EXPECT_TRUE(std::isfinite(v));
        EXPECT_GE(v, 0.0f);
    }
}

TEST(Driver, SampleIdsNamePixelAndSampleWhateverTheThreads) {
    Camera cam(test_camera(), 45, 37);
    RenderOptions o;
    o.width = 45;
    o.height = 37;
    o.aa = AaMode::Grid;
    o.grid_n = 2;
    RadianceFn ids = [](const Ray&, const SampleId& id) {
        return Color(id.x, id.y, id.index);
    };
    o.threads = 2;
    Image img = run_tiles(cam, o, {}, ids);
    // Grid samples 0..3 average to 1.5; x and y name the pixel.
    EXPECT_FLOAT_EQ(img.pixel(44, 36)[0], 44.0f);
    EXPECT_FLOAT_EQ(img.pixel(44, 36)[1], 36.0f);
    EXPECT_FLOAT_EQ(img.pixel(44, 36)[2], 1.5f);
}

TEST(Driver, GridAveragesSubsamples) {
    Camera cam(test_camera(), 10, 10);
    RenderOptions o;
    o.width = 10;
    o.height = 10;
    o.aa = AaMode::Grid;
    o.grid_n = 3;
    RadianceFn left_right = [](const Ray& r, const SampleId&) { return r.dir.x < 0 ? Color(0.0) : Color(1.0); };
    Image img = run_tiles(cam, o, {}, left_right);
    // The screen centre is the boundary between pixel columns 4 and 5: all subsamples of
    // pixel 4 are left of it, all of pixel 5 right of it.
    EXPECT_FLOAT_EQ(img.pixel(4, 5)[0], 0.0f);
    EXPECT_FLOAT_EQ(img.pixel(5, 5)[0], 1.0f);
}

TEST(Driver, AdaptiveSupersamplesOnlyEdges) {
    Camera cam(test_camera(), 33, 20);
    RenderOptions o;
    o.width = 33;
    o.height = 20;
    o.aa = AaMode::Adaptive;
    o.aa_depth = 3;
    // Edge inside pixel column 10 (not on a pixel boundary).
    double edge_sx = (10 + 0.5 + 0.2) / 33.0 - 0.5;
    RadianceFn step = [edge_sx](const Ray& r, const SampleId&) {
        return r.dir.x / r.dir.z * (1.0 / 1.33) < edge_sx ? Color(0.0) : Color(1.0);
    };
    Image img = run_tiles(cam, o, {}, step);
    // The edge lies at raster x = 10.2. Pixel 10's centre is left of it (0); it differs from
    // pixel 11, so both are supersampled: 3x3 samples at offsets -1/3, 0, 1/3 plus the centre
    // sample, averaged over 10. Pixel 10 sees the edge in its right column: 3 / 10.
    EXPECT_NEAR(img.pixel(10, 7)[0], 0.3f, 1e-6);
    EXPECT_NEAR(img.pixel(11, 7)[0], 1.0f, 1e-6);
    EXPECT_FLOAT_EQ(img.pixel(3, 7)[0], 0.0f);
    EXPECT_FLOAT_EQ(img.pixel(20, 7)[0], 1.0f);
}

}  // namespace
}  // namespace glint::render
