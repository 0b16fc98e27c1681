// The path tracer's sampler and BSDFs: determinism and uniformity of the sampler, the white
// furnace on each BSDF alone (the integral of f * cos over the sphere: 1 for Lambert and for a
// smooth dielectric's reflection + transmission, at most 1 otherwise), and consistency of
// sample() with eval()/pdf() (BSDF sampling and uniform sphere sampling estimate the same
// integral within 3 sigma; sample()'s pdf equals pdf()).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "render/bsdf/bsdf.h"
#include "render/bsdf/pov_to_pbr.h"
#include "render/sampling/sampler.h"

namespace glint::render {
namespace {

struct Case {
    std::string name;
    Bsdf bsdf;
    bool smooth = false;
};

PrincipledParams params(Color base, double metallic, double roughness, double specular,
                        double transmission, double ior = 1.5) {
    PrincipledParams p;
    p.base = base;
    p.metallic = metallic;
    p.roughness = roughness;
    p.specular = specular;
    p.transmission = transmission;
    p.ior = ior;
    return p;
}

Vec3 dir_from(double theta_deg, double phi = 0.3) {
    const double t = theta_deg * kPi / 180;
    return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

struct Estimate {
    double mean = 0, stderr_ = 0;
};

// Mean of the BSDF-sampling weight (failed samples count as 0).
Estimate by_sampling(const Bsdf& b, const Vec3& wo, int n, uint32_t seed, double* max_pdf_err) {
    double s = 0, s2 = 0;
    for (int i = 0; i < n; ++i) {
        PixelSampler ps(static_cast<int>(seed), 7, static_cast<uint32_t>(i), seed);
        const Sample2 a = ps.get2(1), d = ps.get2(2);
        BsdfSample bs;
        double v = 0;
        if (b.sample(wo, a.u, d.u, d.v, &bs)) {
            v = (bs.weight.r + bs.weight.g + bs.weight.b) / 3;
            if (!bs.delta && max_pdf_err) {
                const double p = b.pdf(wo, bs.wi);
                *max_pdf_err = std::max(*max_pdf_err, std::fabs(p - bs.pdf) / std::max(p, 1e-12));
            }
        }
        s += v;
        s2 += v * v;
    }
    const double m = s / n;
    return {m, std::sqrt(std::max(0.0, s2 / n - m * m) / n)};
}

// Mean of f * |cos| / (1 / 4 pi) over uniform directions on the sphere.
Estimate by_uniform(const Bsdf& b, const Vec3& wo, int n, uint32_t seed) {
    double s = 0, s2 = 0;
    for (int i = 0; i < n; ++i) {
        const Sample2 u = PixelSampler(static_cast<int>(seed), 11, static_cast<uint32_t>(i), seed).get2(3);
        const double z = 1 - 2 * u.u, r = std::sqrt(std::max(0.0, 1 - z * z));
        const Vec3 wi(r * std::cos(2 * kPi * u.v), r * std::sin(2 * kPi * u.v), z);
        const Color f = b.eval(wo, wi);
        const double v = (f.r + f.g + f.b) / 3 * std::fabs(z) * 4 * kPi;
        s += v;
        s2 += v * v;
    }
    const double m = s / n;
    return {m, std::sqrt(std::max(0.0, s2 / n - m * m) / n)};
}

TEST(PathSampler, DeterministicAndInUnitInterval) {
    PixelSampler a(3, 4, 5, 6), b(3, 4, 5, 6), c(3, 4, 6, 6);
    for (uint32_t d = 0; d < 40; ++d) {
        EXPECT_EQ(a.get2(d).u, b.get2(d).u);
        EXPECT_EQ(a.get2(d).v, b.get2(d).v);
        EXPECT_NE(a.get2(d).u, c.get2(d).u);
    }
    // 2D stratification: 256 samples of one pixel put exactly one in each 16 x 16 cell.
    int cells[256] = {};
    for (uint32_t i = 0; i < 256; ++i) {
        const Sample2 s = PixelSampler(10, 20, i, 1).get2(5);
        ASSERT_GE(s.u, 0.0);
        ASSERT_LT(s.u, 1.0);
        ASSERT_GE(s.v, 0.0);
        ASSERT_LT(s.v, 1.0);
        ++cells[static_cast<int>(s.u * 16) * 16 + static_cast<int>(s.v * 16)];
    }
    for (int c2 : cells) EXPECT_EQ(c2, 1);
}

TEST(PathBsdf, LambertFurnaceIsExactlyOne) {
    const Bsdf b = Bsdf::lambert(Color(1, 1, 1));
    for (double theta : {0.0, 30.0, 60.0, 89.0}) {
        const Estimate e = by_sampling(b, dir_from(theta), 4096, 1, nullptr);
        EXPECT_NEAR(e.mean, 1.0, 1e-12) << theta;
        const Estimate u = by_uniform(b, dir_from(theta), 1 << 16, 2);
        EXPECT_NEAR(u.mean, 1.0, 3 * u.stderr_ + 1e-9) << theta;
    }
}

TEST(PathBsdf, SmoothDielectricReflectionPlusTransmissionIsOne) {
    for (double ior : {1.0001, 1.33, 1.5, 2.4, 100.0}) {
        const Bsdf b = Bsdf::principled(params(Color(1, 1, 1), 0, 0, 0.5, 1, ior));
        EXPECT_TRUE(b.all_delta());
        for (double theta : {0.0, 45.0, 80.0, 100.0, 135.0, 179.0}) {  // > 90: from inside
            const Estimate e = by_sampling(b, dir_from(theta), 2048, 3, nullptr);
            EXPECT_NEAR(e.mean, 1.0, 1e-12) << "ior " << ior << " theta " << theta;
        }
    }
}

TEST(PathBsdf, EnergyAtMostOneAndSamplingMatchesEval) {
    const Case cases[] = {
        {"principled rough dielectric", Bsdf::principled(params(Color(1, 1, 1), 0, 0.5, 0.5, 0))},
        {"principled glossy", Bsdf::principled(params(Color(0.9, 0.5, 0.2), 0, 0.3, 1.0, 0))},
        {"rough metal", Bsdf::principled(params(Color(1, 1, 1), 1, 0.4, 0.5, 0))},
        {"very rough metal", Bsdf::principled(params(Color(1, 1, 1), 1, 1.0, 0.5, 0))},
        {"half metal", Bsdf::principled(params(Color(0.8, 0.8, 0.8), 0.5, 0.6, 0.5, 0))},
        {"rough glass", Bsdf::principled(params(Color(1, 1, 1), 0, 0.5, 0.5, 1, 1.5))},
        {"rough glass ior 1.33", Bsdf::principled(params(Color(1, 1, 1), 0, 0.7, 0.5, 1, 1.33))},
        {"half glass", Bsdf::principled(params(Color(1, 1, 1), 0, 0.6, 0.5, 0.5, 1.5))},
        {"phong n 1", Bsdf::phong(Color(0.5, 0.5, 0.5), Color(0.5, 0.5, 0.5), 1)},
        {"phong n 10", Bsdf::phong(Color(0, 0, 0), Color(1, 1, 1), 10)},
        {"phong n 100", Bsdf::phong(Color(0.3, 0.2, 0.1), Color(0.7, 0.7, 0.7), 100)},
    };
    for (const Case& c : cases) {
        for (double theta : {10.0, 45.0, 75.0, 120.0}) {
            const Vec3 wo = dir_from(theta);
            double pdf_err = 0;
            const Estimate s = by_sampling(c.bsdf, wo, 1 << 16, 5, &pdf_err);
            const Estimate u = by_uniform(c.bsdf, wo, 1 << 18, 9);
            SCOPED_TRACE(c.name + " theta " + std::to_string(theta));
            EXPECT_LE(s.mean, 1.0 + 3 * s.stderr_ + 1e-3);
            EXPECT_LT(pdf_err, 1e-6);
            const double sigma = std::sqrt(s.stderr_ * s.stderr_ + u.stderr_ * u.stderr_);
            EXPECT_NEAR(s.mean, u.mean, 3 * sigma + 1e-4) << "sampled " << s.mean << " uniform "
                                                            << u.mean;
        }
    }
}

TEST(PathBsdf, ExtremeParametersStayFinite) {
    for (double rough : {0.0, 1e-3, 0.0316, 0.05, 1.0})
        for (double tr : {0.0, 1.0})
            for (double ior : {1.0, 1.0001, 2.4, 100.0}) {
                const Bsdf b = Bsdf::principled(params(Color(1, 1, 1), 0, rough, 0.5, tr, ior));
                for (double theta : {0.0, 1e-7, 45.0, 89.9999, 90.0, 135.0, 180.0}) {
                    const Vec3 wo = dir_from(theta);
                    for (uint32_t i = 0; i < 64; ++i) {
                        const Sample2 a = PixelSampler(1, 2, i, 3).get2(1), d = PixelSampler(1, 2, i, 3).get2(2);
                        BsdfSample bs;
                        if (!b.sample(wo, a.u, d.u, d.v, &bs)) continue;
                        ASSERT_TRUE(std::isfinite(bs.weight.r) && std::isfinite(bs.pdf));
                        ASSERT_TRUE(is_finite(bs.wi));
                        const Color f = b.eval(wo, bs.wi);
                        ASSERT_TRUE(std::isfinite(f.r) && std::isfinite(b.pdf(wo, bs.wi)));
                    }
                }
            }
}

TEST(PathBsdf, PhongExtremeExponentsStayFiniteAndPeakAtTheMirror) {
    for (double n : {0.0, 1.0, 1e5, 1e6}) {
        const Bsdf b = Bsdf::phong(Color(0, 0, 0), Color(1, 1, 1), n);
        const Vec3 wo = dir_from(30);
        const Vec3 mirror(-wo.x, -wo.y, wo.z);
        const Color f = b.eval(wo, mirror);
        EXPECT_TRUE(std::isfinite(f.r) && f.r > 0) << n;
        const Estimate e = by_sampling(b, wo, 1024, 4, nullptr);
        EXPECT_TRUE(std::isfinite(e.mean)) << n;
        EXPECT_LE(e.mean, 1.0 + 1e-9) << n;
        if (n >= 1e5) {
            // A narrow modified-Phong lobe reflects (n + 2) / (n + 1) * cos(theta_o) ~ cos 30.
            EXPECT_NEAR(e.mean, std::cos(30 * kPi / 180), 1e-4) << n;
        }
    }
}

TEST(PathPbrMapping, PovFinishesMapAsDocumented) {
    scene::Finish f;
    scene::Interior in;
    // Plain POV-Ray diffuse: Lambert in the pigment color, no highlight.
    SurfacePbr s = pov_to_pbr(f, in, scene::ColorFT(Color(0.2, 0.4, 0.6)));
    EXPECT_EQ(s.bsdf.base, Color(0.2, 0.4, 0.6));
    EXPECT_EQ(s.bsdf.specular, 0);
    EXPECT_EQ(s.alpha, 1);
    // Phong highlight: GGX roughness from phong_size, specular 0.5 .. 1.
    f.phong = 1;
    f.phong_size = 40;
    s = pov_to_pbr(f, in, scene::ColorFT(Color(1, 1, 1)));
    EXPECT_NEAR(s.bsdf.roughness, std::sqrt(std::sqrt(2.0 / 42.0)), 1e-12);
    EXPECT_EQ(s.bsdf.specular, 1.0);
    // Metallic reflection: a metal.
    f.reflection.max = Color(0.8, 0.8, 0.8);
    f.reflection.metallic = 1;
    s = pov_to_pbr(f, in, scene::ColorFT(Color(1, 0.8, 0.3)));
    EXPECT_EQ(s.bsdf.metallic, 0.8);
    EXPECT_EQ(s.bsdf.roughness, 0);
    // Glass: filter/transmit with an ior -> transmission; ior 1 -> coverage.
    scene::Finish plain;
    in.ior = 1.5;
    s = pov_to_pbr(plain, in, scene::ColorFT(Color(1, 1, 1), 0, 0.9));
    EXPECT_EQ(s.bsdf.transmission, 0.9);
    EXPECT_EQ(s.alpha, 1);
    in.ior = 1.0;
    s = pov_to_pbr(plain, in, scene::ColorFT(Color(1, 1, 1), 0.5, 0.5));
    EXPECT_EQ(s.alpha, 0.5);
    EXPECT_EQ(s.bsdf.transmission, 1.0);
    // Emission is tinted by the pigment.
    plain.emission = Color(2, 2, 2);
    s = pov_to_pbr(plain, in, scene::ColorFT(Color(0.5, 1, 1)));
    EXPECT_EQ(s.emission, Color(1, 2, 2));
}

}  // namespace
}  // namespace glint::render
