// The path tracer's sampler and BSDFs: determinism and uniformity of the sampler, the white
// furnace on each BSDF alone (the integral of f * cos over the sphere: 1 for Lambert and for a
// smooth dielectric's reflection + transmission, Burley's 41/42 + 5 r / 84 at normal
// incidence, at most 1 for metals and glass), consistency of sample() with eval()/pdf() (BSDF
// sampling and uniform sphere sampling estimate the same integral within 3 sigma; sample()'s
// pdf equals pdf()), and eval() against Blender 3.4 Cycles' Principled formulas written out
// independently here (Burley diffuse, GGX with separable G1 G1 and Cycles' interpolated
// Fresnel, the glass lobe split by F at the normal).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "formats/obj/obj_importer.h"
#include "render/bsdf/bsdf.h"
#include "render/bsdf/pov_to_pbr.h"
#include "render/materials/sslt.h"
#include "render/sampling/sampler.h"
#include "scene/scene.h"

namespace glint::render {
namespace {

struct Case {
    std::string name;
    Bsdf bsdf;
    bool bounded = true;  // energy at most 1 (false: adds a diffuse lobe to a reflection)
};

PrincipledParams params(Color base, double metallic, double roughness, double specular,
                        double transmission, double ior = 1.5,
                        DiffuseModel diffuse = DiffuseModel::Burley) {
    PrincipledParams p;
    p.diffuse_model = diffuse;
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
        const Sample2 d = ps.get2(2);
        BsdfSample bs;
        double v = 0;
        if (b.sample(wo, d.u, d.v, &bs)) {
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

TEST(PathSampler, Sobol1TablesEqualTheDirectionNumbers) {
    // The byte tables must reproduce the 32 direction numbers' XOR for any index.
    auto reference = [](uint32_t i) {
        uint32_t r = 0;
        for (uint32_t v = 1U << 31; i != 0; i >>= 1, v ^= v >> 1)
            if (i & 1U) r ^= v;
        return r;
    };
    uint32_t x = 12345;
    for (int k = 0; k < 100000; ++k) {
        x = hash_u32(x + static_cast<uint32_t>(k));
        ASSERT_EQ(sobol1(x), reference(x)) << x;
        ASSERT_EQ(sobol1(static_cast<uint32_t>(k)), reference(static_cast<uint32_t>(k))) << k;
    }
    EXPECT_EQ(sobol1(0xffffffffU), reference(0xffffffffU));
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
        // Cycles adds the reflection to the diffuse without Fresnel layering: above 1.
        {"principled rough dielectric", Bsdf::principled(params(Color(1, 1, 1), 0, 0.5, 0.5, 0)),
         false},
        {"principled glossy", Bsdf::principled(params(Color(0.9, 0.5, 0.2), 0, 0.3, 1.0, 0)),
         false},
        {"lambert glossy", Bsdf::principled(params(Color(0.9, 0.5, 0.2), 0, 0.3, 1.0, 0, 1.5,
                                                   DiffuseModel::Lambert)),
         false},
        {"rough metal", Bsdf::principled(params(Color(1, 1, 1), 1, 0.4, 0.5, 0))},
        {"very rough metal", Bsdf::principled(params(Color(1, 1, 1), 1, 1.0, 0.5, 0))},
        {"half metal", Bsdf::principled(params(Color(0.8, 0.8, 0.8), 0.5, 0.6, 0.5, 0)), false},
        {"rough glass", Bsdf::principled(params(Color(1, 1, 1), 0, 0.5, 0.5, 1, 1.5))},
        {"rough glass ior 1.33", Bsdf::principled(params(Color(1, 1, 1), 0, 0.7, 0.5, 1, 1.33))},
        {"half glass", Bsdf::principled(params(Color(1, 1, 1), 0, 0.6, 0.5, 0.5, 1.5)), false},
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
            if (c.bounded) {
                EXPECT_LE(s.mean, 1.0 + 3 * s.stderr_ + 1e-3);
            }
            EXPECT_LT(pdf_err, 1e-6);
            const double sigma = std::sqrt(s.stderr_ * s.stderr_ + u.stderr_ * u.stderr_);
            EXPECT_NEAR(s.mean, u.mean, 3 * sigma + 1e-4) << "sampled " << s.mean << " uniform "
                                                            << u.mean;
        }
    }
}

// Blender 3.4 Cycles' Principled BSDF (v1, GGX, specular_tint 0), written out here from the
// definitions in its kernel (svm/closure.h, closure/bsdf_principled_diffuse.h,
// bsdf_microfacet.h, bsdf_util.h) in Cycles' own terms (tangent form of D, G1 from tan^2,
// fresnel_dielectric_cos), independently of glint's code: f without the cosine.
namespace cycles {

double fresnel_cos(double c, double eta) {
    c = std::fabs(c);
    double g = eta * eta - 1 + c * c;
    if (g <= 0) return 1;
    g = std::sqrt(g);
    const double a = (g - c) / (g + c), b = (c * (g + c) - 1) / (c * (g - c) + 1);
    return 0.5 * a * a * (1 + b * b);
}
double schlick(double u) { return std::pow(std::clamp(1 - u, 0.0, 1.0), 5); }
double d_ggx(double cos_m, double alpha) {
    const double c2 = cos_m * cos_m, t2 = (1 - c2) / c2, a2 = alpha * alpha;
    return a2 / (kPi * c2 * c2 * (a2 + t2) * (a2 + t2));
}
double g1(double cos_n, double alpha) {
    return 2 / (1 + std::sqrt(1 + alpha * alpha * (1 - cos_n * cos_n) / (cos_n * cos_n)));
}

// wo.z < 0: a back-facing hit (Cycles flips N and uses 1 / eta).
Color eval(const PrincipledParams& p, const Vec3& wo_in, const Vec3& wi_in) {
    const bool back = wo_in.z < 0;
    const Vec3 wo(wo_in.x, wo_in.y, back ? -wo_in.z : wo_in.z);
    const Vec3 wi(wi_in.x, wi_in.y, back ? -wi_in.z : wi_in.z);
    const double ior = back ? 1 / p.ior : p.ior;
    const double m = p.metallic, t = p.transmission, r = p.roughness;
    const double diffuse_weight = (1 - m) * (1 - t), final_t = t * (1 - m);
    const double alpha = r * r;
    Color f;
    if (wi.z > 0) {
        // Principled diffuse, components FULL.
        const double fv = schlick(wo.z), fl = schlick(wi.z);
        double v = (1 - 0.5 * fv) * (1 - 0.5 * fl);
        const double rr = r * (dot(wi, wo) + 1);
        v += rr * (fl + fv + fl * fv * (rr - 1));
        const double lambert = p.diffuse_model == DiffuseModel::Lambert ? 1.0 : v;
        f += p.base * (diffuse_weight * lambert / kPi);
        const Vec3 h = normalize(wo + wi);
        const double dg = d_ggx(h.z, alpha) * g1(wo.z, alpha) * g1(wi.z, alpha) /
                          (4 * wo.z * wi.z);
        if (p.specular > 1e-5 || m > 1e-5) {
            const double s_ior = 2 / (1 - std::sqrt(0.08 * p.specular)) - 1;
            const double f0 = fresnel_cos(1, s_ior);
            const double fh = (fresnel_cos(dot(wi, h), s_ior) - f0) / (1 - f0);
            const Color cspec0 = Color(p.specular * 0.08) * (1 - m) + p.base * m;
            f += (cspec0 * (1 - fh) + Color(fh)) * ((1 - final_t) * dg);
        }
        if (final_t > 0) f += Color(final_t * fresnel_cos(wo.z, ior) * dg);
    } else if (final_t > 0) {
        const Vec3 ht = -(wi * ior + wo), hn = normalize(ht);
        const double cos_ho = dot(hn, wo), cos_hi = dot(hn, wi);
        const double g = g1(wo.z, alpha) * g1(-wi.z, alpha);
        const double common = d_ggx(hn.z, alpha) * ior * ior / (wo.z * dot(ht, ht));
        const double out = g * std::fabs(cos_hi * cos_ho) * common;  // f cos(wi)
        const double refraction = std::max(1e-4, 1 - fresnel_cos(wo.z, ior));
        f += p.base * (final_t * refraction * out / std::fabs(wi.z));
    }
    return f;
}

}  // namespace cycles

TEST(PathBsdf, EvalMatchesCyclesPrincipledFormulas) {
    struct Material {
        std::string name;
        PrincipledParams p;
    };
    const Material mats[] = {
        {"plastic", params(Color(0.1, 0.2, 0.6), 0, 0.3, 0.5, 0)},
        {"metal r 1", params(Color(0.95, 0.64, 0.54), 1, 1.0, 0.5, 0)},
        {"metal r 0.05", params(Color(0.95, 0.64, 0.54), 1, 0.05, 0.5, 0)},
        {"metal r 0.2 specular 0.2", params(Color(0.95, 0.64, 0.54), 1, 0.2, 0.2, 0)},
        {"half metal", params(Color(0.8, 0.3, 0.3), 0.4, 0.6, 0.8, 0)},
        {"lambert glossy", params(Color(0.5, 0.5, 0.2), 0, 0.4, 0.7, 0, 1.5, DiffuseModel::Lambert)},
        {"rough glass", params(Color(0.9, 0.8, 1), 0, 0.5, 0.5, 1, 1.45)},
        {"half glass", params(Color(1, 1, 1), 0.2, 0.3, 0.5, 0.6, 1.5)},
    };
    // Directions: wo from outside and from inside; wi around the mirror, elsewhere on wo's
    // side, and (for the glass) near the refracted direction on the other side.
    const Vec3 outside = dir_from(35, 0.3), inside = dir_from(150, 0.3);
    const Vec3 wis_out[] = {dir_from(38, 0.3 + kPi), dir_from(20, 1.5), dir_from(80, 2.0),
                            dir_from(160, 0.3 + kPi), dir_from(145, 0.5 + kPi)};
    const Vec3 wis_in[] = {dir_from(145, 0.3 + kPi), dir_from(120, 1.0), dir_from(40, 0.3 + kPi),
                           dir_from(50, 0.1 + kPi)};
    int checked = 0;
    for (const Material& mt : mats) {
        const Bsdf b = Bsdf::principled(mt.p);
        auto check = [&](const Vec3& wo, const Vec3& wi) {
            const Color want = cycles::eval(mt.p, wo, wi), got = b.eval(wo, wi);
            SCOPED_TRACE(mt.name + " wo.z " + std::to_string(wo.z) + " wi.z " +
                         std::to_string(wi.z));
            for (int k = 0; k < 3; ++k) {
                const double w = k == 0 ? want.r : k == 1 ? want.g : want.b;
                const double g = k == 0 ? got.r : k == 1 ? got.g : got.b;
                EXPECT_NEAR(g, w, 1e-9 * std::max(1.0, std::fabs(w))) << "channel " << k;
            }
            if (want.max() > 0) ++checked;
        };
        for (const Vec3& wi : wis_out) check(outside, wi);
        if (mt.p.transmission > 0)
            for (const Vec3& wi : wis_in) check(inside, wi);
    }
    EXPECT_EQ(checked, 36);  // every non-zero value: 6 x 3 reflections, 2 glasses x 9
}

TEST(PathBsdf, BurleyFurnaceIsCyclesValue) {
    // Burley's diffuse reflects, at normal incidence, 1 - (1/2)(1/21) = 41/42 of the light and
    // 5 r / 84 more by retro-reflection (the integrals of (1 - mu)^5 mu (1 + r (1 + mu)) over
    // the hemisphere); Cycles' Principled BSDF with specular 0 is that lobe alone.
    for (double r : {0.0, 0.5, 1.0}) {
        const Bsdf b = Bsdf::principled(params(Color(1, 1, 1), 0, r, 0, 0));
        const Estimate s = by_sampling(b, Vec3(0, 0, 1), 1 << 16, 8, nullptr);
        const Estimate u = by_uniform(b, Vec3(0, 0, 1), 1 << 18, 12);
        const double want = 41.0 / 42.0 + 5.0 * r / 84.0;
        EXPECT_NEAR(s.mean, want, 3 * s.stderr_ + 1e-4) << r;
        EXPECT_NEAR(u.mean, want, 3 * u.stderr_ + 1e-4) << r;
    }
    // The Lambert model of POV-Ray and non-Principled MTL materials: exactly base / pi.
    const Bsdf l = Bsdf::principled(params(Color(0.5, 0.25, 1), 0, 0.7, 0, 0, 1.5,
                                           DiffuseModel::Lambert));
    const Color f = l.eval(dir_from(70), dir_from(10, 2));
    EXPECT_NEAR(f.r, 0.5 / kPi, 1e-15);
    EXPECT_NEAR(f.b, 1.0 / kPi, 1e-15);
}

TEST(PathBsdf, ExtremeParametersStayFinite) {
    for (double rough : {0.0, 1e-3, 0.0316, 0.05, 1.0})
        for (double tr : {0.0, 1.0})
            for (double ior : {1.0, 1.0001, 2.4, 100.0}) {
                const Bsdf b = Bsdf::principled(params(Color(1, 1, 1), 0, rough, 0.5, tr, ior));
                for (double theta : {0.0, 1e-7, 45.0, 89.9999, 90.0, 135.0, 180.0}) {
                    const Vec3 wo = dir_from(theta);
                    for (uint32_t i = 0; i < 64; ++i) {
                        const Sample2 d = PixelSampler(1, 2, i, 3).get2(2);
                        BsdfSample bs;
                        if (!b.sample(wo, d.u, d.v, &bs)) continue;
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

TEST(PathPbrMapping, DiffuseModelFollowsTheSource) {
    // The Cycles spheres scene's MTL: Blender wrote Ps/Pc/Pcr/aniso for its Principled
    // materials and Pr/Pm alone for the floor's Diffuse BSDF.
    scene::Scene s;
    Diagnostics diag;
    const obj::ObjImport im = obj::import_obj(
        std::string(GLINT_SOURCE_DIR) + "/tests/cycles/scenes/spheres.obj", s, Transform{}, -1,
        diag);
    int principled = 0, lambert = 0;
    for (int i = im.first_material; i < im.first_material + im.material_count; ++i) {
        const scene::Pbr& p = s.materials[static_cast<size_t>(i)].pbr;
        const bool floor = p.base_color == Color(0.5, 0.5, 0.5) && p.specular == 0;
        EXPECT_EQ(p.principled, !floor);
        const SurfacePbr surf = pbr_surface(p, p.base_color);
        EXPECT_EQ(surf.bsdf.diffuse_model, floor ? DiffuseModel::Lambert : DiffuseModel::Burley);
        ++(floor ? lambert : principled);
    }
    EXPECT_EQ(lambert, 1);
    EXPECT_EQ(principled, 7);
    // POV-Ray finishes are Lambert whatever they carry.
    scene::Finish f;
    f.phong = 1;
    EXPECT_EQ(pov_to_pbr(f, scene::Interior{}, scene::ColorFT(Color(1, 1, 1))).bsdf.diffuse_model,
              DiffuseModel::Lambert);
}

TEST(PathPbrMapping, PovSubsurfaceBecomesARandomWalkOfTheDiffusionLength) {
    scene::Finish f;
    f.subsurface = true;
    f.translucency = Color(2, 1, 0.5);  // mm
    scene::Interior in;
    in.ior = 1.45;
    const scene::ColorFT pigment(Color(0.8, 0.5, 0.1));
    // Off without global_settings' subsurface (mm_per_unit 0): plain Lambert.
    SurfacePbr off = pov_to_pbr(f, in, pigment);
    EXPECT_TRUE(off.subsurface_radius.is_black());
    EXPECT_TRUE(off.bsdf.diffuse_lobe);
    // On, 40 mm per unit: the BSSRDF replaces the diffuse lobe, its radius the diffusion
    // length 1 / sqrt(3 sigma_a sigma'_t) of the classic renderer's coefficients, in units.
    SurfacePbr on = pov_to_pbr(f, in, pigment, 40);
    EXPECT_FALSE(on.bsdf.diffuse_lobe);
    const SsltCoefficients k(f.translucency, on.bsdf.base, 1.45);
    EXPECT_NEAR(on.subsurface_radius.g,
                1 / (std::sqrt(3 * k.sigma_a.g * k.sigma_prime_t.g) * 40), 1e-12);
    // A darker channel diffuses less far.
    EXPECT_GT(on.subsurface_radius.r, on.subsurface_radius.b);
}

TEST(PathPbrMapping, PovFinishesMapAsDocumented) {
    scene::Finish f;
    scene::Interior in;
    // Plain POV-Ray diffuse: Lambert in the pigment color, no highlight.
    SurfacePbr s = pov_to_pbr(f, in, scene::ColorFT(Color(0.2, 0.4, 0.6)));
    EXPECT_EQ(s.bsdf.base, Color(0.2, 0.4, 0.6));
    EXPECT_EQ(s.bsdf.specular, 0);
    EXPECT_EQ(s.alpha, 1);
    // Phong highlight: the modified Phong lobe with ks = phong, n = phong_size, and the
    // diffuse albedo held at 1 - ks; no GGX lobe.
    f.phong = 0.4;
    f.phong_size = 40;
    s = pov_to_pbr(f, in, scene::ColorFT(Color(1, 0.5, 0.2)));
    EXPECT_EQ(s.bsdf.phong_ks, Color(0.4, 0.4, 0.4));
    EXPECT_EQ(s.bsdf.phong_exponent, 40);
    EXPECT_EQ(s.bsdf.specular, 0);
    EXPECT_NEAR(s.bsdf.base.r, 0.6, 1e-15);
    EXPECT_EQ(s.bsdf.base.g, 0.5);
    {
        // The BSDF it builds is exactly Bsdf::phong(kd, ks, n).
        const Bsdf a = Bsdf::principled(s.bsdf);
        const Bsdf b = Bsdf::phong(s.bsdf.base, s.bsdf.phong_ks, 40);
        const Vec3 wo = normalize(Vec3(0.3, -0.2, 0.9));
        for (const Vec3& wi : {normalize(Vec3(-0.3, 0.2, 0.9)), normalize(Vec3(0.5, 0.1, 0.4)),
                               normalize(Vec3(-0.25, 0.2, 0.95))}) {
            const Color fa = a.eval(wo, wi), fb = b.eval(wo, wi);
            EXPECT_NEAR(fa.r, fb.r, 1e-12);
            EXPECT_NEAR(fa.g, fb.g, 1e-12);
            EXPECT_NEAR(a.pdf(wo, wi), b.pdf(wo, wi), 1e-12);
        }
    }
    // Blinn `specular` with `roughness`: GGX of the same width, specular 0.5 .. 1.
    f.phong = 0;
    f.specular = 1;
    f.roughness = 1.0 / 40;
    s = pov_to_pbr(f, in, scene::ColorFT(Color(1, 1, 1)));
    EXPECT_NEAR(s.bsdf.roughness, std::sqrt(std::sqrt(2.0 / 42.0)), 1e-12);
    EXPECT_EQ(s.bsdf.specular, 1.0);
    EXPECT_EQ(s.bsdf.phong_ks, Color(0, 0, 0));
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
