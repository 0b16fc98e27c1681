// VALIDATION.md case 1: the sphere-on-plane scene at scale 1e-4, 1, 1e4 and translated by 1e5
// renders the same image (>= 99.9% of pixels within 1/255), with no shadow acne on the plane.
#include <gtest/gtest.h>

#include <cstdio>

#include "stability_support.h"

namespace glint::stability {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;
constexpr double kMinWithin = 0.999;

// Distance from point c to the segment a-b.
double segment_distance(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a;
    const double t = std::clamp(dot(c - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(a + ab * t - c);
}

// Counts plane pixels that are clearly lit (the shadow ray passes the sphere by more than 2% of
// its radius, and the pixel is not near the sphere's outline) yet come out more than 2% darker
// than the shading POV-Ray's model gives there: pigment * (ambient + diffuse * cos) (reference
// manual 3.6.2.1.1 "Ambient", 3.6.2.1.2 "Diffuse Reflection Items"). Geometry of the S = 1
// scene; the others must look the same.
// Also counts pixels well inside the sphere's shadow (the shadow ray passes within 98% of the
// radius) that come out lit (above 1.5 x the ambient-only shade): a lost shadow. `quantized`:
// the image came from an 8-bit file (POV-Ray's), where one 8-bit step of a dark value is more
// than 2%, so acne there is more than 2/255 below the expected 8-bit value.
struct AcneCount {
    long acne = 0;
    long checked = 0;
    long lost_shadow = 0;
    long shadowed = 0;
};
AcneCount count_acne(const Image& image, const scene::Camera& unit_camera,
                     bool quantized = false) {
    const Vec3 sphere_center{0, 1, 0};
    const double radius = 1.0;
    const Vec3 light{-3, 6, -4};
    const double pigment = 0.8, ambient = 0.1, diffuse = 0.6;
    AcneCount count;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const CameraRay ray = primary_ray(unit_camera, x, y, image.width, image.height);
            if (ray.dir.y >= -1e-3) continue;  // misses the plane or meets it near the horizon
            const double t = -ray.origin.y / ray.dir.y;
            const Vec3 p = ray.origin + ray.dir * t;
            // Not near (or behind) the sphere's outline, and not in or near its shadow.
            if (segment_distance(ray.origin, p, sphere_center) < radius * 1.02) continue;
            const float* px = image.pixel(x, y);
            const double shadow_distance = segment_distance(p, light, sphere_center);
            if (shadow_distance < radius * 0.98) {
                ++count.shadowed;
                if (px[0] > pigment * ambient * 1.5) ++count.lost_shadow;
            }
            if (shadow_distance < radius * 1.02) continue;
            const double cosine = std::max(0.0, normalize(light - p).y);
            const double expected = pigment * (ambient + diffuse * cosine);
            ++count.checked;
            for (int c = 0; c < 3; ++c) {
                const bool dark = quantized
                                      ? to_8bit(px[c]) < to_8bit(static_cast<float>(expected)) - 2
                                      : px[c] < expected * 0.98;
                if (dark) {
                    ++count.acne;
                    break;
                }
            }
        }
    }
    return count;
}

TEST(StabilityScaleInvariance, SameImageAtEveryScaleAndOffset) {
    const scene::Scene unit_scene = load_scene("scale_invariance.pov", "", kWidth, kHeight);
    const Image reference = render_scene(unit_scene, kWidth, kHeight);
    ASSERT_EQ(count_nonfinite(reference), 0);

    const AcneCount unit_acne = count_acne(reference, unit_scene.camera);
    std::printf("case 1 whitted scale 1: acne pixels = %ld of %ld lit plane pixels (bound 0)\n",
                unit_acne.acne, unit_acne.checked);
    EXPECT_GT(unit_acne.checked, kWidth * kHeight / 4);
    EXPECT_EQ(unit_acne.acne, 0);
    EXPECT_GT(unit_acne.shadowed, 1000);
    EXPECT_EQ(unit_acne.lost_shadow, 0);

    struct Variant {
        const char* name;
        const char* prelude;
        bool required;  // VALIDATION.md's cases; the last one is a harder extra, only reported
    };
    const Variant variants[] = {
        {"scale 1e-4", "#declare S = 1e-4;", true},
        {"scale 1e4", "#declare S = 1e4;", true},
        {"translate 1e5", "#declare T = <1e5, 1e5, 1e5>;", true},
        {"scale 1e-4 + translate 1e5", "#declare S = 1e-4; #declare T = <1e5, 1e5, 1e5>;", false},
        {"translate 1e8", "#declare T = <1e8, 1e8, 1e8>;", false},
    };
    for (const Variant& v : variants) {
        const Image image = render_file("scale_invariance.pov", v.prelude, kWidth, kHeight);
        ASSERT_EQ(image.width, kWidth);
        ASSERT_EQ(image.height, kHeight);
        EXPECT_EQ(count_nonfinite(image), 0) << v.name;
        const double within = fraction_within(image, reference, 1);
        const AcneCount acne = count_acne(image, unit_scene.camera);
        std::printf(
            "case 1 whitted %s: within 1/255 of scale 1 = %.5f (bound >= %.3f); acne "
            "pixels = %ld of %ld (bound 0); lost shadow pixels = %ld of %ld (bound 0)\n",
            v.name, within, kMinWithin, acne.acne, acne.checked, acne.lost_shadow, acne.shadowed);
        if (v.required) {
            EXPECT_GE(within, kMinWithin) << v.name;
            EXPECT_EQ(acne.acne, 0) << v.name;
            EXPECT_EQ(acne.lost_shadow, 0) << v.name;
        }
    }
}

TEST(StabilityScaleInvariance, PathTracerSameImageAtEveryScaleAndOffset) {
    // The same seed gives every scale the same random numbers, so the images agree up to the
    // rare sample that grazes an outline differently.
    const int w = 160, h = 120, spp = 8;
    const scene::Scene unit_scene = load_scene("scale_invariance.pov", "", w, h);
    const Image reference = render_path_tracer(unit_scene, w, h, spp, 4, 1).image;
    ASSERT_EQ(count_nonfinite(reference), 0);
    const char* preludes[] = {"#declare S = 1e-4;", "#declare S = 1e4;",
                              "#declare T = <1e5, 1e5, 1e5>;"};
    for (const char* prelude : preludes) {
        const scene::Scene s = load_scene("scale_invariance.pov", prelude, w, h);
        const Image image = render_path_tracer(s, w, h, spp, 4, 1).image;
        const double within = fraction_within(image, reference, 1);
        std::printf(
            "case 1 path %s: within 1/255 of scale 1 = %.5f (bound >= %.3f); non-finite "
            "%ld\n",
            prelude, within, kMinWithin, count_nonfinite(image));
        EXPECT_GE(within, kMinWithin) << prelude;
        EXPECT_EQ(count_nonfinite(image), 0);
    }
}

TEST(StabilityScaleInvariance, PovRayFigures) {
    // Not a bound on POV-Ray: its figures for the report, measured as glint's are. POV-Ray's
    // absolute epsilons (MIN_ISECT_DEPTH 1e-4, SHADOW_TOLERANCE 1e-3) do not scale.
    if (!povray_available()) GTEST_SKIP() << "povray not installed";
    const auto reference = povray_render("scale_invariance.pov", "", kWidth, kHeight);
    ASSERT_TRUE(reference.has_value());
    const scene::Scene unit_scene = load_scene("scale_invariance.pov", "", kWidth, kHeight);
    const AcneCount unit_acne = count_acne(*reference, unit_scene.camera, true);
    std::printf(
        "case 1 povray scale 1: acne pixels = %ld of %ld; lost shadow pixels = %ld of "
        "%ld\n",
        unit_acne.acne, unit_acne.checked, unit_acne.lost_shadow, unit_acne.shadowed);
    const char* preludes[] = {"#declare S = 1e-4;", "#declare S = 1e4;",
                              "#declare T = <1e5, 1e5, 1e5>;", "#declare T = <1e8, 1e8, 1e8>;"};
    for (const char* prelude : preludes) {
        const auto image = povray_render("scale_invariance.pov", prelude, kWidth, kHeight);
        ASSERT_TRUE(image.has_value());
        const AcneCount acne = count_acne(*image, unit_scene.camera, true);
        std::printf(
            "case 1 povray %s: within 1/255 of scale 1 = %.5f; acne pixels = %ld of "
            "%ld; lost shadow pixels = %ld of %ld\n",
            prelude, fraction_within(*image, *reference, 1), acne.acne, acne.checked,
            acne.lost_shadow, acne.shadowed);
    }
}

}  // namespace
}  // namespace glint::stability
