// The path tracer end to end: the white furnace (VALIDATION.md case 10), the lossless
// specular furnace (case 12), thread-count independence (case 18), and a POV-Ray area light
// over a diffuse plane against the irradiance integrated by quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/log.h"
#include "render/camera.h"
#include "render/integrators/path_lights.h"
#include "render/render.h"

namespace glint::render {
namespace {

scene::Material lambert(Color c) {
    scene::Material m;
    m.pbr.derived = false;
    m.pbr.base_color = c;
    m.pbr.specular = 0;
    m.pbr.metallic = 0;
    m.pbr.roughness = 1;
    return m;
}

scene::Scene sphere_in_environment(const scene::Material& m) {
    scene::Scene s;
    s.camera.location = Vec3(0, 0, -4);
    s.materials.push_back(m);
    scene::Object o;
    o.shape = scene::Sphere{Vec3(0, 0, 0), 1};
    o.material = 0;
    s.objects.push_back(o);
    s.background = scene::ColorFT(Color(1, 1, 1));
    return s;
}

RenderOptions path_options(int w, int h, int spp) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.integrator = IntegratorKind::Path;
    o.spp = spp;
    o.max_depth = 64;
    o.threads = 2;
    return o;
}

struct Stats {
    double mean = 0, stderr_ = 0;
    double max_dev = 0;
};

// Mean over the pixels (all channels) and its standard error from the pixels' spread.
Stats image_stats(const Image& img) {
    double s = 0, s2 = 0;
    size_t n = 0;
    Stats st;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v = img.pixel(x, y)[c];
                s += v;
                s2 += v * v;
                ++n;
                st.max_dev = std::max(st.max_dev, std::fabs(v - 1.0));
            }
    st.mean = s / n;
    st.stderr_ = std::sqrt(std::max(0.0, s2 / n - st.mean * st.mean) / n);
    return st;
}

TEST(PathRender, WhiteFurnaceConvergesToOne) {
    Diagnostics diag;
    const scene::Scene s = sphere_in_environment(lambert(Color(1, 1, 1)));
    RenderResult r = render(s, path_options(48, 36, 256), diag);
    EXPECT_EQ(r.samples_per_pixel, 256);
    EXPECT_EQ(r.nonfinite_paths, 0u);
    const Stats st = image_stats(r.image);
    std::printf("white furnace: mean %.7f, stderr %.2g, max |pixel - 1| %.3g\n", st.mean,
                st.stderr_, st.max_dev);
    EXPECT_NEAR(st.mean, 1.0, 3 * st.stderr_ + 1e-6) << "stderr " << st.stderr_;
    EXPECT_NEAR(st.mean, 1.0, 1e-3);  // VALIDATION.md case 10
}

TEST(PathRender, ClosedSphereFurnace) {
    // VALIDATION.md case 11: the camera inside a unit sphere with albedo 0.5 and emission 0.5
    // sees Le / (1 - albedo) = 1 everywhere (emission found by BSDF sampling only).
    scene::Material m = lambert(Color(0.5, 0.5, 0.5));
    m.pbr.emission = Color(0.5, 0.5, 0.5);
    m.pbr.emission_strength = 1;
    scene::Scene s = sphere_in_environment(m);
    s.background = scene::ColorFT(Color(0, 0, 0));
    s.camera.location = Vec3(0, 0, 0);
    Diagnostics diag;
    RenderOptions o = path_options(32, 24, 64);
    o.max_depth = 64;
    RenderResult r = render(s, o, diag);
    const Stats st = image_stats(r.image);
    std::printf("closed-sphere furnace: mean %.6f, stderr %.2g\n", st.mean, st.stderr_);
    EXPECT_NEAR(st.mean, 1.0, 3 * st.stderr_ + 1e-6);
    EXPECT_NEAR(st.mean, 1.0, 0.005);
}

TEST(PathRender, LosslessSpecularFurnace) {
    // A mirror and a smooth glass sphere (ior 1.5) lose nothing at depth 64 (case 12).
    scene::Material mirror = lambert(Color(1, 1, 1));
    mirror.pbr.metallic = 1;
    mirror.pbr.roughness = 0;
    scene::Material glass = lambert(Color(1, 1, 1));
    glass.pbr.transmission = 1;
    glass.pbr.roughness = 0;
    glass.pbr.ior = 1.5;
    glass.pbr.specular = 0.5;
    for (const scene::Material& m : {mirror, glass}) {
        Diagnostics diag;
        RenderResult r = render(sphere_in_environment(m), path_options(32, 24, 16), diag);
        const Stats st = image_stats(r.image);
        std::printf("specular furnace (%s): mean %.7f, stderr %.2g\n",
                    m.pbr.transmission > 0 ? "glass" : "mirror", st.mean, st.stderr_);
        // Unbiased (Russian roulette only adds noise): 1 within 3 sigma, and within 1e-3.
        EXPECT_NEAR(st.mean, 1.0, 3 * st.stderr_ + 1e-6);
        EXPECT_NEAR(st.mean, 1.0, 1e-3);
        EXPECT_EQ(r.nonfinite_paths, 0u);
    }
    // The loss at depth 5, reported as case 12 asks: most paths leave a glass sphere after
    // two refractions, only internally reflected ones run out of depth.
    RenderOptions o5 = path_options(32, 24, 16);
    o5.max_depth = 5;
    Diagnostics diag;
    const Stats d5 = image_stats(render(sphere_in_environment(glass), o5, diag).image);
    std::printf("specular furnace (glass) at depth 5: mean %.6f, stderr %.2g\n", d5.mean,
                d5.stderr_);
    EXPECT_GT(d5.mean, 0.99);
}

scene::Scene busy_scene() {
    scene::Scene s = sphere_in_environment(lambert(Color(0.7, 0.5, 0.3)));
    s.background = scene::ColorFT(Color(0.2, 0.3, 0.4));
    scene::Material glass = lambert(Color(1, 1, 1));
    glass.pbr.transmission = 1;
    glass.pbr.roughness = 0.2;
    s.materials.push_back(glass);
    scene::Material emitter = lambert(Color(0, 0, 0));
    emitter.pbr.emission = Color(4, 4, 3);
    emitter.pbr.emission_strength = 1;
    s.materials.push_back(emitter);
    scene::Object g;
    g.shape = scene::Sphere{Vec3(1.2, 0.3, -1), 0.5};
    g.material = 1;
    s.objects.push_back(g);
    scene::Object plane;
    plane.shape = scene::Plane{Vec3(0, 1, 0), -1};
    plane.material = 0;
    s.objects.push_back(plane);
    scene::Object tri;
    tri.shape = scene::Triangle{{Vec3(-2, 2, 0), Vec3(-1, 2, 1), Vec3(-1.5, 2.5, -1)}};
    tri.material = 2;
    s.objects.push_back(tri);
    scene::Light l;
    l.location = Vec3(2, 4, -3);
    l.color = Color(0.5, 0.5, 0.5);
    l.area = scene::AreaLight{};
    s.lights.push_back(l);
    return s;
}

TEST(PathRender, ImageIsIdenticalForOneAndTwoThreads) {
    const scene::Scene s = busy_scene();
    RenderOptions o = path_options(40, 30, 8);
    o.max_depth = 6;
    Diagnostics diag;
    o.threads = 1;
    RenderResult a = render(s, o, diag);
    o.threads = 2;
    RenderResult b = render(s, o, diag);
    EXPECT_EQ(a.image.rgba, b.image.rgba);
    o.seed = 7;
    RenderResult c = render(s, o, diag);
    EXPECT_NE(a.image.rgba, c.image.rgba);
    EXPECT_EQ(a.nonfinite_paths, 0u);
}

TEST(PathRender, AreaLightOverDiffusePlaneMatchesQuadrature) {
    // A POV-Ray area light (a rectangle of isotropic emitters, fade_power 2) over a white
    // Lambert plane seen from above: radiance = C * mean over the rectangle of cos * fade.
    scene::Scene s;
    s.camera.location = Vec3(0, 6, 0);
    s.camera.direction = Vec3(0, -1, 0);
    s.camera.up = Vec3(0, 0, 1);
    s.camera.right = Vec3(1.33, 0, 0);
    s.materials.push_back(lambert(Color(1, 1, 1)));
    scene::Object plane;
    plane.shape = scene::Plane{Vec3(0, 1, 0), 0};
    plane.material = 0;
    s.objects.push_back(plane);
    scene::Light l;
    l.location = Vec3(0.3, 1.5, -0.2);
    l.color = Color(1, 1, 1);
    l.fade_distance = 1;
    l.fade_power = 2;
    scene::AreaLight a;
    a.axis1 = Vec3(1, 0, 0);
    a.axis2 = Vec3(0, 0, 0.5);
    l.area = a;
    s.lights.push_back(l);

    const int w = 24, h = 18;
    Diagnostics diag;
    RenderResult r = render(s, path_options(w, h, 64), diag);
    Camera cam(s.camera, w, h);
    auto irradiance_term = [&](const Vec3& p) {
        const int n = 48;
        double sum = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const Vec3 q = l.location + a.axis1 * ((i + 0.5) / n - 0.5) +
                               a.axis2 * ((j + 0.5) / n - 0.5);
                const Vec3 d = q - p;
                const double dist = length(d);
                sum += (d.y / dist) * 2.0 / (1.0 + dist * dist);
            }
        return sum / (n * n);
    };
    double s1 = 0, s2 = 0;
    int count = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double ref = 0;
            const int k = 3;  // the pixel's footprint, as the jittered samples cover it
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) {
                    const Ray ray = *cam.generate(x + (i + 0.5) / k - 0.5, y + (j + 0.5) / k - 0.5);
                    const double t = -ray.origin.y / ray.dir.y;
                    ref += irradiance_term(ray.origin + ray.dir * t);
                }
            ref /= k * k;
            const double d = r.image.pixel(x, y)[1] - ref;
            s1 += d;
            s2 += d * d;
            ++count;
        }
    const double mean = s1 / count;
    const double se = std::sqrt(std::max(0.0, s2 / count - mean * mean) / count);
    EXPECT_NEAR(mean, 0.0, 3 * se + 2e-4) << "stderr " << se;
}

TEST(PathRender, EmissiveQuadOverDiffusePlaneMatchesQuadrature) {
    // Two emissive triangles (a two-sided Lambertian emitter, Le = 3) beside the view light a
    // white Lambert plane: L = Le / pi * integral of cos_p cos_l / r^2 over the quad. Light
    // sampling and BSDF sampling are combined by MIS, so this checks both and their weights.
    scene::Scene s;
    s.camera.location = Vec3(0, 6, 0);
    s.camera.direction = Vec3(0, -3, 0);
    s.camera.up = Vec3(0, 0, 1);
    s.camera.right = Vec3(1.33, 0, 0);
    s.materials.push_back(lambert(Color(1, 1, 1)));
    scene::Material emitter = lambert(Color(0, 0, 0));
    emitter.pbr.emission = Color(3, 3, 3);
    emitter.pbr.emission_strength = 1;
    s.materials.push_back(emitter);
    scene::Object plane;
    plane.shape = scene::Plane{Vec3(0, 1, 0), 0};
    plane.material = 0;
    s.objects.push_back(plane);
    const Vec3 c[4] = {Vec3(2, 1, -0.5), Vec3(3, 1, -0.5), Vec3(3, 1, 0.5), Vec3(2, 1, 0.5)};
    for (int k = 0; k < 2; ++k) {
        scene::Object t;
        t.shape = scene::Triangle{{c[0], c[1 + k], c[2 + k]}};
        t.material = 1;
        s.objects.push_back(t);
    }
    const int w = 24, h = 18;
    Diagnostics diag;
    RenderResult r = render(s, path_options(w, h, 64), diag);
    EXPECT_EQ(r.nonfinite_paths, 0u);
    Camera cam(s.camera, w, h);
    auto radiance = [&](const Vec3& p) {
        const int n = 48;
        double sum = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const Vec3 q(2 + (i + 0.5) / n, 1, -0.5 + (j + 0.5) / n);
                const Vec3 d = q - p;
                const double r2 = length_squared(d);
                sum += (d.y * d.y / r2) / r2;
            }
        return 3.0 / kPi * sum / (n * n);  // area 1
    };
    double s1 = 0, s2 = 0;
    int count = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double ref = 0;
            const int k = 3;
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) {
                    const Ray ray = *cam.generate(x + (i + 0.5) / k - 0.5, y + (j + 0.5) / k - 0.5);
                    const double t = -ray.origin.y / ray.dir.y;
                    ref += radiance(ray.origin + ray.dir * t);
                }
            ref /= k * k;
            const double d = r.image.pixel(x, y)[0] - ref;
            s1 += d;
            s2 += d * d;
            ++count;
        }
    const double mean = s1 / count;
    const double se = std::sqrt(std::max(0.0, s2 / count - mean * mean) / count);
    std::printf("emissive quad: mean pixel - quadrature %.3g, stderr %.2g\n", mean, se);
    EXPECT_NEAR(mean, 0.0, 3 * se + 2e-4) << "stderr " << se;
}

TEST(PathLights, SpotConeFollowsPovRaysAttenuation) {
    // POV-Ray's spot: full inside radius (times cos^tightness), POV-Ray's cubic between
    // radius and falloff, nothing outside falloff; irradiance factor pi * color.
    scene::Scene s;
    scene::Light l;
    l.kind = scene::LightKind::Spot;
    l.location = Vec3(0, 10, 0);
    l.point_at = Vec3(0, 0, 0);
    l.radius = 10;
    l.falloff = 20;
    l.color = Color(1, 1, 1);
    s.lights.push_back(l);
    PathLights lights(s, {});
    ASSERT_EQ(lights.count(), 1);
    auto at_angle = [&](double deg) {
        const Vec3 p(10 * std::tan(deg * kPi / 180), 0, 0);
        PathLightSample ls;
        EXPECT_TRUE(lights.sample(0, p, {0.5, 0.5}, &ls) || deg > 20);
        return ls.value.r / kPi;
    };
    EXPECT_NEAR(at_angle(0), 1.0, 1e-12);
    EXPECT_NEAR(at_angle(9.9), 1.0, 1e-12);
    const double c = std::cos(15 * kPi / 180), lo = std::cos(20 * kPi / 180),
                 hi = std::cos(10 * kPi / 180);
    const double t = (c - lo) / (hi - lo);
    EXPECT_NEAR(at_angle(15), (3 - 2 * t) * t * t, 1e-12);
    EXPECT_EQ(at_angle(25), 0.0);
}

}  // namespace
}  // namespace glint::render
