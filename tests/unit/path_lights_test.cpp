// The path tracer's light sampling against closed forms: a Lambert plane under a sphere light
// and a disc light (on-axis irradiance), HDR environments (a constant image against the
// uniform background, a small bright sun: variance against uniform sampling and the mean
// against the image's own quadrature), the environment table's pdf (integral, histogram),
// and the orientation of a spherical image map against Blender's world texture (measured).
// (The light tree: path_light_tree_test.cpp.)
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <unistd.h>

#include <vector>

#include "core/log.h"
#include "render/lights/environment.h"
#include "render/lights/path_lights.h"
#include "render/render.h"
#include "render/textures/image_texture.h"
#include "render/textures/pigment.h"
#include "unit/path_test_util.h"

namespace glint::render {
namespace {

using path_test::emitter;
using path_test::lambert;

RenderOptions path_options(int w, int h, int spp) {
    return path_test::path_options(w, h, spp, 8);
}

// A camera at `from` looking at `at` with a field of view of about 1e-3 radians.
void aim(scene::Scene* s, const Vec3& from, const Vec3& at, double spread = 1e-3) {
    const Vec3 d = normalize(at - from);
    const Vec3 a = normalize(std::fabs(d.y) > 0.9 ? cross(d, Vec3(1, 0, 0)) : cross(d, Vec3(0, 1, 0)));
    const Vec3 b = cross(a, d);
    s->camera.location = from;
    s->camera.direction = d;
    s->camera.right = a * spread;
    s->camera.up = b * spread;
}

struct Stats {
    double mean = 0, stderr_ = 0;
};

// Mean of the red channel over the pixels and its standard error.
Stats image_stats(const Image& img) {
    double s = 0, s2 = 0;
    size_t n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const double v = img.pixel(x, y)[0];
            s += v;
            s2 += v * v;
            ++n;
        }
    Stats st;
    st.mean = s / n;
    st.stderr_ = std::sqrt(std::max(0.0, s2 / n - st.mean * st.mean) / n);
    return st;
}

// A Lambert plane y = 0 of albedo 0.5 (material 0); the camera looks at the origin from the
// side, so every pixel sees the plane within ~3e-3 of the origin.
scene::Scene lit_plane() {
    scene::Scene s;
    s.materials.push_back(lambert(Color(0.5, 0.5, 0.5)));
    scene::Object plane;
    plane.shape = scene::Plane{Vec3(0, 1, 0), 0};
    plane.material = 0;
    s.objects.push_back(plane);
    aim(&s, Vec3(0, 1, -3), Vec3(0, 0, 0));
    return s;
}

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("glint_path_lights_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

void write_exr(const std::string& path, int w, int h, const std::vector<float>& rgb) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::FLOAT);
    ASSERT_TRUE(out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgb.data()));
    out->close();
}

// sky_sphere { pigment { image_map { exr "path" map_type 1 } } rotate <0, rot_y, 0> }
void set_sky_image(scene::Scene* s, const std::string& path, double rot_y = 0) {
    scene::Pigment p;
    p.kind = scene::PatternKind::ImageMap;
    p.params.image.file = path;
    p.params.image.resolved_path = path;
    p.params.image.type = "exr";
    p.params.image.map_type = 1;
    s->sky_sphere.emplace();
    s->sky_sphere->pigments.push_back(p);
    if (rot_y != 0) s->sky_sphere->transform = Transform::rotate_xyz_degrees(Vec3(0, rot_y, 0));
}

// ---------------------------------------------------------------- sphere and disc lights

// On the axis of a sphere of radius r at distance d: E = pi L (r/d)^2; a Lambert surface of
// albedo 0.5 shows 0.5 E / pi.
TEST(PathLights, SphereLightMatchesAnalyticIrradiance) {
    const double le = 10, r = 0.5, d = 2;
    const double expected = 0.5 * le * r * r / (d * d);
    struct Case {
        const char* name;
        Transform x;
        scene::Sphere sphere;
    };
    const Case cases[] = {
        {"sphere", Transform(), scene::Sphere{Vec3(0, d, 0), r}},
        // A uniformly scaled unit sphere: still cone-sampled.
        {"scaled", Transform::scale(Vec3(r, r, r)).then(Transform::translate(Vec3(0, d, 0))),
         scene::Sphere{Vec3(0, 0, 0), 1}},
        // Non-uniform scale: the area-sampling fallback (an ellipsoid all but a sphere).
        {"ellipsoid",
         Transform::scale(Vec3(r, r * (1 + 1e-7), r)).then(Transform::translate(Vec3(0, d, 0))),
         scene::Sphere{Vec3(0, 0, 0), 1}},
    };
    for (const Case& c : cases) {
        scene::Scene s = lit_plane();
        s.materials.push_back(emitter(le));
        scene::Object o;
        o.shape = c.sphere;
        o.transform = c.x;
        o.material = 1;
        s.objects.push_back(o);
        PathLights lights(s, {Color(), Color(le, le, le)});
        EXPECT_EQ(lights.shape_emitters(), 1);
        Diagnostics diag;
        const RenderResult res = render(s, path_options(8, 8, 256), diag);
        const Stats st = image_stats(res.image);
        std::printf("sphere light (%s): mean %.6f, expected %.6f, stderr %.2g\n", c.name,
                    st.mean, expected, st.stderr_);
        // Tolerance: 4 standard errors plus 2e-4 relative for the ~3e-3 patch the pixels see.
        EXPECT_NEAR(st.mean, expected, 4 * st.stderr_ + 2e-4 * expected) << c.name;
        EXPECT_NEAR(st.mean, expected, 0.01 * expected) << c.name;
        EXPECT_EQ(res.nonfinite_paths, 0u);
    }
}

// A disc of radius r facing the plane from height h: E = pi L r^2 / (r^2 + h^2) on the axis.
TEST(PathLights, DiscLightMatchesAnalyticIrradiance) {
    const double le = 4, r = 0.5, h = 1;
    const double expected = 0.5 * le * r * r / (r * r + h * h);
    scene::Scene s = lit_plane();
    aim(&s, Vec3(0, 0.5, -3), Vec3(0, 0, 0));
    s.materials.push_back(emitter(le));
    scene::Object o;
    o.shape = scene::Disc{Vec3(0, h, 0), Vec3(0, -1, 0), r, 0};
    o.material = 1;
    s.objects.push_back(o);
    Diagnostics diag;
    const RenderResult res = render(s, path_options(8, 8, 256), diag);
    const Stats st = image_stats(res.image);
    std::printf("disc light: mean %.6f, expected %.6f, stderr %.2g\n", st.mean, expected,
                st.stderr_);
    EXPECT_NEAR(st.mean, expected, 4 * st.stderr_ + 2e-4 * expected);
    EXPECT_NEAR(st.mean, expected, 0.01 * expected);
}

// The same disc inside a union with transforms at both levels (obj_file's OBJ parts sit in a
// union): found through the tree and light-sampled; a union that also holds an emitting box
// is left to BSDF sampling as a whole.
TEST(PathLights, EmittersInsideUnionsAreSampled) {
    const double le = 4, r = 0.5, h = 1;
    const double expected = 0.5 * le * r * r / (r * r + h * h);
    scene::Scene s = lit_plane();
    aim(&s, Vec3(0, 0.5, -3), Vec3(0, 0, 0));
    s.materials.push_back(emitter(le));
    scene::Object disc;
    disc.shape = scene::Disc{Vec3(0, 0, 0), Vec3(0, -1, 0), r, 0};
    disc.transform = Transform::translate(Vec3(0, 0.25, 0));
    disc.material = -1;  // inherited from the union
    scene::Object u;
    u.shape = scene::Csg{scene::CsgOp::Union, {disc}};
    u.transform = Transform::translate(Vec3(0, h - 0.25, 0));
    u.material = 1;
    s.objects.push_back(u);
    {
        PathLights lights(s, {Color(), Color(le, le, le)});
        EXPECT_TRUE(lights.emitter_object(1));
        EXPECT_EQ(lights.shape_emitters(), 1);
    }
    Diagnostics diag;
    const RenderResult res = render(s, path_options(8, 8, 256), diag);
    const Stats st = image_stats(res.image);
    std::printf("disc light in a union: mean %.6f, expected %.6f, stderr %.2g\n", st.mean,
                expected, st.stderr_);
    EXPECT_NEAR(st.mean, expected, 4 * st.stderr_ + 2e-4 * expected);

    // A second, smaller disc below it in the same union hides the middle of the first with the
    // same radiance, so the irradiance stays pi L r^2 / (r^2 + h^2); hits on the union are
    // matched to the disc they lie on.
    scene::Object low = disc;
    low.shape = scene::Disc{Vec3(0, 0, 0), Vec3(0, 1, 0), 0.2, 0};
    low.transform = Transform::translate(Vec3(0, -0.25, 0));
    std::get<scene::Csg>(s.objects[1].shape).children.push_back(low);
    {
        PathLights lights(s, {Color(), Color(le, le, le)});
        EXPECT_TRUE(lights.emitter_object(1));
        EXPECT_EQ(lights.shape_emitters(), 2);
        const RenderResult two = render(s, path_options(8, 8, 256), diag);
        const Stats st2 = image_stats(two.image);
        std::printf("two discs in a union: mean %.6f, expected %.6f, stderr %.2g\n", st2.mean,
                    expected, st2.stderr_);
        EXPECT_NEAR(st2.mean, expected, 4 * st2.stderr_ + 2e-4 * expected);
    }

    scene::Object box;
    box.shape = scene::Box{Vec3(5, 5, 5), Vec3(6, 6, 6)};
    std::get<scene::Csg>(s.objects[1].shape).children.push_back(box);
    PathLights mixed(s, {Color(), Color(le, le, le)});
    EXPECT_FALSE(mixed.emitter_object(1));
    EXPECT_EQ(mixed.shape_emitters(), 0);
}

// Light sampling and emitter_pdf agree: for a point sampled on a sphere, an ellipsoid, a disc
// with a hole or a triangle, the pdf the BSDF side computes for the same point equals the
// sample's pdf, both with each emitter its own object and with all of them in one union
// (where emitter_pdf must tell from the point which one was hit).
TEST(PathLights, EmitterPdfMatchesSamplePdf) {
    std::vector<scene::Object> parts(4);
    parts[0].shape = scene::Sphere{Vec3(0, 3, 0), 0.7};
    parts[1].shape = scene::Sphere{Vec3(0, 0, 0), 1};
    parts[1].transform =
        Transform::scale(Vec3(0.3, 0.8, 0.5)).then(Transform::translate(Vec3(2, 1, 0)));
    parts[2].shape = scene::Disc{Vec3(0, 0, 0), Vec3(0, 0, 1), 1, 0.25};
    parts[2].transform =
        Transform::scale(Vec3(2, 1, 1)).then(Transform::translate(Vec3(-2, 1, 1)));
    const Vec3 t0(-1, -2, 3), t1(1, -2, 3), t2(0, -1, 4);
    parts[3].shape = scene::Triangle{{t0, t1, t2}};
    const Vec3 tri_n = normalize(cross(t1 - t0, t2 - t0));
    for (const bool in_union : {false, true}) {
        scene::Scene s;
        s.materials.push_back(emitter(1));
        if (in_union) {
            scene::Object u;
            u.shape = scene::Csg{scene::CsgOp::Union, parts};
            u.material = 0;
            s.objects.push_back(u);
        } else {
            for (scene::Object o : parts) {
                o.material = 0;
                s.objects.push_back(o);
            }
        }
        PathLights lights(s, {Color(1, 1, 1)});
        ASSERT_EQ(lights.count(), 1);
        ASSERT_EQ(lights.shape_emitters(), 3);
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> U(0, 1);
        const Vec3 p(0.1, -0.5, 0.2);
        int checked[4] = {0, 0, 0, 0};
        for (int i = 0; i < 4000; ++i) {
            PathLightSample ls;
            if (!lights.sample(0, p, {U(rng), U(rng)}, &ls)) continue;
            const Vec3 q = p + ls.wi * ls.dist;
            // Which part: the one whose surface the point is on.
            int part = 3;
            if (std::fabs(length(q - Vec3(0, 3, 0)) - 0.7) < 1e-9) {
                part = 0;
            } else if (std::fabs(length(parts[1].transform.inverse_point(q)) - 1) < 1e-9) {
                part = 1;
            } else if (std::fabs(parts[2].transform.inverse_point(q).z) < 1e-9) {
                part = 2;
            }
            const int object = in_union ? 0 : part;
            const double pdf = lights.emitter_pdf(object, p, q, tri_n, Color(1, 1, 1));
            EXPECT_NEAR(pdf / ls.pdf, 1.0, 1e-9) << "part " << part << " union " << in_union;
            ++checked[part];
        }
        for (int k = 0; k < 4; ++k) EXPECT_GT(checked[k], 100) << "part " << k;
    }
}

TEST(PathLights, NearTrianglesAreSampledBySolidAngle) {
    // A 2 x 2 emitting square (two triangles) at y = 1 over a point h below its centre: close
    // enough that each triangle is sampled over its spherical triangle (Cycles' rule). Every
    // sample lands on the square, its pdf is what emitter_pdf() gives a BSDF hit there, and
    // the irradiance estimate matches the analytic value with a small error even at h = 0.05,
    // where area sampling's 1/r^2 weights are large.
    const Vec3 c0(-1, 1, -1), c1(1, 1, -1), c2(1, 1, 1), c3(-1, 1, 1);
    scene::Scene s;
    s.materials.push_back(emitter(1));
    scene::Mesh m;
    m.positions = {c0, c1, c2, c3};
    m.faces.push_back({{0, 1, 2}});
    m.faces.push_back({{0, 2, 3}});
    s.meshes.push_back(m);
    scene::Object o;
    o.shape = scene::MeshRef{0};
    o.material = 0;
    s.objects.push_back(o);
    PathLights lights(s, {Color(1, 1, 1)});
    ASSERT_EQ(lights.count(), 1);
    for (const double h : {0.05, 0.5}) {
        const Vec3 p(0, 1 - h, 0);
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> U(0, 1);
        const int n = 20000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; ++i) {
            PathLightSample ls;
            ASSERT_TRUE(lights.sample(0, p, {U(rng), U(rng)}, &ls));
            const Vec3 q = p + ls.wi * ls.dist;
            ASSERT_NEAR(q.y, 1.0, 1e-9);
            ASSERT_LE(std::fabs(q.x), 1 + 1e-9);
            ASSERT_LE(std::fabs(q.z), 1 + 1e-9);
            const double pdf = lights.emitter_pdf(0, p, q, Vec3(0, -1, 0), Color(1, 1, 1));
            ASSERT_NEAR(pdf / ls.pdf, 1.0, 1e-6) << q.x << " " << q.z;
            const double e = ls.value.r * ls.wi.y;  // L cos / pdf, receiver facing up
            sum += e;
            sum2 += e * e;
        }
        const double mean = sum / n;
        const double se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
        // E = pi L F, F of a point below a rectangle's centre: four corner form factors.
        const double x = 1, r = std::sqrt(x * x + h * h);
        const double exact = 4 * 0.5 * (2 * x / r * std::atan(x / r));
        std::printf("square light at h = %g: E = %.6f +- %.2g (analytic %.6f), relative stderr "
                    "%.2g\n", h, mean, se, exact, se / exact);
        EXPECT_NEAR(mean, exact, 4 * se + 1e-9);
        // The same estimate by area sampling of the square, for comparison.
        double a1 = 0, a2 = 0;
        for (int i = 0; i < n; ++i) {
            const Vec3 q(2 * U(rng) - 1, 1, 2 * U(rng) - 1);
            const Vec3 d = q - p;
            const double d2 = length_squared(d), cos = h / std::sqrt(d2);
            const double e = cos * cos / d2 * 4;  // L cos_p cos_l / r^2 / (1 / area)
            a1 += e;
            a2 += e * e;
        }
        const double am = a1 / n;
        const double ase = std::sqrt(std::max(0.0, a2 / n - am * am) / n);
        std::printf("  area sampling: E = %.6f +- %.2g\n", am, ase);
        EXPECT_LT(se, ase);
        if (h < 0.1) {
            EXPECT_LT(se, 0.2 * ase);
        }
    }
}

// ---------------------------------------------------------------- environment

// POV-Ray's spherical map_type 1 and Blender's world Environment Texture: texels Blender
// 3.4.1 Cycles showed along these directions (Blender world, Z up; `alpha`: a Mapping node's
// Z rotation in degrees) for a 64 x 32 image, measured by rendering a 0.001-rad camera
// along each direction with Closest interpolation. Texel (x, y), y counted from the top row.
TEST(PathLights, EnvironmentMatchesBlender) {
    const int w = 64, h = 32;
    std::vector<float> px(static_cast<size_t>(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &px[(static_cast<size_t>(y) * w + x) * 3];
            p[0] = static_cast<float>(x);
            p[1] = static_cast<float>(y);
            p[2] = 1e4f;  // HDR values are read linear and unclamped
        }
    const std::string path = temp_path("probe.exr");
    write_exr(path, w, h, px);
    struct Probe {
        double alpha;
        Vec3 b;
        int x, y;
    };
    const Probe probes[] = {
        {0, {0.925417, 0.163176, 0.342020}, 30, 12},  {0, {-0.150384, 0.852869, -0.5}, 14, 21},
        {0, {-0.936117, -0.340719, 0.087156}, 60, 15}, {0, {0.25, -0.433013, 0.866025}, 42, 5},
        {0, {0.176514, 0.189288, -0.965926}, 23, 29},  {90, {0.925417, 0.163176, 0.342020}, 14, 12},
        {90, {-0.150384, 0.852869, -0.5}, 62, 21},     {90, {-0.936117, -0.340719, 0.087156}, 44, 15},
        {90, {0.25, -0.433013, 0.866025}, 26, 5},      {90, {0.176514, 0.189288, -0.965926}, 7, 29},
    };
    for (const Probe& pr : probes)
        for (const bool obj_file : {true, false}) {
            scene::Scene s;
            Vec3 g;
            if (obj_file) {
                // A POV scene placing the export with obj_file, which mirrors z into POV-Ray's
                // left-handed axes: a Blender direction is (x, z, y); the sky is mirrored in x.
                g = Vec3(pr.b.x, pr.b.z, pr.b.y);
                set_sky_image(&s, path);
                s.sky_sphere->transform = Transform::scale(Vec3(-1, 1, 1))
                                              .then(Transform::rotate_xyz_degrees(
                                                  Vec3(0, pr.alpha, 0)));
            } else {
                // The OBJ file's own coordinates (forward -Z, up Y): (x, z, -y).
                g = Vec3(pr.b.x, pr.b.z, -pr.b.y);
                set_sky_image(&s, path, 180 - pr.alpha);
            }
            aim(&s, Vec3(0, 0, 0), g, 1e-6);
            Diagnostics diag;
            const RenderResult r = render(s, path_options(1, 1, 1), diag);
            const float* c = r.image.pixel(0, 0);
            const std::string what = std::string(obj_file ? "obj_file" : "OBJ") + " alpha " +
                                     std::to_string(pr.alpha) + " dir " + std::to_string(pr.b.x) +
                                     " " + std::to_string(pr.b.y);
            EXPECT_EQ(c[0], pr.x) << what;
            EXPECT_EQ(c[1], pr.y) << what;
            EXPECT_EQ(c[2], 1e4f);
        }
    std::filesystem::remove(path);
}

// A constant environment image renders as the uniform background of that value: a Lambert
// sphere of albedo 0.5 shows 0.5 L, the background L.
TEST(PathLights, ConstantEnvironmentImageMatchesUniformBackground) {
    const double level = 0.75;
    const std::string path = temp_path("constant.exr");
    write_exr(path, 256, 128, std::vector<float>(256 * 128 * 3, static_cast<float>(level)));
    auto scene_with = [&](bool image) {
        scene::Scene s;
        s.materials.push_back(lambert(Color(0.5, 0.5, 0.5)));
        scene::Object o;
        o.shape = scene::Sphere{Vec3(0, 0, 0), 1};
        o.material = 0;
        s.objects.push_back(o);
        aim(&s, Vec3(0, 0, -4), Vec3(0, 0, 0), 0.3);
        if (image)
            set_sky_image(&s, path);
        else
            s.background = scene::ColorFT(Color(level, level, level));
        return s;
    };
    Diagnostics diag;
    const RenderOptions o = path_options(24, 24, 128);
    const RenderResult a = render(scene_with(true), o, diag);
    const RenderResult b = render(scene_with(false), o, diag);
    const Stats sa = image_stats(a.image), sb = image_stats(b.image);
    std::printf("constant environment: image %.6f (stderr %.2g), uniform %.6f (stderr %.2g)\n",
                sa.mean, sa.stderr_, sb.mean, sb.stderr_);
    EXPECT_NEAR(sa.mean, sb.mean, 1e-3);
    EXPECT_EQ(a.nonfinite_paths, 0u);
    std::filesystem::remove(path);
}

// A 256 x 128 sky of 0.5 with a 3 x 3-texel sun of 2e4.
struct SunMap {
    static constexpr int kW = 256, kH = 128;
    static constexpr double kSky = 0.5, kSun = 2e4;
    static bool sun(int x, int y) { return x >= 40 && x < 43 && y >= 30 && y < 33; }
    std::string path;
    SunMap() : path(temp_path("sun.exr")) {
        std::vector<float> px(kW * kH * 3);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                for (int c = 0; c < 3; ++c)
                    px[(y * kW + x) * 3 + c] = static_cast<float>(sun(x, y) ? kSun : kSky);
        write_exr(path, kW, kH, px);
    }
    ~SunMap() { std::filesystem::remove(path); }
    // Irradiance on an upward-facing surface, texel by texel: POV-Ray's map_type 1 puts row y
    // (from the top) between elevations (0.5 - (y + 1) / H) pi and (0.5 - y / H) pi, and each
    // column spans 2 pi / W in azimuth; the integral of cos over the texel is closed-form.
    static double irradiance_up() {
        double e = 0;
        for (int y = 0; y < kH; ++y) {
            const double hi = (0.5 - static_cast<double>(y) / kH) * kPi;
            const double lo = (0.5 - static_cast<double>(y + 1) / kH) * kPi;
            if (lo < 0) break;
            const double band = (std::sin(hi) * std::sin(hi) - std::sin(lo) * std::sin(lo)) / 2;
            for (int x = 0; x < kW; ++x) e += (sun(x, y) ? kSun : kSky) * band * 2 * kPi / kW;
        }
        return e;
    }
};

// The sky's radiance as the integrator computes it (pigment of the sky_sphere, no transform).
struct SkyRadiance {
    scene::Scene scene;
    TextureCache textures{ImageGamma{}};
    std::optional<PigmentEvaluator> pigments;
    explicit SkyRadiance(const std::string& path) {
        set_sky_image(&scene, path);
        textures.preload(scene);
        pigments.emplace(&textures);
    }
    Color operator()(const Vec3& d) const {
        scene::ColorFT c;
        pigments->evaluate(scene.sky_sphere->pigments[0], {d, {}, false}, &c);
        return c.rgb;
    }
};

// Irradiance on an upward-facing point by light sampling alone, through the table and
// through uniform sphere sampling: the same mean, and the table's variance far lower.
TEST(PathLights, SunEnvironmentVarianceFarBelowUniform) {
    SunMap map;
    SkyRadiance sky(map.path);
    const EnvironmentDistribution::Radiance radiance = [&](const Vec3& d) { return sky(d); };
    PathLights table(sky.scene, {}, radiance, &sky.textures);
    PathLights uniform(sky.scene, {});
    ASSERT_EQ(table.count(), 1);
    const double expected = SunMap::irradiance_up();
    const int n = 200000;
    auto estimate = [&](const PathLights& lights, double* mean, double* var) {
        std::mt19937_64 rng(11);
        std::uniform_real_distribution<double> U(0, 1);
        double s = 0, s2 = 0;
        for (int i = 0; i < n; ++i) {
            PathLightSample ls;
            double x = 0;
            if (lights.sample(0, Vec3(0, 0, 0), {U(rng), U(rng)}, &ls) && ls.wi.y > 0)
                x = ls.value.r * sky(ls.wi).r * ls.wi.y;
            s += x;
            s2 += x * x;
        }
        *mean = s / n;
        *var = std::max(0.0, s2 / n - *mean * *mean);
    };
    double mt, vt, mu, vu;
    estimate(table, &mt, &vt);
    estimate(uniform, &mu, &vu);
    const double ratio = vu / vt;
    std::printf("sun sky: E %.5f; table mean %.5f var %.4g; uniform mean %.5f var %.4g; "
                "variance ratio %.0fx\n",
                expected, mt, vt, mu, vu, ratio);
    EXPECT_NEAR(mt, expected, 4 * std::sqrt(vt / n) + 1e-4 * expected);
    EXPECT_NEAR(mu, expected, 4 * std::sqrt(vu / n));
    EXPECT_GE(ratio, 10.0);
}

// The same sky over a Lambert plane, rendered (light sampling and BSDF sampling under MIS):
// 0.5 E / pi.
TEST(PathLights, SunEnvironmentRenderMatchesQuadrature) {
    SunMap map;
    scene::Scene s = lit_plane();
    set_sky_image(&s, map.path);
    Diagnostics diag;
    const RenderResult r = render(s, path_options(8, 8, 128), diag);
    const Stats st = image_stats(r.image);
    const double expected = 0.5 * SunMap::irradiance_up() / kPi;
    std::printf("sun sky over a plane: mean %.5f, expected %.5f, stderr %.2g\n", st.mean,
                expected, st.stderr_);
    EXPECT_NEAR(st.mean, expected, 4 * st.stderr_ + 1e-3 * expected);
    EXPECT_EQ(r.nonfinite_paths, 0u);
}

// The table's pdf integrates to 1 over the sphere, sample() reports the pdf that pdf() gives
// for its direction, and a histogram of samples matches the pdf (chi-square).
TEST(PathLights, EnvironmentPdfIntegratesToOneAndMatchesHistogram) {
    SunMap map;
    SkyRadiance sky(map.path);
    const EnvironmentGrid grid = environment_grid(sky.scene, &sky.textures);
    EXPECT_EQ(grid.width, 256);
    EXPECT_EQ(grid.height, 128);
    const EnvironmentDistribution env([&](const Vec3& d) { return sky(d); }, grid);

    // Integral over the sphere: midpoint rule on a grid 4x finer than the table, with
    // d omega = 2 pi^2 sin(theta) du dv.
    const int nu = grid.width * 4, nv = grid.height * 4;
    double integral = 0;
    for (int i = 0; i < nv; ++i)
        for (int j = 0; j < nu; ++j) {
            const double u = (j + 0.5) / nu, v = (i + 0.5) / nv;
            integral += env.pdf(EnvironmentDistribution::direction(u, v)) * 2 * kPi * kPi *
                        std::sin(kPi * v) / (static_cast<double>(nu) * nv);
        }
    std::printf("environment pdf integral %.9f\n", integral);
    EXPECT_NEAR(integral, 1.0, 1e-6);

    // Histogram over 32 x 16 bins of (u, v) against the pdf's integral over each bin.
    const int bu = 32, bv = 16, n = 400000;
    std::vector<double> expected(bu * bv, 0.0), seen(bu * bv, 0.0);
    for (int i = 0; i < nv; ++i)
        for (int j = 0; j < nu; ++j) {
            const double u = (j + 0.5) / nu, v = (i + 0.5) / nv;
            expected[(i * bv / nv) * bu + j * bu / nu] +=
                env.pdf(EnvironmentDistribution::direction(u, v)) * 2 * kPi * kPi *
                std::sin(kPi * v) / (static_cast<double>(nu) * nv) * n;
        }
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> U(0, 1);
    int mismatched = 0;
    for (int k = 0; k < n; ++k) {
        Vec3 d;
        double pdf;
        ASSERT_TRUE(env.sample({U(rng), U(rng)}, &d, &pdf));
        if (std::fabs(env.pdf(d) / pdf - 1) > 1e-9) ++mismatched;
        double u, v;
        EnvironmentDistribution::coordinates(d, &u, &v);
        seen[std::min(bv - 1, static_cast<int>(v * bv)) * bu +
             std::min(bu - 1, static_cast<int>(u * bu))] += 1;
    }
    // Directions on a cell border may map back to the neighbouring cell.
    EXPECT_LT(mismatched, n / 1000);
    double chi2 = 0, pooled_e = 0, pooled_o = 0;
    int dof = -1;
    for (int b = 0; b < bu * bv; ++b) {
        if (expected[b] < 5) {
            pooled_e += expected[b];
            pooled_o += seen[b];
            continue;
        }
        chi2 += (seen[b] - expected[b]) * (seen[b] - expected[b]) / expected[b];
        ++dof;
    }
    if (pooled_e > 0) {
        chi2 += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e;
        ++dof;
    }
    // Wilson-Hilferty: chi2/dof^(1/3) is about normal; z < 4 is p > 3e-5.
    const double k = dof;
    const double z =
        (std::cbrt(chi2 / k) - (1 - 2 / (9 * k))) / std::sqrt(2 / (9 * k));
    std::printf("environment histogram: chi2 %.1f, dof %d, z %.2f, pdf mismatches %d\n", chi2,
                dof, z, mismatched);
    EXPECT_LT(z, 4.0);
}

}  // namespace
}  // namespace glint::render
