// POV-Ray media: the parser's stored values and errors, and the classic renderer's media
// against closed forms: a slab's transmittance exp(-sigma d), emission with absorption
// converging to E / sigma (1 - exp(-sigma d)) as intervals grow, single scattering of a light
// against numerical quadrature, shadows through media, and the variance thresholds of
// methods 1 and 2 (inverse chi-square values from tables).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/log.h"
#include "render/media/pov_media.h"
#include "render/integrators/whitted.h"
#include "render/prepare/prepared_scene.h"
#include "unit/pov_test_util.h"

namespace glint {
namespace {

using pov::testing::error_of;
using pov::testing::parse;

TEST(MediaParser, DefaultsFollowTheVersion) {
    auto s = parse("#version 3.7; media { scattering { 1, 0.1 } }");
    ASSERT_EQ(s.media.size(), 1u);
    EXPECT_EQ(s.media[0].method, 3);
    EXPECT_EQ(s.media[0].intervals, 1);
    EXPECT_EQ(s.media[0].min_samples, 10);
    EXPECT_EQ(s.media[0].max_samples, 10);
    auto old = parse("#version 3.1; media { scattering { 1, 0.1 } }");
    EXPECT_EQ(old.media[0].method, 1);
    EXPECT_EQ(old.media[0].intervals, 10);
    EXPECT_EQ(old.media[0].min_samples, 1);
}

TEST(MediaParser, ItemsIdentifiersAndDensities) {
    auto s = parse(
        "#declare M = media { absorption <1, 0.5, 0.25> samples 3, 7 }\n"
        "#declare P = density { rgb 2 }\n"
        "#declare D = density { spherical density_map { [0 rgb 0] [1 P scale 2] } }\n"
        "sphere { 0, 1 pigment { rgbt 1 } hollow\n"
        "  interior { media { M emission 0.3 scattering { 5, rgb 0.2 eccentricity 0.4 "
        "extinction 0.5 } method 2 intervals 4 jitter 0.1 aa_level 4 aa_threshold 0.05 "
        "confidence 0.8 variance 0.01 ratio 0.7 collect off density { D } density { rgb 0.5 } } }\n"
        "  translate <1, 2, 3> }");
    ASSERT_EQ(s.objects.size(), 1u);
    const scene::Interior& in = s.materials[s.objects[0].material].interior;
    ASSERT_EQ(in.media.size(), 1u);
    const scene::Media& m = in.media[0];
    EXPECT_EQ(m.absorption, Color(1, 0.5, 0.25));
    EXPECT_EQ(m.min_samples, 3);
    EXPECT_EQ(m.max_samples, 7);
    EXPECT_EQ(m.emission, Color(0.3));
    EXPECT_EQ(m.type, scene::ScatteringType::HenyeyGreenstein);
    EXPECT_EQ(m.scattering, Color(0.2));
    EXPECT_EQ(m.eccentricity, 0.4);
    EXPECT_EQ(m.extinction, 0.5);
    EXPECT_EQ(m.method, 2);
    EXPECT_EQ(m.intervals, 4);
    EXPECT_EQ(m.jitter, 0.1);
    EXPECT_EQ(m.aa_level, 4);
    EXPECT_EQ(m.aa_threshold, 0.05);
    EXPECT_EQ(m.confidence, 0.8);
    EXPECT_EQ(m.variance, 0.01);
    EXPECT_EQ(m.ratio, 0.7);
    EXPECT_FALSE(m.collect);
    ASSERT_EQ(m.density.size(), 2u);
    EXPECT_EQ(m.density[0].kind, scene::PatternKind::Spherical);
    ASSERT_EQ(m.density[0].pigment_map.size(), 2u);
    EXPECT_EQ(m.density[0].pigment_map[1].pigment[0].color.rgb, Color(2));
    // The object's transform carries the density with it.
    EXPECT_EQ(m.density[0].transform.point(Vec3(0, 0, 0)), Vec3(1, 2, 3));
    EXPECT_TRUE(s.objects[0].hollow);
}

TEST(MediaParser, Errors) {
    EXPECT_EQ(error_of("media { intervals 0 }"), "1:9: at least one interval is needed in media");
    EXPECT_EQ(error_of("media { samples 4, 2 }"),
              "1:9: the maximum number of media samples is smaller than the minimum");
    EXPECT_EQ(error_of("media { method 4 }"), "1:9: media method choices are 1, 2 or 3");
    EXPECT_EQ(error_of("media { scattering { 1, 0.5 eccentricity 0.3 } }"),
              "1:29: eccentricity can only be used with scattering type 5");
    EXPECT_EQ(error_of("sphere { 0, 1 pigment { bozo density_map { [0 rgb 0] } } }"),
              "1:30: density_map can only be used in a density");
    EXPECT_EQ(error_of("media { intervals 1000 samples 200, 200 }"),
              "1:7: media sampling of 1000 intervals x 200 samples is over the limit of 100000 "
              "samples per ray");
    EXPECT_EQ(error_of("media { foo }"),
              "1:9: expected a media item (absorption, emission, scattering, density, samples, "
              "...), got 'foo'");
}

TEST(MediaParser, LightFlags) {
    auto s = parse("light_source { 0, 1 media_interaction off media_attenuation on }");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_FALSE(s.lights[0].media_interaction);
    EXPECT_TRUE(s.lights[0].media_attenuation);
}

TEST(MediaParser, DensityFileReadsDf3Grids) {
    // A 2 x 1 x 1 grid of 16-bit voxels: 0 and 65535.
    const std::string path = ::testing::TempDir() + "glint_two.df3";
    {
        std::ofstream f(path, std::ios::binary);
        const unsigned char bytes[] = {0, 2, 0, 1, 0, 1, 0, 0, 0xff, 0xff};
        f.write(reinterpret_cast<const char*>(bytes), sizeof bytes);
    }
    auto s = parse("media { density { density_file df3 \"" + path + "\" interpolate 1 } }");
    ASSERT_EQ(s.media[0].density.size(), 1u);
    const scene::Pigment& d = s.media[0].density[0];
    EXPECT_EQ(d.kind, scene::PatternKind::DensityFile);
    ASSERT_TRUE(d.params.density_file);
    EXPECT_EQ(d.params.density_file->nx, 2);
    EXPECT_EQ(d.params.density_interpolate, 1);
    EXPECT_FLOAT_EQ(d.params.density_file->values[1], 1.0f);
    // interpolate may also follow the pattern's other modifiers (densfile.pov's normal does);
    // on any other pattern it is an error.
    auto later = parse("media { density { density_file df3 \"" + path +
                       "\" scale 2 interpolate 2 } }");
    EXPECT_EQ(later.media[0].density[0].params.density_interpolate, 2);
    EXPECT_EQ(error_of("media { density { bozo interpolate 1 } }"),
              "1:24: 'interpolate' applies only to density_file patterns");
    // A file whose size does not fit its header is refused, with the place.
    const std::string bad = ::testing::TempDir() + "glint_bad.df3";
    {
        std::ofstream f(bad, std::ios::binary);
        const unsigned char bytes[] = {0, 2, 0, 2, 0, 2, 1, 2, 3};
        f.write(reinterpret_cast<const char*>(bytes), sizeof bytes);
    }
    EXPECT_EQ(error_of("media { density { density_file df3 \"" + bad + "\" } }"),
              "1:32: '" + bad + "' is not a df3 density file: 2 x 2 x 2 voxels do not fill its "
              "3 bytes of data");
    EXPECT_EQ(error_of("media { density { density_file df3 \"no_such.df3\" } }"),
              "1:32: cannot find the file 'no_such.df3'");
}

TEST(PovMedia, InverseChiSquareMatchesTables) {
    using render::PovMedia;
    // Upper-tail critical values of the chi-square distribution.
    EXPECT_NEAR(PovMedia::chi_square_upper_inverse(1, 0.05), 3.841459, 1e-5);
    EXPECT_NEAR(PovMedia::chi_square_upper_inverse(2, 0.10), 4.605170, 1e-5);
    EXPECT_NEAR(PovMedia::chi_square_upper_inverse(10, 0.90), 4.865182, 1e-5);
    EXPECT_NEAR(PovMedia::chi_square_upper_inverse(5, 0.99), 0.554298, 1e-5);
    scene::Media m;
    m.max_samples = 4;
    m.confidence = 0.9;
    m.variance = 0.01;
    std::vector<double> t = PovMedia::sample_thresholds(m);
    ASSERT_EQ(t.size(), 4u);
    // Scaled so that the last threshold is the variance itself, growing with the samples.
    EXPECT_NEAR(t[2], 0.01, 1e-12);
    EXPECT_LT(t[0], t[1]);
    EXPECT_LT(t[1], t[2]);
}

// Renders one ray of a parsed scene with the classic renderer.
Color trace(const std::string& pov, Vec3 origin, Vec3 dir) {
    scene::Scene s = parse(pov);
    Diagnostics diag;
    render::RenderOptions opts;
    auto prepared = render::prepare(s, opts, diag);
    render::Whitted w(*prepared);
    render::Ray r;
    r.origin = origin;
    r.dir = normalize(dir);
    return w.li(r);
}

// A transparent hollow slab z in [0, d], wide in x and y, seen along +z against a background.
std::string slab(double d, const std::string& media, const std::string& extra = "") {
    return "#version 3.7; background { rgb <0.8, 0.6, 0.4> }\n" + extra +
           "box { <-50, -50, 0> <50, 50, " + std::to_string(d) +
           "> pigment { rgbt 1 } hollow interior { media { " + media + " } } }";
}

TEST(PovMediaRender, SlabTransmittanceIsExponential) {
    const double sigma = 0.7, d = 1.5;
    Color c = trace(slab(d, "absorption <0.7, 1.4, 0.35>"), Vec3(0, 0, -5), Vec3(0, 0, 1));
    EXPECT_NEAR(c.r, 0.8 * std::exp(-sigma * d), 1e-9);
    EXPECT_NEAR(c.g, 0.6 * std::exp(-2 * sigma * d), 1e-9);
    EXPECT_NEAR(c.b, 0.4 * std::exp(-0.5 * sigma * d), 1e-9);
    // A slanted ray crosses d / cos(theta).
    const double cos_t = 1.0 / std::sqrt(2.0);
    Color s = trace(slab(d, "absorption 0.7"), Vec3(-5, 0, -5), Vec3(1, 0, 1));
    EXPECT_NEAR(s.r, 0.8 * std::exp(-sigma * d / cos_t), 1e-9);
    // Not hollow: POV-Ray computes no media inside solid objects.
    std::string solid = slab(d, "absorption 0.7");
    solid.replace(solid.find(" hollow"), 7, "");
    EXPECT_NEAR(trace(solid, Vec3(0, 0, -5), Vec3(0, 0, 1)).r, 0.8, 1e-12);
}

TEST(PovMediaRender, HollowBelongsToTheShapeInsideACsg) {
    // POV-Ray keeps `hollow` with the interior of the shape a ray is in: a hollow sphere
    // inside a union that is not hollow holds its media, for the eye inside it and for a ray
    // entering it (abyss.pov's water).
    auto scene = [](const std::string& sphere_flag, const std::string& union_flag) {
        return "#version 3.7; background { rgb <0.8, 0.6, 0.4> }\n"
               "camera { location 0 look_at z }\n"
               "union { sphere { 0, 2 pigment { rgbt 1 } " + sphere_flag +
               " interior { media { absorption 0.7 } } }\n"
               "        sphere { <50, 0, 0>, 1 } " + union_flag + " }";
    };
    const double from_eye = 0.8 * std::exp(-0.7 * 2);                // radius 2
    const double through = 0.8 * std::exp(-0.7 * 2 * std::sqrt(3.75));  // chord at y = 0.5
    for (const auto& [s, u] : {std::pair{"hollow", ""}, std::pair{"", "hollow"}}) {
        const std::string pov = scene(s, u);
        EXPECT_NEAR(trace(pov, Vec3(0, 0, 0), Vec3(0, 0, 1)).r, from_eye, 1e-9) << pov;
        EXPECT_NEAR(trace(pov, Vec3(0, 0.5, -5), Vec3(0, 0, 1)).r, through, 1e-9) << pov;
    }
    // Neither hollow: no media inside the solid.
    EXPECT_NEAR(trace(scene("", ""), Vec3(0, 0, 0), Vec3(0, 0, 1)).r, 0.8, 1e-12);
}

TEST(PovMediaRender, EyeInsideAUnionChildWhateverTheViewMeetsFirst) {
    // POV-Ray links a union's children as objects of their own, so the eye is inside the
    // media sphere even when the first surface in the view is another child (entered).
    const std::string pov =
        "#version 3.7; background { rgb <0.8, 0.6, 0.4> }\n"
        "camera { location 0 look_at z }\n"
        "union { sphere { <0, 0, 1>, 0.3 pigment { rgb 1 } }\n"
        "        sphere { 0, 2 pigment { rgbt 1 } hollow interior { media { absorption 0.7 } } } }";
    EXPECT_NEAR(trace(pov, Vec3(0, 0, 0), Vec3(0, 0, -1)).r, 0.8 * std::exp(-0.7 * 2), 1e-9);
}

TEST(PovMediaRender, EmissionWithAbsorptionConvergesToTheIntegral) {
    // L = bg e^{-sigma d} + E / sigma (1 - e^{-sigma d}). POV-Ray's sampler sums the emission
    // of sub-intervals, so the error falls as the intervals grow.
    const double sigma = 1.2, d = 2.0, e = 0.5;
    const double exact = 0.8 * std::exp(-sigma * d) + e / sigma * (1 - std::exp(-sigma * d));
    double previous = HUGE_VAL;
    for (int intervals : {1, 4, 32, 128}) {
        Color c = trace(slab(d, "absorption 1.2 emission 0.5 intervals " +
                                    std::to_string(intervals) + " density { rgb 1 }"),
                        Vec3(0, 0, -5), Vec3(0, 0, 1));
        const double err = std::fabs(c.r - exact);
        EXPECT_LT(err, previous) << intervals << " intervals";
        previous = err;
    }
    EXPECT_LT(previous / exact, 0.01);
}

TEST(PovMediaRender, SingleScatteringMatchesQuadrature) {
    // A point light behind the camera on the axis; isotropic scattering sigma_s, absorption
    // sigma_a. Light reaching depth t crossed t of the medium, and the scattered light
    // crosses t again on its way back: L = bg e^{-st d} + int_0^d ss I e^{-2 st t} dt.
    const double ss = 0.6, sa = 0.3, st = ss + sa, d = 1.0, I = 1.5;
    const std::string light = "light_source { <0, 0, -3> rgb 1.5 }\n";
    Color c = trace(slab(d, "scattering { 1, 0.6 } absorption 0.3 intervals 200 samples 3",
                         light),
                    Vec3(0, 0, -5), Vec3(0, 0, 1));
    double integral = 0.0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        double t = (i + 0.5) / n * d;
        integral += ss * I * std::exp(-2 * st * t) * d / n;
    }
    const double exact = 0.8 * std::exp(-st * d) + integral;
    EXPECT_NEAR(c.r, exact, 5e-3 * exact);
    // media_interaction off: only the attenuated background is left.
    Color off = trace(slab(d, "scattering { 1, 0.6 } absorption 0.3 intervals 200 samples 3",
                           "light_source { <0, 0, -3> rgb 1.5 media_interaction off }\n"),
                      Vec3(0, 0, -5), Vec3(0, 0, 1));
    EXPECT_NEAR(off.r, 0.8 * std::exp(-st * d), 1e-9);
}

TEST(PovMediaRender, MediaShadowTheLight) {
    // A lit white floor under an absorbing hollow box: the light through the box is dimmed
    // by e^{-sigma h} for the box's height h along the (vertical) shadow ray.
    const std::string scene =
        "#version 3.7; light_source { <0, 10, 0> rgb 1 }\n"
        "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
        "box { <-1, 1, -1> <1, 3, 1> pigment { rgbt 1 } hollow interior { media { "
        "absorption <0.5, 1, 2> } } }\n";
    Color lit = trace(scene, Vec3(3, 1, 0), Vec3(0, -1, 0));     // beside the box
    Color under = trace(scene, Vec3(0, 0.5, 0), Vec3(0, -1, 0));  // below it
    EXPECT_NEAR(lit.r, 10.0 / std::sqrt(109.0), 1e-9);  // Lambert's cosine only
    EXPECT_NEAR(under.r, std::exp(-0.5 * 2), 1e-9);
    EXPECT_NEAR(under.g, std::exp(-1.0 * 2), 1e-9);
    EXPECT_NEAR(under.b, std::exp(-2.0 * 2), 1e-9);
}

TEST(PovMediaRender, AtmosphereAttenuatesOnlyLightsThatAsk) {
    // Atmospheric absorption between floor and light dims a media_attenuation light only.
    auto floor = [](const std::string& flags) {
        return "#version 3.7; media { absorption 0.1 }\n"
               "light_source { <0, 10, 0> rgb 1 " + flags + " }\n"
               "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
    };
    // The eye ray also crosses 1 unit of the medium down to the floor.
    const double eye = std::exp(-0.1 * 1.0);
    EXPECT_NEAR(trace(floor(""), Vec3(0, 1, 0), Vec3(0, -1, 0)).r, eye, 1e-9);
    EXPECT_NEAR(trace(floor("media_attenuation on"), Vec3(0, 1, 0), Vec3(0, -1, 0)).r,
                eye * std::exp(-0.1 * 10.0), 1e-9);
}

}  // namespace
}  // namespace glint
