// The path tracer end to end: the white furnace (VALIDATION.md case 10), the closed-sphere
// furnace (case 11), the lossless specular furnace (case 12), extreme gloss lobes (case 14),
// thread-count independence (case 18), and area and emissive lights over a diffuse plane
// against the irradiance integrated by quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "core/log.h"
#include "render/bsdf/bsdf.h"
#include "render/camera.h"
#include "render/lights/path_lights.h"
#include "render/render.h"
#include "unit/path_test_util.h"

namespace glint::render {
namespace {

using path_test::lambert;

// Deep enough that the furnaces lose nothing to the depth limit.
RenderOptions path_options(int w, int h, int spp) {
    return path_test::path_options(w, h, spp, 64);
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
    // VALIDATION.md case 10 at its 1024 spp.
    Diagnostics diag;
    const scene::Scene s = sphere_in_environment(lambert(Color(1, 1, 1)));
    RenderResult r = render(s, path_options(24, 18, 1024), diag);
    EXPECT_EQ(r.samples_per_pixel, 1024);
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
    // The loss at depth d, reported as case 12 asks. With the same seed the paths agree up to
    // the shorter depth, so the difference of two means is the loss itself, free of most of
    // the sampling noise. In a sphere every internal hit meets the entry angle again, so a
    // camera ray that hits at incidence cos keeps (1 - F) F^(d - 1) inside after d events
    // (F = Fresnel at cos): integrated here over each pixel's footprint by quadrature.
    const int w = 32, h = 24, spp = 256;
    Diagnostics diag;
    const scene::Scene glass_scene = sphere_in_environment(glass);
    const RenderResult deep = render(glass_scene, path_options(w, h, spp), diag);
    const Camera cam(glass_scene.camera, w, h);
    for (int depth : {1, 2, 3, 5}) {
        RenderOptions od = path_options(w, h, spp);
        od.max_depth = depth;
        const RenderResult shallow = render(glass_scene, od, diag);
        double s1 = 0, s2 = 0, expected = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double e = 0;
                const int k = 32;  // the rim where F^(d - 1) matters is thin
                for (int j = 0; j < k; ++j)
                    for (int i = 0; i < k; ++i) {
                        const Ray ray =
                            *cam.generate(x + (i + 0.5) / k - 0.5, y + (j + 0.5) / k - 0.5);
                        const double b = dot(ray.origin, ray.dir);
                        const double disc = b * b - (length_squared(ray.origin) - 1);
                        if (disc < 0) continue;
                        const Vec3 n = normalize(ray.origin + ray.dir * (-b - std::sqrt(disc)));
                        const double F = fresnel_dielectric(-dot(ray.dir, n), 1.5);
                        e += (1 - F) * std::pow(F, depth - 1);
                    }
                e /= k * k;
                expected += e;
                const double d = static_cast<double>(deep.image.pixel(x, y)[1]) -
                                 shallow.image.pixel(x, y)[1] - e;
                s1 += d;
                s2 += d * d;
            }
        const int count = w * h;
        const double diff = s1 / count;
        const double se = std::sqrt(std::max(0.0, s2 / count - diff * diff) / count);
        expected /= count;
        std::printf("specular furnace (glass): loss at depth %d = %.4g (expected %.4g; "
                    "difference %.2g, stderr %.2g)\n", depth, diff + expected, expected, diff, se);
        EXPECT_NEAR(diff, 0.0, 4 * se + 1e-6) << depth;
        if (depth == 5) {
            EXPECT_LT(diff + expected, 1e-3);
        }
    }
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

scene::Material pov_phong(double phong_size) {
    // A POV-Ray finish { phong 1 phong_size N } on a black pigment: only the highlight,
    // mapped onto GGX by pov_to_pbr (alpha = sqrt(2 / (N + 2))).
    scene::Material m;
    m.texture.pigment.color = scene::ColorFT(Color(0, 0, 0));
    m.texture.finish.phong = 1;
    m.texture.finish.phong_size = phong_size;
    return m;
}

TEST(PathRender, ExtremeGlossLobesAreFiniteAndHighlightSitsAtTheMirrorPoint) {
    // VALIDATION.md case 14: a glossy floor under a small emissive sphere, with POV-Ray
    // phong_size 0, 1e5 and 1e6 (GGX alpha 1, 4.5e-3, 1.4e-3) and a metal of GGX alpha 1e-6
    // (roughness 1e-3, a delta mirror). No value may be non-finite, and for the narrow lobes
    // the brightest floor pixel must be one whose mirror ray (traced here by hand from the
    // pixel centre) meets the light, or next to one.
    scene::Material mirror = lambert(Color(1, 1, 1));
    mirror.pbr.metallic = 1;
    mirror.pbr.roughness = 1e-3;
    struct Variant {
        const char* name;
        scene::Material m;
        bool narrow;
    };
    const Variant variants[] = {{"phong_size 0", pov_phong(0), false},
                                {"phong_size 1e5", pov_phong(1e5), true},
                                {"phong_size 1e6", pov_phong(1e6), true},
                                {"ggx alpha 1e-6", mirror, true}};
    const Vec3 light_at(0.2, 1.5, 3);
    const double light_r = 0.3;
    for (const Variant& v : variants) {
        scene::Scene s;
        s.camera.location = Vec3(0, 1, -3);
        s.background = scene::ColorFT(Color(0, 0, 0));
        s.materials.push_back(v.m);
        scene::Material emitter = lambert(Color(0, 0, 0));
        emitter.pbr.emission = Color(20, 20, 20);
        emitter.pbr.emission_strength = 1;
        s.materials.push_back(emitter);
        scene::Object floor;
        floor.shape = scene::Plane{Vec3(0, 1, 0), 0};
        floor.material = 0;
        s.objects.push_back(floor);
        scene::Object light;
        light.shape = scene::Sphere{light_at, light_r};
        light.material = 1;
        s.objects.push_back(light);
        const int w = 48, h = 36;
        RenderOptions o = path_options(w, h, 64);
        o.max_depth = 4;
        Diagnostics diag;
        const RenderResult r = render(s, o, diag);
        long nonfinite = 0;
        for (float f : r.image.rgba) nonfinite += std::isfinite(f) ? 0 : 1;
        EXPECT_EQ(nonfinite, 0) << v.name;
        EXPECT_EQ(r.nonfinite_paths, 0u) << v.name;
        // The brightest floor pixel, and the pixels whose centre's mirror ray hits the light.
        const Camera cam(s.camera, w, h);
        double best = -1, floor_sum = 0;
        int bx = -1, by = -1, n_mirror = 0, best_dist = 1 << 20;
        std::vector<std::pair<int, int>> mirror_pixels;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const Ray ray = *cam.generate(x, y);
                if (!(ray.dir.y < 0)) continue;
                const double t = -ray.origin.y / ray.dir.y;
                const Vec3 p = ray.origin + ray.dir * t;
                const Vec3 d(ray.dir.x, -ray.dir.y, ray.dir.z);
                const Vec3 oc = p - light_at;
                const double b = dot(oc, d), c = dot(oc, oc) - light_r * light_r;
                if (b < 0 && b * b - c >= 0) mirror_pixels.emplace_back(x, y);
                const double val = r.image.pixel(x, y)[1];
                floor_sum += val;
                if (val > best) {
                    best = val;
                    bx = x;
                    by = y;
                }
            }
        n_mirror = static_cast<int>(mirror_pixels.size());
        for (const auto& [mx, my] : mirror_pixels)
            best_dist = std::min(best_dist, std::max(std::abs(mx - bx), std::abs(my - by)));
        std::printf("case 14 %-15s: non-finite %ld, brightest floor pixel %.3g at (%d, %d), "
                    "%d mirror pixels, distance %d\n",
                    v.name, nonfinite, best, bx, by, n_mirror, best_dist);
        EXPECT_GT(floor_sum, 0.0) << v.name;
        ASSERT_GT(n_mirror, 0);
        if (v.narrow) {
            EXPECT_LE(best_dist, 1) << v.name;
        }
    }
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
