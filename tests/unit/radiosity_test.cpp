// POV-Ray radiosity's parts (render/gi/radiosity.h): the irradiance cache's reuse rules, the
// gather's cosine-distributed directions and its averaging, against what they must give on
// cases whose answer is known: a uniform sky gives its own colour, a cosine lobe's mean cosine
// is 2/3, and a cached sample is reused near its point and normal but not past its reach.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "core/log.h"
#include "render/gi/radiosity.h"
#include "render/render.h"
#include "unit/pov_test_util.h"

namespace glint::render {
namespace {

RadiositySample sample_at(const Vec3& p, const Vec3& n, const Color& c, double reach) {
    RadiositySample s;
    s.p = p;
    s.n = n;
    s.to_nearest = -n;
    s.irradiance = c;
    s.harmonic_mean = reach;
    s.nearest = reach;
    s.quality = 1;
    return s;
}

TEST(RadiosityCache, ReusesASampleAtItsOwnPointWithFullWeight) {
    RadiosityCache cache;
    cache.add(sample_at(Vec3(1, 2, 3), Vec3(0, 1, 0), Color(0.5, 0.25, 1), 0.4), 0.4 * 1.8);
    RadiosityReuse r;
    cache.gather(Vec3(1, 2, 3), Vec3(0, 1, 0), 0, 1.8, false, &r);
    EXPECT_DOUBLE_EQ(r.weight, 1.0);
    EXPECT_DOUBLE_EQ(r.weighted.g, 0.25);
    // The final render's pseudo-sigmoid also gives 1 at no error.
    RadiosityReuse smooth;
    cache.gather(Vec3(1, 2, 3), Vec3(0, 1, 0), 0, 1.8, true, &smooth);
    EXPECT_DOUBLE_EQ(smooth.weight, 1.0);
}

TEST(RadiosityCache, WeightFallsWithDistanceAndEndsAtTheErrorBound) {
    RadiosityCache cache;
    const double reach = 0.5, bound = 1.8;
    cache.add(sample_at(Vec3(0, 0, 0), Vec3(0, 1, 0), Color(1), reach), reach * bound);
    // Along the surface (perpendicular to to_nearest): error = dist / reach, linear weight.
    for (double d : {0.1, 0.3, 0.6, 0.85}) {
        RadiosityReuse r;
        cache.gather(Vec3(d, 0, 0), Vec3(0, 1, 0), 0, bound, false, &r);
        EXPECT_NEAR(r.weight, 1 - (d / reach) / bound, 1e-12) << d;
    }
    RadiosityReuse far;
    cache.gather(Vec3(reach * bound * 1.01, 0, 0), Vec3(0, 1, 0), 0, bound, false, &far);
    EXPECT_EQ(far.weight, 0.0);
    // A tilted normal adds 2 sqrt(1 - cos): 90 degrees is already past 1.8.
    RadiosityReuse tilted;
    cache.gather(Vec3(0, 0, 0), Vec3(1, 0, 0), 0, bound, false, &tilted);
    EXPECT_EQ(tilted.weight, 0.0);
    // Another recursion depth never sees it.
    RadiosityReuse other_depth;
    cache.gather(Vec3(0, 0, 0), Vec3(0, 1, 0), 1, bound, false, &other_depth);
    EXPECT_EQ(other_depth.weight, 0.0);
}

TEST(RadiosityCache, SkipsSamplesWellInFrontOfThePoint) {
    // A sample on a ledge above the point (in front along the normal) may be shadowing it.
    RadiosityCache cache;
    cache.add(sample_at(Vec3(0, 0, 0), Vec3(0, 1, 0), Color(1), 1.0), 1.8);
    RadiosityReuse below;
    cache.gather(Vec3(0.05, -0.3, 0), Vec3(0, 1, 0), 0, 1.8, false, &below);
    EXPECT_EQ(below.weight, 0.0);
    RadiosityReuse above;
    cache.gather(Vec3(0.05, 0.3, 0), Vec3(0, 1, 0), 0, 1.8, false, &above);
    EXPECT_GT(above.weight, 0.0);
}

TEST(RadiosityCache, FindsSamplesFiledAtEveryScaleAndPlace) {
    // The octree files by influence radius; lookups anywhere inside the reach must find the
    // sample whatever its size and however it straddles cube boundaries.
    for (double reach : {1e-3, 0.07, 1.0, 37.0}) {
        for (const Vec3& p : {Vec3(0, 0, 0), Vec3(-5.3, 2.2, 9.9), Vec3(1000, -1000, 0.5)}) {
            RadiosityCache cache;
            cache.add(sample_at(p, Vec3(0, 0, 1), Color(1), reach), reach * 1.8);
            for (double f : {-0.9, -0.5, 0.0, 0.5, 0.9}) {
                RadiosityReuse r;
                cache.gather(p + Vec3(f * reach, -f * reach * 0.5, 0), Vec3(0, 0, 1), 0, 1.8,
                             false, &r);
                EXPECT_GT(r.weight, 0.0) << reach << " " << f;
            }
        }
    }
}

TEST(RadiosityCache, OddReachesNeitherHangNorGetLost) {
    // An infinite reach (a huge maximum_reuse and rays that all miss) is filed at a huge but
    // finite cube; a NaN reach as no reach; a sample at a non-finite point is not kept.
    RadiosityCache cache;
    cache.add(sample_at(Vec3(1, 2, 3), Vec3(0, 1, 0), Color(1), 1e300), kInfinity);
    cache.add(sample_at(Vec3(4, 5, 6), Vec3(0, 1, 0), Color(1), 0.5), std::nan(""));
    cache.add(sample_at(Vec3(kInfinity, 0, 0), Vec3(0, 1, 0), Color(1), 0.5), 1.0);
    EXPECT_EQ(cache.size(), 2u);
    RadiosityReuse r;
    cache.gather(Vec3(1, 2, 3.5), Vec3(0, 1, 0), 0, 1.8, false, &r);
    EXPECT_GT(r.weight, 0.0);
}

RadiosityPoint point_up() {
    RadiosityPoint at;
    at.p = Vec3(0, 0, 0);
    at.p_error = Vec3(1e-9);
    at.ng = at.raw_n = at.layer_n = Vec3(0, 1, 0);
    return at;
}

TEST(Radiosity, AUniformSkyGivesItsOwnColourTimesBrightness) {
    scene::Radiosity s;
    s.brightness = 1.5;
    Radiosity rad(s, Vec3(0, 1, -5));
    RadiosityBlock block;
    RadiosityTicket t;
    t.block = &block;
    int rays = 0;
    auto sky = [&](const Ray& r, double, int level, RadiosityTicket& ticket, double* depth) {
        ++rays;
        EXPECT_GT(dot(r.dir, Vec3(0, 1, 0)), 0.0);  // never below the surface
        EXPECT_EQ(ticket.depth, 1);
        EXPECT_EQ(level, 1);  // POV-Ray's trace level for depth 0's rays
        *depth = kInfinity;
        return Color(0.2, 0.4, 0.8);
    };
    const Color c = rad.ambient(point_up(), 1.0, t, sky);
    EXPECT_EQ(rays, 35);  // count
    EXPECT_NEAR(c.r, 0.3, 1e-12);
    EXPECT_NEAR(c.g, 0.6, 1e-12);
    EXPECT_NEAR(c.b, 1.2, 1e-12);
    EXPECT_EQ(t.depth, 0);
    // The sample went into the block's cache; the next query nearby reuses it.
    EXPECT_EQ(block.local.size(), 1u);
}

TEST(Radiosity, RaysFollowTheCosineLobe) {
    // The mean cosine of cosine-distributed directions is 2/3; the Halton pool of 35 gets
    // within a few percent, with 800 rays within a fraction of one.
    for (int count : {35, 800}) {
        scene::Radiosity s;
        s.count = count;
        Radiosity rad(s, Vec3(0, 1, -5));
        RadiosityBlock block;
        RadiosityTicket t;
        t.block = &block;
        auto cosine = [](const Ray& r, double, int, RadiosityTicket&, double* depth) {
            *depth = 1;
            return Color(dot(r.dir, Vec3(0, 1, 0)));
        };
        const Color c = rad.ambient(point_up(), 1.0, t, cosine);
        EXPECT_NEAR(c.r, 2.0 / 3.0, count == 35 ? 0.03 : 0.005) << count;
    }
}

TEST(Radiosity, GrayThresholdAndMaxSample) {
    scene::Radiosity s;
    s.gray_threshold = 1;
    s.max_sample = 0.5;
    Radiosity rad(s, Vec3(0, 1, -5));
    RadiosityBlock block;
    RadiosityTicket t;
    t.block = &block;
    auto red = [](const Ray&, double, int, RadiosityTicket&, double* depth) {
        *depth = 2;
        return Color(2, 0, 0);
    };
    const Color c = rad.ambient(point_up(), 1.0, t, red);
    // Each ray is scaled to a brightest channel of 0.5, then made fully grey.
    EXPECT_NEAR(c.r, 0.297 * 0.5, 1e-12);
    EXPECT_NEAR(c.g, c.r, 1e-12);
}

TEST(Radiosity, PretraceIsTheSameWhateverTheThreadCount) {
    scene::Radiosity s;
    auto run = [&](int threads) {
        Radiosity rad(s, Vec3(0, 0, -5));
        // A ground plane at y = -1 under a grey sky: each pixel's ray hits it or misses.
        auto pixel = [&](double x, double y, RadiosityTicket& t) {
            if (y < 60) return;  // the upper half sees sky: no radiosity
            const Vec3 p((x - 80) * 0.05, -1, (y - 60) * 0.1);
            RadiosityPoint at = point_up();
            at.p = p;
            rad.ambient(at, 1.0, t, [](const Ray& r, double, int, RadiosityTicket&, double* d) {
                *d = kInfinity;
                return Color(0.5 + 0.5 * r.dir.x);
            });
        };
        std::atomic<bool> cancel{false};
        EXPECT_TRUE(rad.pretrace(160, 120, threads, &cancel, pixel));
        return rad.cache_size();
    };
    const size_t one = run(1);
    EXPECT_GT(one, 10u);
    EXPECT_EQ(run(2), one);
}

// A furnace for radiosity: the camera inside a sphere whose surface emits E and reflects
// diffusely with albedo rho. Every sample ray sees the same radiance, so the cache is exact and
// each recursion level adds one more bounce: L = E (1 + rho + ... + rho^limit).
RenderResult furnace(int limit, int threads, double brightness = 1) {
    const std::string scene =
        "#version 3.7;\n"
        "global_settings { radiosity { count 50 recursion_limit " + std::to_string(limit) +
        " brightness " + std::to_string(brightness) + " } }\n"
        "camera { location 0 look_at z }\n"
        "sphere { 0, 10 pigment { rgb 1 } finish { emission 0.2 diffuse 0.5 ambient 0.3 } }\n";
    RenderOptions o;
    o.width = 24;
    o.height = 18;
    o.threads = threads;
    o.integrator = IntegratorKind::Whitted;
    Diagnostics diag;
    return render(pov::testing::parse(scene), o, diag);
}

TEST(RadiosityRender, FurnaceAddsOneBouncePerRecursionLevel) {
    for (int limit : {1, 2, 3}) {
        double expected = 0, term = 0.2;
        for (int i = 0; i <= limit; ++i, term *= 0.5) expected += term;
        const Image img = furnace(limit, 2).image;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                ASSERT_NEAR(img.pixel(x, y)[1], expected, 1e-6) << limit << " at " << x << "," << y;
    }
    // brightness scales each bounce's gathered light: 0.2 + 0.5 * 2 * (0.2 + 0.5 * 2 * 0.2).
    const Image bright = furnace(2, 1, 2.0).image;
    EXPECT_NEAR(bright.pixel(3, 3)[0], 0.2 + 0.5 * 2 * (0.2 + 0.5 * 2 * 0.2), 1e-6);
}

TEST(RadiosityRender, ImageIsIdenticalForOneAndTwoThreadsAndInFarmRegions) {
    // A small diffuse room lit by a point light: the cache holds real variation.
    const std::string text =
        "#version 3.7;\n"
        "global_settings { radiosity { count 30 error_bound 0.8 recursion_limit 2 } }\n"
        "camera { location <0, 1.5, -4> look_at <0, 1, 0> }\n"
        "light_source { <1, 2.5, -1> rgb 1 }\n"
        "box { <-2, 0, -5>, <2, 3, 2> inverse pigment { rgb 0.8 } finish { ambient 0 } }\n"
        "box { <-2.01, 0, -5>, <-1.99, 3, 2> pigment { rgb <0.9, 0.1, 0.1> } }\n"
        "sphere { <0.5, 0.6, 0>, 0.6 pigment { rgb <0.2, 0.3, 0.9> } }\n";
    const scene::Scene s = pov::testing::parse(text);
    RenderOptions o;
    o.width = 96;
    o.height = 64;
    o.integrator = IntegratorKind::Whitted;
    Diagnostics diag;
    o.threads = 1;
    const Image one = render(s, o, diag).image;
    o.threads = 2;
    const Image two = render(s, o, diag).image;
    EXPECT_EQ(one.rgba, two.rgba);
    // A farm part (a region) gets the same pixels as the whole render: one shared pretrace.
    o.region = Region{32, 0, 96, 32};
    const Image part = render(s, o, diag).image;
    ASSERT_EQ(part.width, 64);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 4; ++c)
                ASSERT_EQ(part.pixel(x, y)[c], one.pixel(x + 32, y)[c]) << x << "," << y;
    // And radiosity does light it: the floor in the sphere's shadow is not black.
    float darkest = 1;
    for (float v : one.rgba) darkest = std::min(darkest, v);
    EXPECT_GT(darkest, 0.0f);
}

}  // namespace
}  // namespace glint::render
