// The tile driver: thread-count independence, progress, cancellation, anti-aliasing modes.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <mutex>

#include "core/error.h"
#include "render/film/driver.h"

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
    for (AaMode aa : {AaMode::None, AaMode::Adaptive, AaMode::Adaptive2, AaMode::Grid}) {
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
    o.aa_jitter = 0;  // -J: the sub-samples on their grid
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

// The raster x of a ray of test_camera() on a 33-pixel-wide image (the inverse of its
// projection: right vector 1.33, pixel centres at integers).
double raster_x(const Ray& r) { return (r.dir.x / r.dir.z / 1.33 + 0.5) * 33.0 - 0.5; }

// POV-Ray's default jitter (+J1.0) moves each of method 1's sub-samples within its own cell
// of the aa_depth grid (by at most half a cell), not the pixel's first sample; every pixel
// still gets the same samples whatever the thread.
TEST(Driver, AdaptiveJitterStaysInsideEachSubsampleCell) {
    Camera cam(test_camera(), 33, 20);
    RenderOptions o;
    o.width = 33;
    o.height = 20;
    o.aa = AaMode::Adaptive;
    o.aa_depth = 3;
    o.threads = 1;
    ASSERT_EQ(o.aa_jitter, 1.0);  // POV-Ray's default
    const double edge = 10.2;
    std::mutex m;
    int subsamples = 0, moved = 0, outside = 0, centre_moved = 0;
    RadianceFn step = [&](const Ray& r, const SampleId& id) {
        const double x = raster_x(r);
        std::lock_guard<std::mutex> lock(m);
        if (id.index == 0) {
            centre_moved += std::fabs(x - id.x) > 1e-9;
        } else {
            ++subsamples;
            const int i = static_cast<int>((id.index - 1) % 3);
            const double cell = id.x - 1.0 / 3.0 + i / 3.0;  // the unjittered column
            moved += std::fabs(x - cell) > 1e-9;
            outside += std::fabs(x - cell) > 0.5 / 3.0 + 1e-9;
        }
        return x < edge ? Color(0.0) : Color(1.0);
    };
    Image img = run_tiles(cam, o, {}, step);
    EXPECT_GT(subsamples, 0);
    EXPECT_GT(moved, subsamples / 2);
    EXPECT_EQ(outside, 0);
    EXPECT_EQ(centre_moved, 0);
    // Pixel 10 is still a mix of both sides, its neighbours are not.
    EXPECT_GT(img.pixel(10, 7)[0], 0.05f);
    EXPECT_LT(img.pixel(10, 7)[0], 0.95f);
    EXPECT_FLOAT_EQ(img.pixel(3, 7)[0], 0.0f);
    EXPECT_FLOAT_EQ(img.pixel(20, 7)[0], 1.0f);
}

// Sampling method 2 splits a pixel from its four corners while they differ, aa_depth - 1
// times: with the edge at x = 10.2, pixel 10 (corners at 9.5 and 10.5) splits, its left
// quarters (9.5 .. 10.0) are 0, its right ones split again at 10.25 into 0.5 and 1:
// (0 + 0 + 0.75 + 0.75) / 4.
TEST(Driver, Adaptive2SubdividesFromTheCorners) {
    Camera cam(test_camera(), 33, 20);
    RenderOptions o;
    o.width = 33;
    o.height = 20;
    o.aa = AaMode::Adaptive2;
    o.aa_depth = 3;
    o.aa_jitter = 0;
    RadianceFn step = [](const Ray& r, const SampleId&) {
        return raster_x(r) < 10.2 ? Color(0.0) : Color(1.0);
    };
    Image img = run_tiles(cam, o, {}, step);
    EXPECT_NEAR(img.pixel(10, 7)[0], 0.375f, 1e-6);
    EXPECT_FLOAT_EQ(img.pixel(11, 7)[0], 1.0f);
    EXPECT_FLOAT_EQ(img.pixel(9, 7)[0], 0.0f);
    // aa_depth 1 allows no split: the mean of the four corners.
    o.aa_depth = 1;
    img = run_tiles(cam, o, {}, step);
    EXPECT_NEAR(img.pixel(10, 7)[0], 0.5f, 1e-6);
}

}  // namespace
}  // namespace glint::render

namespace glint::render {
namespace {

// Region (x0, y0)-(x1, y1) of `full` equals `part` bit for bit.
void expect_crop(const Image& full, const Image& part, const Region& r, const char* what) {
    ASSERT_EQ(part.width, r.width()) << what;
    ASSERT_EQ(part.height, r.height()) << what;
    int differ = 0;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x)
            for (int c = 0; c < 4; ++c)
                differ += full.pixel(x, y)[c] != part.pixel(x - r.x0, y - r.y0)[c];
    EXPECT_EQ(differ, 0) << what << " region " << r.x0 << "," << r.y0 << "," << r.x1 << ","
                         << r.y1;
}

// Regions that cut blocks anywhere (adaptive AA compares neighbours within 32x32 blocks), the
// whole image, one pixel, and a corner: each is the same pixels as the whole render.
TEST(Driver, RegionsAreTheWholeRendersPixels) {
    Camera cam(test_camera(), 97, 61);
    const Region regions[] = {{0, 0, 97, 61}, {13, 5, 71, 40}, {31, 31, 33, 33},
                              {96, 60, 97, 61}, {0, 32, 64, 61}, {50, 0, 51, 61}};
    for (AaMode aa : {AaMode::None, AaMode::Adaptive, AaMode::Adaptive2, AaMode::Grid}) {
        RenderOptions o;
        o.width = 97;
        o.height = 61;
        o.aa = aa;
        o.threads = 2;
        const Image full = run_tiles(cam, o, {}, busy);
        const char* names[] = {"none", "adaptive", "adaptive2", "grid"};
        for (const Region& r : regions) {
            o.region = r;
            expect_crop(full, run_tiles(cam, o, {}, busy), r, names[static_cast<int>(aa)]);
        }
        o.region = {};
    }
}

// Adaptive sampling (Cycles' Noise Threshold): a pixel whose samples do not vary stops at the
// minimum, a noisy one goes on to the full count; the noisy pixels' means stay unbiased, and
// the image is the same at one and two threads and in any region.
TEST(Driver, AdaptiveSamplingStopsQuietPixelsFirst) {
    Camera cam(test_camera(), 40, 20);
    std::mutex m;
    std::vector<int> samples(40 * 20, 0);
    PathRadianceFn f = [&](const Ray&, const SampleId& id, FirstHit*) {
        {
            std::lock_guard<std::mutex> lock(m);
            ++samples[static_cast<size_t>(id.y) * 40 + id.x];
        }
        if (id.x < 20) return Color(0.5, 0.5, 0.5);  // the left half: no noise at all
        // The right half: values 0 or 1 with mean 0.5, a hash of the sample.
        uint32_t h = static_cast<uint32_t>(id.x * 73856093u ^ id.y * 19349663u ^
                                           (id.index + 1) * 83492791u);
        h ^= h >> 13;
        h *= 0x5bd1e995u;
        h ^= h >> 15;
        return Color((h & 1) ? 1.0 : 0.0);
    };
    RenderOptions o;
    o.width = 40;
    o.height = 20;
    o.spp = 256;
    o.adaptive = true;  // automatic: threshold 1/256 (x5), minimum 16 / (1/256)^0.3 = 85
    o.threads = 1;
    PathFilm one;
    EXPECT_EQ(run_path_tiles(cam, o, f, &one), 256);
    // The minimum rounded up to the next check (every 16 samples): 96 on the left; on the
    // right most pixels go on to 256 (a noisy pixel may pass the test by chance, as in
    // Cycles).
    double right = 0;
    for (int y = 0; y < 20; ++y) {
        for (int x = 0; x < 20; ++x) EXPECT_EQ(samples[y * 40 + x], 96) << x << "," << y;
        for (int x = 20; x < 40; ++x) right += samples[y * 40 + x] / 400.0;
        EXPECT_FLOAT_EQ(one.image.pixel(5, y)[0], 0.5f);
    }
    EXPECT_GT(right, 160);  // 197 on this hash
    double mean = 0;
    for (int y = 0; y < 20; ++y)
        for (int x = 20; x < 40; ++x) mean += one.image.pixel(x, y)[0] / 400.0;
    EXPECT_NEAR(mean, 0.5, 4 * 0.5 / std::sqrt(400.0 * 256));
    o.threads = 2;
    PathFilm two;
    run_path_tiles(cam, o, f, &two);
    EXPECT_EQ(one.image.rgba, two.image.rgba);
    const Region r{13, 2, 31, 17};
    o.region = r;
    PathFilm part;
    run_path_tiles(cam, o, f, &part);
    expect_crop(one.image, part.image, r, "adaptive region");
}

TEST(Driver, PathRegionsAreTheWholeRendersPixels) {
    Camera cam(test_camera(), 70, 45);
    // Radiance that depends on the sample's pixel and index, as the path tracer's does.
    PathRadianceFn f = [](const Ray& r, const SampleId& id, FirstHit* first) {
        if (first) {
            first->hit = true;
            first->albedo = Color(0.25, 0.5, id.index * 0.01);
            first->depth = 2 + r.dir.x;
        }
        return busy(r) * (1 + 0.1 * (id.index % 3));
    };
    RenderOptions o;
    o.width = 70;
    o.height = 45;
    o.spp = 7;
    o.seed = 5;
    o.aovs = true;
    o.variance = true;
    PathFilm full;
    run_path_tiles(cam, o, f, &full);
    for (const Region& r : {Region{3, 4, 41, 37}, Region{33, 0, 70, 45}, Region{0, 44, 1, 45}}) {
        o.region = r;
        PathFilm part;
        run_path_tiles(cam, o, f, &part);
        expect_crop(full.image, part.image, r, "image");
        expect_crop(full.albedo, part.albedo, r, "albedo");
        expect_crop(full.depth, part.depth, r, "depth");
        expect_crop(full.variance, part.variance, r, "variance");
    }
}

TEST(Driver, RegionsOutsideTheImageAreRefused) {
    Camera cam(test_camera(), 40, 30);
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    for (const Region& r : {Region{0, 0, 41, 30}, Region{-1, 0, 10, 10}, Region{5, 5, 5, 9},
                            Region{10, 10, 4, 20}}) {
        o.region = r;
        try {
            run_tiles(cam, o, {}, busy);
            ADD_FAILURE() << "accepted " << r.x0 << "," << r.y0 << "," << r.x1 << "," << r.y1;
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Usage);
            EXPECT_NE(std::string(e.what()).find("inside the 40x30 image"), std::string::npos)
                << e.what();
        }
    }
}

}  // namespace
}  // namespace glint::render
