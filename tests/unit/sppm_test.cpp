// The photon integrator (--integrator sppm, render/gi/sppm.h): it converges to the path
// tracer's image where both converge (a small light in a box), its error falling pass after
// pass; a point light's caustic through a glass ball carries the flux the ball lets through
// (an analytic check with the dielectric Fresnel factors); the image is the same at any
// thread count and a region is the whole image's pixels; what it cannot render is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "core/log.h"
#include "render/bsdf/closure_set.h"
#include "render/render.h"
#include "unit/pov_test_util.h"

namespace glint::render {
namespace {

Image render_text(const std::string& text, IntegratorKind kind, int w, int h, int spp,
                  long photons = 0, int threads = 2, Region region = {}) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.integrator = kind;
    o.spp = spp;
    o.photons = photons;
    o.threads = threads;
    o.region = region;
    Diagnostics diag;
    return render(pov::testing::parse(text), o, diag).image;
}

// mean((x - r)^2 / (r^2 + 0.01)) over the RGB values, as `glint report` measures it.
double relmse(const Image& x, const Image& r) {
    double s = 0;
    int n = 0;
    for (size_t i = 0; i < x.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = x.rgba[i] - r.rgba[i];
        s += d * d / (static_cast<double>(r.rgba[i]) * r.rgba[i] + 0.01);
        ++n;
    }
    return s / n;
}

double mean(const Image& img) {
    double s = 0;
    for (size_t i = 0; i < img.rgba.size(); ++i)
        if (i % 4 != 3) s += img.rgba[i];
    return s / (img.rgba.size() / 4 * 3);
}

// A closed diffuse box lit by a small emitting ball, a diffuse ball and a mirror ball in it:
// light that bounces several times, which the path tracer and the photons both carry.
const char* kBox =
    "#version 3.7;\n"
    "camera { location <0, 1, -2.8> look_at <0, 1, 0> angle 60 }\n"
    "box { <-1.5, 0, -3>, <1.5, 2.2, 1.5> pigment { rgb 0.7 } finish { ambient 0 diffuse 1 } }\n"
    "sphere { <0.4, 2.0, 0.3>, 0.08 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 60 } }\n"
    "sphere { <-0.5, 0.4, 0.4>, 0.4 pigment { rgb <0.8, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }\n"
    "sphere { <0.6, 0.35, -0.2>, 0.35 pigment { rgb 0 }\n"
    "  finish { ambient 0 diffuse 0 reflection 1 } }\n";

TEST(Sppm, ConvergesToThePathTracerPassAfterPass) {
    const int w = 24, h = 18;
    const Image ref = render_text(kBox, IntegratorKind::Path, w, h, 2048);
    double last = 1e300;
    std::vector<double> errors;
    Image img;
    for (int passes : {4, 16, 64}) {
        img = render_text(kBox, IntegratorKind::Sppm, w, h, passes, 20000);
        const double e = relmse(img, ref);
        errors.push_back(e);
        std::printf("%d passes: relmse %g\n", passes, e);
        EXPECT_LT(e, last) << passes << " passes";
        last = e;
    }
    // The error falls about as a consistent estimate's should: by 4x over 16x the passes.
    EXPECT_LT(errors.back(), errors.front() / 4) << errors.front() << " " << errors.back();
    EXPECT_LT(errors.back(), 0.003);
    // And the light is all there: the mean within 3% of the path tracer's.
    EXPECT_NEAR(mean(img) / mean(ref), 1.0, 0.03);
}

// The exact dielectric Fresnel reflectance at incidence cosine c from outside, eta = n2/n1.
double fresnel(double c, double eta) {
    const double s2 = 1 - c * c;
    const double t2 = 1 - s2 / (eta * eta);
    if (t2 <= 0) return 1;
    const double ct = std::sqrt(t2);
    const double rs = (c - eta * ct) / (c + eta * ct);
    const double rp = (eta * c - ct) / (eta * c + ct);
    return 0.5 * (rs * rs + rp * rp);
}

TEST(Sppm, PointLightCausticCarriesTheFluxTheBallLetsThrough) {
    // A point light 4 above a white floor, a glass ball (radius 0.5, ior 1.5) halfway; an
    // orthographic camera just above the floor (cameras cast no shadow) looks straight down
    // at [-1.6, 1.6]^2, which holds the ball's whole shadow (radius 1.03) and its caustic.
    // fade_power 2 with a small fade_distance makes the light physical: irradiance
    // pi C cos 2 / (1 + (d / fd)^2).
    const double C = 1000, fd = 0.05, H = 4, D = 2, R = 0.5, eta = 1.5, half = 1.6;
    const std::string light = "light_source { <0, 4, 0> rgb 1000 fade_distance 0.05 "
                              "fade_power 2 }\n";
    const std::string base =
        "#version 3.7;\n"
        "camera { orthographic location <0, 0.3, 0> look_at 0 right 3.2*x up 3.2*z }\n" +
        light + "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
    const std::string ball =
        "sphere { <0, 2, 0>, 0.5 pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }\n"
        "  interior { ior 1.5 } }\n";
    const int n = 64;
    const Image img = render_text(base + ball, IntegratorKind::Sppm, n, n, 24, 200000);
    // The flux on the window: irradiance = pi x radiance (white Lambert) times pixel area.
    const double pixel_area = (2 * half / n) * (2 * half / n);
    double flux = 0, peak = 0;
    for (int i = 0; i < n * n; ++i) {
        const double e = kPi * img.rgba[static_cast<size_t>(i) * 4 + 1];
        flux += e * pixel_area;
        peak = std::max(peak, e);
    }
    // Without the ball, and through its cone, by quadrature of the light's irradiance.
    auto irradiance = [&](double x, double z) {
        const double d2 = x * x + z * z + H * H;
        return kPi * C * (H / std::sqrt(d2)) * 2 / (1 + d2 / (fd * fd));
    };
    const double shadow = H * std::tan(std::asin(R / D));  // where the cone meets the floor
    const int q = 800;
    double open = 0, cone = 0, through = 0, through_more = 0;
    for (int a = 0; a < q; ++a)
        for (int b = 0; b < q; ++b) {
            const double x = -half + (a + 0.5) * 2 * half / q;
            const double z = -half + (b + 0.5) * 2 * half / q;
            const double dflux = irradiance(x, z) * (2 * half / q) * (2 * half / q);
            open += dflux;
            const double rho = std::sqrt(x * x + z * z);
            if (rho >= shadow) continue;
            cone += dflux;
            // The ray towards (x, 0, z) meets the ball at incidence sin = (D / R) sin(beta).
            const double sin_i = std::min(1.0, D / R * std::sin(std::atan(rho / H)));
            const double F = fresnel(std::sqrt(1 - sin_i * sin_i), eta);
            through += dflux * (1 - F) * (1 - F);       // in and out
            through_more += dflux * (1 - F) * F;        // reflected inside first: anywhere
        }
    const double without = open - cone;
    std::printf("flux %g open %g cone %g through %g more %g peak %g e0 %g\n", flux, open, cone,
                through, through_more, peak, irradiance(0, 0));
    EXPECT_GT(flux, without + through - 0.02 * open);
    EXPECT_LT(flux, without + through + through_more + 0.02 * open);
    // And it is a caustic: far brighter than the open floor under the light.
    EXPECT_GT(peak, 4 * irradiance(0, 0));
    // The path tracer cannot reach it: its shadow holds little more than the light the
    // floor sends back up through the ball.
    const Image path = render_text(base + ball, IntegratorKind::Path, n, n, 16);
    double path_flux = 0;
    for (int i = 0; i < n * n; ++i)
        path_flux += kPi * path.rgba[static_cast<size_t>(i) * 4 + 1] * pixel_area;
    std::printf("path flux %g\n", path_flux);
    EXPECT_LT(path_flux, without + 0.3 * through);
}

const char* kCaustic =
    "#version 3.7;\n"
    "camera { location <0, 2.5, -3> look_at <0, 0.4, 0> angle 40 }\n"
    "light_source { <-1, 4, 1> rgb 900 fade_distance 0.05 fade_power 2 }\n"
    "plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 1 } }\n"
    "sphere { <0, 0.6, 0>, 0.6 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }\n"
    "  interior { ior 1.5 } }\n";

TEST(Sppm, SameImageAtAnyThreadCountAndInARegion) {
    const Image two = render_text(kCaustic, IntegratorKind::Sppm, 32, 24, 4, 5000, 2);
    const Image one = render_text(kCaustic, IntegratorKind::Sppm, 32, 24, 4, 5000, 1);
    EXPECT_EQ(one.rgba, two.rgba);
    const Region r{8, 6, 20, 18};
    const Image part = render_text(kCaustic, IntegratorKind::Sppm, 32, 24, 4, 5000, 2, r);
    ASSERT_EQ(part.width, 12);
    ASSERT_EQ(part.height, 12);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x)
            for (int c = 0; c < 4; ++c)
                ASSERT_EQ(part.pixel(x, y)[c], two.pixel(x + 8, y + 6)[c]) << x << "," << y;
    double sum = 0;
    for (size_t i = 0; i < two.rgba.size(); ++i) {
        ASSERT_TRUE(std::isfinite(two.rgba[i]));
        sum += two.rgba[i];
    }
    EXPECT_GT(sum, 0);
}

TEST(Sppm, RefusesWhatItCannotRender) {
    const std::string fog =
        "#version 3.7;\n"
        "camera { location <0, 1, -3> look_at 0 }\n"
        "light_source { <0, 3, 0> rgb 1 }\n"
        "sphere { 0, 1 pigment { rgbt 1 } hollow\n"
        "  interior { media { scattering { 1, 0.5 } } } }\n";
    try {
        render_text(fog, IntegratorKind::Sppm, 8, 6, 1);
        FAIL() << "media rendered by sppm";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("participating media"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("--integrator path"), std::string::npos);
    }
}

TEST(Sppm, SaysWhichEmittersLightNothing) {
    // An emitting box is left to BSDF hits by light sampling: no photon leaves it.
    const std::string text =
        "#version 3.7;\n"
        "camera { location <0, 1, -3> look_at 0 }\n"
        "light_source { <0, 3, 0> rgb 1 }\n"
        "plane { y, 0 pigment { rgb 1 } }\n"
        "box { -0.2, 0.2 pigment { rgb 1 } finish { emission 2 } }\n";
    std::vector<std::string> warnings;
    Diagnostics diag([&](const Diagnostic& d) {
        if (d.level == Diagnostic::Level::Warning)
            warnings.push_back(std::to_string(d.loc.line) + ": " + d.message);
    });
    RenderOptions o;
    o.width = 8;
    o.height = 6;
    o.integrator = IntegratorKind::Sppm;
    o.spp = 1;
    render(pov::testing::parse(text), o, diag);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].rfind("5: this emitting object cannot be light-sampled", 0), 0u)
        << warnings[0];
}

TEST(PathTracer, SaysWhatOnlyTheClassicRendererDraws) {
    // light_group, blob component textures and interior_texture are the classic renderer's:
    // the path tracer says so instead of silently rendering something else.
    const std::string text =
        "#version 3.7;\n"
        "camera { location <0, 1, -3> look_at 0 }\n"
        "light_group { light_source { <0, 3, 0> rgb 1 } sphere { 0, 0.5 pigment { rgb 1 } } }\n"
        "blob { threshold 0.5 sphere { x, 1, 1 pigment { rgb x } } sphere { -x, 1, 1 } }\n"
        "sphere { y, 0.3 pigment { rgb 1 } interior_texture { pigment { rgb x } } }\n";
    for (IntegratorKind kind : {IntegratorKind::Path, IntegratorKind::Whitted}) {
        std::vector<std::string> warnings;
        Diagnostics diag([&](const Diagnostic& d) {
            if (d.level == Diagnostic::Level::Warning) warnings.push_back(d.message);
        });
        RenderOptions o;
        o.width = 8;
        o.height = 6;
        o.integrator = kind;
        o.spp = 1;
        render(pov::testing::parse(text), o, diag);
        if (kind == IntegratorKind::Whitted) {
            EXPECT_TRUE(warnings.empty());
            continue;
        }
        ASSERT_EQ(warnings.size(), 1u);
        for (const char* what : {"light_group", "blob component textures", "interior_texture"})
            EXPECT_NE(warnings[0].find(what), std::string::npos) << warnings[0];
    }
}

TEST(ClosureSetDelta, TheDeltaChanceIsHowOftenSamplingPicksADelta) {
    // A POV-Ray finish with diffuse and a partial mirror: some samples are the mirror's.
    PrincipledParams p;
    p.base = Color(0.5, 0.5, 0.5);
    p.specular = 0.3 / 0.08;
    p.roughness = 0;
    const Vec3 ng(0, 0, 1), wo = normalize(Vec3(0.3, 0.1, 1));
    ClosureSet set(ng, wo);
    set.add(Bsdf::principled(p), Color(1, 1, 1), ng, 1);
    const double pd = set.delta_probability();
    ASSERT_GT(pd, 0.05);
    ASSERT_LT(pd, 0.95);
    int deltas = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        ClosureSample s;
        if (set.sample((i + 0.5) / n, std::fmod(i * 0.618033988749895, 1.0), &s) && s.delta)
            ++deltas;
    }
    EXPECT_NEAR(static_cast<double>(deltas) / n, pd, 0.002);
    // A plain diffuse surface has none, smooth glass only deltas.
    ClosureSet diffuse(ng, wo);
    diffuse.add(Bsdf::lambert(Color(0.8, 0.8, 0.8)), Color(1, 1, 1), ng, 1);
    EXPECT_EQ(diffuse.delta_probability(), 0.0);
    PrincipledParams g;
    g.transmission = 1;
    g.ior = 1.5;
    g.roughness = 0;
    ClosureSet glass(ng, wo);
    glass.add(Bsdf::principled(g), Color(1, 1, 1), ng, 1);
    EXPECT_NEAR(glass.delta_probability(), 1.0, 1e-12);
}

}  // namespace
}  // namespace glint::render
