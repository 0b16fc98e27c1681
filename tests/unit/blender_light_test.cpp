// blender_light: the parser's block and its errors, and Cycles 3.4's light units checked
// against closed forms. A Lambert plane of albedo a under
// - a point light of power P at height h (radius r): radiance a P / (4 pi^2 (h^2 + r^2))
//   (the disc of radiance P / (4 pi pi r^2) facing the point gives E = P / (4 pi (h^2 + r^2)));
// - a sun of strength S (angle 0): a S / pi; with angle A, a S / pi times the mean cosine over
//   the disc of radius R = tan(A/2) at unit distance, 2 (sqrt(1 + R^2) - 1) / R^2;
// - an area light of power P and area A facing it: radiance P / (4 A), so a P / (4 A) F with
//   F the form factor (pi F the projected solid angle); an infinite one gives a P / (4 A)
//   whatever its spread (the spread is normalised).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/log.h"
#include "render/lights/blender_lights.h"
#include "render/lights/light.h"
#include "render/render.h"
#include "unit/path_test_util.h"
#include "unit/pov_test_util.h"

namespace glint {
namespace {

using pov::testing::error_of;
using pov::testing::parse;
using render::CyclesLight;
using render::Sample2;
using scene::BlenderLightType;

// ---------------------------------------------------------------- parsing

TEST(BlenderLightParse, ReadsEveryItem) {
    const scene::Scene s = parse(
        "blender_light { spot location <1, 2, 3> direction <0, -2, 0> color rgb <1, 0.5, 0.25>\n"
        "  power 40 radius 0.1 spot_size 60 spot_blend 0.3 visible_camera on }\n"
        "blender_light { area location <0, 3, 0> direction <0, -1, 0> shape ellipse\n"
        "  size <2, 1> axis_x <2, 0, 0> axis_y <0, 0, 1> spread 90 power 5 }\n"
        "blender_light { sun direction <0, -1, 1> angle 0.5 power 3 }\n"
        "blender_light { point }\n");
    ASSERT_EQ(s.lights.size(), 4u);
    const scene::Light& spot = s.lights[0];
    ASSERT_TRUE(spot.blender);
    EXPECT_EQ(spot.blender->type, BlenderLightType::Spot);
    EXPECT_EQ(spot.location, Vec3(1, 2, 3));
    EXPECT_EQ(spot.blender->direction, Vec3(0, -1, 0));  // normalised
    EXPECT_EQ(spot.color, Color(1, 0.5, 0.25));
    EXPECT_EQ(spot.blender->power, 40);
    EXPECT_EQ(spot.blender->radius, 0.1);
    EXPECT_EQ(spot.blender->spot_size, 60);
    EXPECT_EQ(spot.blender->spot_blend, 0.3);
    EXPECT_TRUE(spot.blender->visible_camera);
    const scene::BlenderLight& area = *s.lights[1].blender;
    EXPECT_EQ(area.type, BlenderLightType::Area);
    EXPECT_TRUE(area.ellipse);
    EXPECT_EQ(area.size_x, 2);
    EXPECT_EQ(area.size_y, 1);
    EXPECT_EQ(area.axis_x, Vec3(1, 0, 0));
    EXPECT_EQ(area.spread, 90);
    EXPECT_FALSE(area.visible_camera);
    const scene::BlenderLight& sun = *s.lights[2].blender;
    EXPECT_EQ(sun.type, BlenderLightType::Sun);
    EXPECT_NEAR(sun.direction.z, std::sqrt(0.5), 1e-15);
    EXPECT_EQ(sun.angle, 0.5);
    // Blender's defaults.
    const scene::BlenderLight& point = *s.lights[3].blender;
    EXPECT_EQ(point.power, 10);
    EXPECT_EQ(point.radius, 0.25);
    EXPECT_EQ(s.lights[3].color, Color(1, 1, 1));
}

TEST(BlenderLightParse, SinglePrecisionDegreesAreClamped) {
    const scene::Scene s = parse("blender_light { area spread 180.000005 }");
    EXPECT_EQ(s.lights[0].blender->spread, 180);
}

TEST(BlenderLightParse, ErrorsNameThePlace) {
    EXPECT_EQ(error_of("blender_light {\n  point power -3 }"),
              "2:9: blender_light power must not be negative, got -3");
    EXPECT_EQ(error_of("blender_light { spot radius -0.5 }"),
              "1:22: blender_light radius must not be negative, got -0.5");
    EXPECT_EQ(error_of("blender_light { spot spot_size 0 }"),
              "1:22: blender_light spot_size must be in (0, 180], got 0");
    EXPECT_EQ(error_of("blender_light { spot spot_blend 1.5 }"),
              "1:22: blender_light spot_blend must be in [0, 1], got 1.5");
    EXPECT_EQ(error_of("blender_light { sun angle 200 }"),
              "1:21: blender_light angle must be in [0, 180], got 200");
    EXPECT_EQ(error_of("blender_light { area size <1, 0> }"),
              "1:22: blender_light size must be positive, got <1, 0>");
    EXPECT_EQ(error_of("blender_light { area direction <0, 0, 0> }"),
              "1:22: blender_light direction must be a non-zero vector");
    EXPECT_EQ(error_of("blender_light { point angle 3 }"),
              "1:23: blender_light: 'angle' does not apply to a point light (only to: sun)");
    EXPECT_EQ(error_of("blender_light { sun location <0, 1, 0> }"),
              "1:21: blender_light: 'location' does not apply to a sun light (only to: point "
              "spot area)");
    EXPECT_EQ(error_of("blender_light { point power 1 power 2 }"),
              "1:31: blender_light: 'power' given twice");
    EXPECT_EQ(error_of("blender_light { lamp }"),
              "1:17: blender_light: expected the light type first (point, spot, sun or area), "
              "got 'lamp'");
    EXPECT_NE(error_of("blender_light { point brightness 3 }")
                  .find("1:23: expected a blender_light item (location"),
              std::string::npos);
    EXPECT_EQ(error_of("blender_light { area shape square }"),
              "1:28: blender_light shape must be rectangle or ellipse, got 'square'");
    EXPECT_EQ(error_of("blender_light { area color rgb <1, -1, 1> }"),
              "1:22: blender_light color must be finite and not negative");
    EXPECT_EQ(error_of("blender_light { area axis_x <1, 0, 0> axis_y <2, 0, 0> }"),
              "1:1: blender_light area: axis_x and axis_y must not be parallel");
}

// ---------------------------------------------------------------- the lights themselves

scene::Light make_light(BlenderLightType type, Vec3 location, double power) {
    scene::Light l;
    l.location = location;
    scene::BlenderLight b;
    b.type = type;
    b.power = power;
    b.radius = 0;
    l.blender = b;
    return l;
}

// The irradiance at p (normal n) from light sampling, n samples of a stratified grid.
double irradiance(const CyclesLight& c, const Vec3& p, const Vec3& n, int k = 64) {
    double sum = 0;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) {
            CyclesLight::Sample s;
            if (!c.sample(p, Sample2{(i + 0.5) / k, (j + 0.5) / k}, &s)) continue;
            sum += s.value.g * std::max(0.0, dot(s.wi, n));
        }
    return sum / (k * k);
}

// The irradiance from the rectangle [0,a] x [0,b] of unit radiance at height h, at the point
// below its corner (parallel planes): pi times the form factor.
double corner_rect_projected(double a, double b, double h) {
    const double x = a / h, y = b / h;
    const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
    return 0.5 * (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy));
}

TEST(BlenderLight, PointLightIrradianceIsPowerOverFourPiSquaredDistance) {
    const double P = 100, h = 2;
    scene::Light l = make_light(BlenderLightType::Point, Vec3(0, h, 0), P);
    EXPECT_NEAR(irradiance(CyclesLight(l), Vec3(0, 0, 0), Vec3(0, 1, 0)),
                P / (4 * kPi * h * h), 1e-12);
    l.blender->radius = 0.5;
    const double r = 0.5;
    EXPECT_NEAR(irradiance(CyclesLight(l), Vec3(0, 0, 0), Vec3(0, 1, 0)),
                P / (4 * kPi * (h * h + r * r)), 1e-4 * P / (4 * kPi * h * h));
}

TEST(BlenderLight, SpotAttenuationIsCosineTimesSmoothstep) {
    // Cycles 3.4: attenuation = cos(angle to the axis), times smoothstep(t / smooth) inside
    // the band t = cos - cos(size / 2) < smooth = (1 - cos(size / 2)) * blend.
    scene::Light l = make_light(BlenderLightType::Spot, Vec3(0, 0, 0), 50);
    l.blender->direction = Vec3(0, -1, 0);
    l.blender->spot_size = 60;
    l.blender->spot_blend = 0.5;
    const CyclesLight c(l);
    const double cos_edge = std::cos(kPi / 6), smooth = (1 - cos_edge) * 0.5;
    for (double deg : {0.0, 10.0, 20.0, 27.0, 29.5, 31.0}) {
        const double th = deg * kPi / 180;
        const Vec3 p(2 * std::sin(th), -2 * std::cos(th), 0);
        CyclesLight::Sample s;
        const bool lit = c.sample(p, Sample2{0.5, 0.5}, &s);
        const double cs = std::cos(th);
        double att = cs > cos_edge ? cs : 0.0;
        const double t = cs - cos_edge;
        if (att > 0 && t < smooth) att *= (t / smooth) * (t / smooth) * (3 - 2 * t / smooth);
        EXPECT_EQ(lit, att > 0) << deg;
        if (lit) {
            EXPECT_NEAR(s.value.r, 50 / (4 * kPi * 4) * att, 1e-12) << deg;
            EXPECT_EQ(s.pdf, 0.0);  // radius 0: a delta light, no MIS
        }
    }
}

TEST(BlenderLight, SunIrradianceIsStrength) {
    scene::Light l = make_light(BlenderLightType::Sun, Vec3(0, 0, 0), 3);
    l.blender->direction = Vec3(0, -1, 0);
    l.blender->angle = 0;
    EXPECT_NEAR(irradiance(CyclesLight(l), Vec3(0, 0, 0), Vec3(0, 1, 0), 4), 3.0, 1e-12);
    l.blender->angle = 10;
    const double R = std::tan(5 * kPi / 180);
    EXPECT_NEAR(irradiance(CyclesLight(l), Vec3(0, 0, 0), Vec3(0, 1, 0)),
                3.0 * 2 * (std::sqrt(1 + R * R) - 1) / (R * R), 1e-5);
}

TEST(BlenderLight, AreaLightRadianceIsPowerOverFourArea) {
    const double P = 40, h = 1;
    scene::Light l = make_light(BlenderLightType::Area, Vec3(0, h, 0), P);
    l.blender->direction = Vec3(0, -1, 0);
    l.blender->axis_x = Vec3(1, 0, 0);
    l.blender->axis_y = Vec3(0, 0, 1);
    l.blender->size_x = 1;
    l.blender->size_y = 0.6;
    // Rectangle: four corner rectangles around the foot point.
    const double L = P / (4 * 0.6);
    const double rect = L * 4 * corner_rect_projected(0.5, 0.3, h);
    EXPECT_NEAR(irradiance(CyclesLight(l), Vec3(0, 0, 0), Vec3(0, 1, 0)), rect, 1e-3 * rect);
    // Disk of radius R: E = pi L R^2 / (h^2 + R^2).
    l.blender->ellipse = true;
    l.blender->size_y = 1;
    const double R = 0.5, Ld = P / (4 * kPi * R * R);
    const double disk = kPi * Ld * R * R / (h * h + R * R);
    EXPECT_NEAR(irradiance(CyclesLight(l), Vec3(0, 0, 0), Vec3(0, 1, 0), 256), disk,
                2e-3 * disk);
    // One-sided: nothing behind it.
    CyclesLight::Sample s;
    EXPECT_FALSE(CyclesLight(l).sample(Vec3(0, 2, 0), Sample2{0.3, 0.3}, &s));
}

TEST(BlenderLight, SpreadIsNormalisedOverTheHemisphere) {
    // An area light much larger than its height lights the point below with E = pi L,
    // whatever the spread (Cycles normalises the soft-box attenuation).
    const double size = 400, L = 1;
    scene::Light l = make_light(BlenderLightType::Area, Vec3(0, 1, 0), 4 * size * size * L);
    l.blender->direction = Vec3(0, -1, 0);
    l.blender->size_x = l.blender->size_y = size;
    for (double spread : {180.0, 120.0, 60.0, 20.0}) {
        l.blender->spread = spread;
        EXPECT_NEAR(irradiance(CyclesLight(l), Vec3(0, 0, 0), Vec3(0, 1, 0), 256), kPi * L,
                    3e-3 * kPi)
            << spread;
    }
}

TEST(BlenderLight, SphericalRectangleSolidAngle) {
    // A square of side s seen on its axis from distance h: 4 asin((s/2)^2 / ((s/2)^2 + h^2)).
    const double s = 1.2, h = 0.7;
    const double want = 4 * std::asin((s * s / 4) / (s * s / 4 + h * h));
    EXPECT_NEAR(render::spherical_rectangle(Vec3(0, 0, 0), Vec3(-0.6, h, -0.6), Vec3(s, 0, 0),
                                            Vec3(0, 0, s), Sample2{}, nullptr),
                want, 1e-12);
    // Samples land on the rectangle.
    Vec3 q;
    render::spherical_rectangle(Vec3(0.3, 0, 0.1), Vec3(-0.6, h, -0.6), Vec3(s, 0, 0),
                                Vec3(0, 0, s), Sample2{0.9, 0.2}, &q);
    EXPECT_NEAR(q.y, h, 1e-12);
    EXPECT_LE(std::fabs(q.x), 0.6 + 1e-12);
    EXPECT_LE(std::fabs(q.z), 0.6 + 1e-12);
}

TEST(BlenderLight, HitsAgreeWithSamplesForMis) {
    // For every light BSDF rays can hit, a ray along a light sample meets the light at the
    // sample, sees radiance = value * pdf, and gets the same pdf (MIS needs both the same).
    std::vector<scene::Light> lights;
    scene::Light point = make_light(BlenderLightType::Point, Vec3(0.2, 2, 0.1), 30);
    point.blender->radius = 0.4;
    lights.push_back(point);
    scene::Light spot = make_light(BlenderLightType::Spot, Vec3(0.5, 2, 0), 30);
    spot.blender->radius = 0.3;
    spot.blender->direction = Vec3(-0.2, -1, 0);
    spot.blender->spot_size = 70;
    lights.push_back(spot);
    scene::Light sun = make_light(BlenderLightType::Sun, Vec3(0, 0, 0), 2);
    sun.blender->direction = Vec3(0.3, -1, 0.2);
    sun.blender->angle = 8;
    lights.push_back(sun);
    scene::Light area = make_light(BlenderLightType::Area, Vec3(0.3, 1.5, -0.2), 20);
    area.blender->direction = Vec3(0, -1, 0.3);
    area.blender->axis_x = Vec3(1, 0, 0);
    area.blender->axis_y = normalize(cross(Vec3(0, -1, 0.3), Vec3(1, 0, 0)));
    area.blender->size_x = 1.5;
    area.blender->size_y = 0.7;
    lights.push_back(area);
    area.blender->spread = 50;
    lights.push_back(area);
    area.blender->ellipse = true;
    lights.push_back(area);
    const Vec3 p(0.1, 0, 0.05);
    for (size_t i = 0; i < lights.size(); ++i) {
        const CyclesLight c(lights[i]);
        ASSERT_TRUE(c.visible()) << i;
        int tried = 0;
        for (int k = 0; k < 50; ++k) {
            CyclesLight::Sample s;
            if (!c.sample(p, Sample2{(k % 7 + 0.5) / 7, (k / 7 + 0.5) / 8}, &s)) continue;
            ++tried;
            double t, pdf;
            Color le;
            const double tmax = std::isinf(s.dist) ? kInfinity : s.dist * 1.001;
            ASSERT_TRUE(c.intersect(p, s.wi, 0, tmax, &t, &le, &pdf)) << i << " " << k;
            if (!std::isinf(s.dist)) {
                EXPECT_NEAR(t, s.dist, 1e-9 * s.dist) << i;
            }
            EXPECT_NEAR(pdf, s.pdf, 1e-7 * s.pdf) << i << " " << k;
            EXPECT_NEAR(le.g, s.value.g * s.pdf, 1e-7 * le.g) << i << " " << k;
        }
        EXPECT_GT(tried, 20) << i;
    }
    // Points and angle-0 suns are not hit.
    EXPECT_FALSE(CyclesLight(make_light(BlenderLightType::Point, Vec3(0, 1, 0), 1)).visible());
}

TEST(BlenderLight, WhittedColorIsIrradianceOverPi) {
    scene::Light l = make_light(BlenderLightType::Point, Vec3(0, 2, 0), 100);
    Color c;
    ASSERT_TRUE(render::whitted_blender_color(render::whitted_light(l), Vec3(0, 0, 0), &c));
    EXPECT_NEAR(c.r, 100 / (4 * kPi * kPi * 4), 1e-12);
    scene::Light area = make_light(BlenderLightType::Area, Vec3(0, 2, 0), 100);
    area.blender->direction = Vec3(0, -1, 0);
    const scene::Light w = render::whitted_light(area);
    ASSERT_TRUE(w.area);  // soft shadows from a grid over the rectangle
    ASSERT_TRUE(render::whitted_blender_color(w, Vec3(0, 0, 0), &c));
    EXPECT_NEAR(c.r, 0.25 * 100 / (kPi * 4), 1e-12);  // intensity P/4 towards the normal
    EXPECT_FALSE(render::whitted_blender_color(w, Vec3(0, 3, 0), &c));  // behind it
    // The sun: a parallel light whose grid's edge shines from angle / 2 off its direction.
    scene::Light sun = make_light(BlenderLightType::Sun, Vec3(0, 0, 0), 2);
    sun.blender->direction = Vec3(0, -1, 0);
    sun.blender->angle = 10;
    const scene::Light ws = render::whitted_light(sun);
    ASSERT_TRUE(ws.parallel);
    ASSERT_TRUE(ws.area);
    const render::PreparedLight pl(ws);
    Vec3 dir;
    double depth;
    pl.white_ray(Vec3(0.5, 0, 0.2), Vec3(0, 0, 0), &dir, &depth);
    EXPECT_NEAR(dir.y, 1.0, 1e-12);
    EXPECT_GT(depth, 1e6);  // shadow rays reach past any scene
    pl.white_ray(Vec3(0.5, 0, 0.2), ws.area->axis1 * 0.5, &dir, &depth);
    EXPECT_NEAR(std::acos(dir.y) * 180 / kPi, 5.0, 1e-6);
}

// ---------------------------------------------------------------- rendered

// A Lambert plane y = 0 of albedo 0.5 seen straight down through a very narrow camera (the
// pixels all see about the origin), lit by `light`; the mean of the image.
double rendered_radiance(const scene::Light& light, int spp = 64, bool path = true) {
    scene::Scene s;
    s.camera.location = Vec3(0, 6, 0);
    s.camera.direction = Vec3(0, -1, 0);
    s.camera.up = Vec3(0, 0, 1e-4);
    s.camera.right = Vec3(1e-4, 0, 0);
    s.materials.push_back(render::path_test::lambert(Color(0.5, 0.5, 0.5)));
    scene::Object plane;
    plane.shape = scene::Plane{Vec3(0, 1, 0), 0};
    plane.material = 0;
    s.objects.push_back(plane);
    s.lights.push_back(light);
    Diagnostics diag;
    render::RenderOptions o = render::path_test::path_options(4, 4, spp, 4);
    if (!path) o.integrator = render::IntegratorKind::Whitted;
    const render::RenderResult r = render::render(s, o, diag);
    double sum = 0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) sum += r.image.pixel(x, y)[1];
    return sum / 16;
}

TEST(BlenderLightRender, DiffusePlaneUnderPointLight) {
    // a P / (4 pi^2 h^2): albedo 0.5, 100 W, 2 m.
    scene::Light l = make_light(BlenderLightType::Point, Vec3(0, 2, 0), 100);
    EXPECT_NEAR(rendered_radiance(l), 0.5 * 100 / (4 * kPi * kPi * 4), 1e-6);
    l.blender->radius = 0.5;
    const double want = 0.5 * 100 / (4 * kPi * kPi * (4 + 0.25));
    EXPECT_NEAR(rendered_radiance(l), want, 3e-3 * want);
}

TEST(BlenderLightRender, DiffusePlaneUnderSunAndArea) {
    scene::Light sun = make_light(BlenderLightType::Sun, Vec3(0, 0, 0), 3);
    sun.blender->direction = Vec3(0, -1, 0);
    sun.blender->angle = 0;
    EXPECT_NEAR(rendered_radiance(sun), 0.5 * 3 / kPi, 1e-6);
    scene::Light area = make_light(BlenderLightType::Area, Vec3(0, 1, 0), 40);
    area.blender->direction = Vec3(0, -1, 0);
    area.blender->size_x = area.blender->size_y = 1;
    const double want = 0.5 * 10 * 4 * corner_rect_projected(0.5, 0.5, 1) / kPi;
    EXPECT_NEAR(rendered_radiance(area), want, 3e-3 * want);
}

TEST(BlenderLightRender, CameraSeesLightsOnlyWithVisibleCamera) {
    // The camera looks down through a square area light facing it (radiance P / (4 A)) at a
    // black plane: the light shows only with visible_camera; from behind, never.
    scene::Light area = make_light(BlenderLightType::Area, Vec3(0, 3, 0), 40);
    area.blender->direction = Vec3(0, 1, 0);  // faces the camera above it
    area.blender->size_x = area.blender->size_y = 1;
    scene::Scene s;
    s.camera.location = Vec3(0, 6, 0);
    s.camera.direction = Vec3(0, -1, 0);
    s.camera.up = Vec3(0, 0, 1e-4);
    s.camera.right = Vec3(1e-4, 0, 0);
    s.materials.push_back(render::path_test::lambert(Color(0, 0, 0)));
    scene::Object plane;
    plane.shape = scene::Plane{Vec3(0, 1, 0), 0};
    plane.material = 0;
    s.objects.push_back(plane);
    auto pixel = [&](const scene::Light& l) {
        s.lights = {l};
        Diagnostics diag;
        return render::render(s, render::path_test::path_options(2, 2, 4, 4), diag)
            .image.pixel(0, 0)[0];
    };
    EXPECT_EQ(pixel(area), 0.0f);
    area.blender->visible_camera = true;
    EXPECT_NEAR(pixel(area), 40 / 4.0, 1e-5);
    area.blender->direction = Vec3(0, -1, 0);  // facing away: one-sided
    EXPECT_EQ(pixel(area), 0.0f);
}

TEST(BlenderLightRender, WhittedMatchesThePathTracerForAPointLight) {
    // The lambert() material's texture keeps POV-Ray's default finish in Whitted (ambient
    // 0.1, diffuse 0.6 of the default pigment): compare against the same light as a POV-Ray
    // light of color E / pi instead.
    scene::Light l = make_light(BlenderLightType::Point, Vec3(0, 2, 0), 100);
    scene::Light pov;
    pov.location = Vec3(0, 2, 0);
    pov.color = Color(1, 1, 1) * (100 / (4 * kPi * kPi * 4));
    EXPECT_NEAR(rendered_radiance(l, 1, false), rendered_radiance(pov, 1, false), 1e-6);
}

}  // namespace
}  // namespace glint
