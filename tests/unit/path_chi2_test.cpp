// VALIDATION.md case 13: chi-square goodness-of-fit tests of each BSDF's sample() against its
// pdf() (Lambert; modified Phong n = 1 .. 1e5; GGX alpha = 1e-3 .. 1 as Principled metal,
// dielectric reflection over a diffuse base, and rough dielectric transmission; the smooth
// dielectric's discrete reflect/refract choice against Fresnel; Blender's single lobes:
// Oren-Nayar, Translucent, both Toons, Velvet, sheen, clearcoat, Beckmann, anisotropic GGX and
// Beckmann, Ashikhmin-Shirley, microfacet refraction), with the Sidak correction
// over every test of the file at a family-wise significance of 0.01. Each configuration also
// checks energy: the mean of f |cos| / pdf equals the integral of f |cos| over the same bins
// (so sampling is unbiased), and it is at most 1.01 without a diffuse lobe (Cycles adds
// Principled's Burley diffuse to the reflection without Fresnel layering, so a white
// dielectric reflects a little more than 1); and that sample()'s weight and pdf are
// eval |cos| / pdf and pdf(). Fixed seeds: the outcome is the same on every run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "chi2.h"
#include "render/bsdf/bsdf.h"
#include "render/bsdf/lobe.h"

namespace glint::render {
namespace {

// A Bsdf or a single Lobe behind one interface: f (without the cosine), pdf and sample.
struct Model {
    Model(const Bsdf& b) : is_lobe(false), bsdf(b) {}  // NOLINT: implicit on purpose
    Model(const Lobe& l) : is_lobe(true), lobe(l) {}   // NOLINT
    bool is_lobe;
    Bsdf bsdf;
    Lobe lobe;
    Color eval(const Vec3& wo, const Vec3& wi) const {
        if (!is_lobe) return bsdf.eval(wo, wi);
        double p;
        const Color fc = lobe.eval(wo, wi, &p);
        return wi.z != 0 ? fc * (1 / std::fabs(wi.z)) : Color();
    }
    double pdf(const Vec3& wo, const Vec3& wi) const {
        if (!is_lobe) return bsdf.pdf(wo, wi);
        double p;
        lobe.eval(wo, wi, &p);
        return p;
    }
    bool sample(const Vec3& wo, double u1, double u2, BsdfSample* out) const {
        return is_lobe ? lobe.sample(wo, u1, u2, out) : bsdf.sample(wo, u1, u2, out);
    }
    bool all_delta() const { return is_lobe ? lobe.delta() : bsdf.all_delta(); }
};

constexpr int kSamples = 1 << 17;
constexpr double kFamilyAlpha = 0.01;

double sqr(double v) { return v * v; }

enum class Axis { Normal, Mirror, Refract };

struct Config {
    std::string name;
    Model bsdf;
    double theta_o;  // degrees from the normal; > 90: from inside
    Axis axis;
    double width;  // angular width of the lobe (radians); >= 0.5: cos-uniform bins
    double eta = 1.5;
    double max_energy = 1.01;  // bound on the mean weight (a diffuse lobe adds to reflection)
    // Toon: sample() weighs as Cycles does, not by eval / pdf (lobe.cpp); only the directions
    // are tested against the pdf.
    bool cycles_weight = false;
};

Vec3 dir_from(double theta_deg, double phi = 0.3) {
    const double t = theta_deg * kPi / 180;
    return {std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t)};
}

// The smooth refraction of wo through the plane z = 0 (eta: inside over outside index), or
// the mirror direction under total internal reflection.
Vec3 refracted(const Vec3& wo, double eta) {
    const double e = wo.z > 0 ? eta : 1.0 / eta;
    const double c = std::fabs(wo.z);
    const double s2 = (1 - c * c) / (e * e);
    if (s2 >= 1) return {-wo.x, -wo.y, wo.z};
    const Vec3 n(0, 0, wo.z > 0 ? 1.0 : -1.0);
    return normalize(-wo / e + n * (c / e - std::sqrt(1 - s2)));
}

PrincipledParams principled(Color base, double metallic, double alpha, double transmission,
                            double ior = 1.5) {
    PrincipledParams p;
    p.base = base;
    p.metallic = metallic;
    // Just above sqrt(alpha) so that alpha = 1e-3 stays a (very sharp) GGX lobe.
    p.roughness = std::min(1.0, std::sqrt(alpha) * (1 + 1e-9));
    p.specular = 0.5;
    p.transmission = transmission;
    p.ior = ior;
    return p;
}

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::vector<Config> configs() {
    std::vector<Config> out;
    for (double th : {30.0, 70.0})
        out.push_back({"lambert", Bsdf::lambert(Color(1, 1, 1)), th, Axis::Normal, 1.0});
    for (double n : {1.0, 10.0, 100.0, 1e3, 1e4, 1e5})
        for (double th : {30.0, 70.0}) {
            const Color kd = n == 1.0 ? Color(0.5, 0.5, 0.5) : Color(0, 0, 0);
            const Color ks = n == 1.0 ? Color(0.5, 0.5, 0.5) : Color(1, 1, 1);
            out.push_back({"phong n " + num(n), Bsdf::phong(kd, ks, n), th, Axis::Mirror,
                           std::min(1.0, 1.0 / std::sqrt(n + 1))});
        }
    for (double a : {1e-3, 1e-2, 0.1, 0.3, 1.0})
        for (double th : {30.0, 70.0}) {
            out.push_back({"ggx metal alpha " + num(a),
                           Bsdf::principled(principled(Color(1, 1, 1), 1, a, 0)), th,
                           Axis::Mirror, std::min(1.0, 2 * a)});
            // Burley's white diffuse (up to ~1.04, more at grazing angles) plus the reflection.
            out.push_back({"ggx dielectric reflection alpha " + num(a),
                           Bsdf::principled(principled(Color(1, 1, 1), 0, a, 0)), th,
                           Axis::Mirror, std::min(1.0, 2 * a), 1.5, 1.2});
        }
    // Rough glass, from outside and from inside (150: refracts; 125: beyond the critical
    // angle of 41.8 degrees, total internal reflection of the mean direction).
    for (double a : {1e-3, 1e-2, 0.1, 0.3, 1.0})
        for (double th : {30.0, 70.0, 150.0, 125.0})
            out.push_back({"ggx glass alpha " + num(a),
                           Bsdf::principled(principled(Color(1, 1, 1), 0, a, 1)), th,
                           Axis::Refract, std::min(1.0, a), 1.5});
    for (double th : {20.0, 60.0, 160.0})
        out.push_back({"ggx glass ior 2.4 alpha 0.05",
                       Bsdf::principled(principled(Color(1, 1, 1), 0, 0.05, 1, 2.4)), th,
                       Axis::Refract, 0.05, 2.4});
    // Every lobe at once, in colour: diffuse, GGX reflection, metal and rough transmission
    // mixed by Principled's weights (lobe choice then depends on wo's Fresnel).
    for (double th : {30.0, 70.0, 150.0}) {
        PrincipledParams p = principled(Color(0.9, 0.5, 0.2), 0.3, 0.05, 0.4);
        p.specular = 0.8;
        out.push_back({"principled mix alpha 0.05", Bsdf::principled(p), th, Axis::Refract,
                       0.05, 1.5, 1.2});
    }
    // Blender's other BSDFs (render/bsdf/lobe.h), each about its own axis.
    for (double th : {30.0, 70.0}) {
        for (double r : {0.3, 1.0})
            out.push_back({"oren-nayar sigma " + num(r), Lobe::oren_nayar(r), th, Axis::Normal, 1.0});
        out.push_back({"translucent", Lobe::translucent(), th, Axis::Normal, 1.0});
        out.push_back({"diffuse toon", Lobe::toon(false, 0.5, 0.2), th, Axis::Normal, 1.0, 1.5,
                       1.01, true});
        out.push_back({"glossy toon", Lobe::toon(true, 0.1, 0.1), th, Axis::Mirror, 0.3, 1.5,
                       1.01, true});
        out.push_back({"velvet sigma 0.5", Lobe::velvet(0.5), th, Axis::Normal, 1.0, 1.5, 2.0});
        out.push_back({"sheen", Lobe::sheen(), th, Axis::Normal, 1.0});
        for (double r : {0.03, 0.3})
            out.push_back({"clearcoat roughness " + num(r), Lobe::clearcoat(1, r), th,
                           Axis::Mirror, std::max(0.05, r * r)});
        for (double a : {0.01, 0.2}) {
            out.push_back({"beckmann alpha " + num(a),
                           Lobe::reflection(Microfacet{Microfacet::Kind::Beckmann, a, a}), th,
                           Axis::Mirror, std::min(1.0, 2 * a)});
            out.push_back({"anisotropic ggx alpha " + num(a) + " x 4",
                           Lobe::reflection(Microfacet{Microfacet::Kind::GGX, a, 4 * a}), th,
                           Axis::Mirror, std::min(1.0, 8 * a)});
            out.push_back({"anisotropic beckmann alpha " + num(a) + " x 3",
                           Lobe::reflection(Microfacet{Microfacet::Kind::Beckmann, 3 * a, a}),
                           th, Axis::Mirror, std::min(1.0, 6 * a)});
            out.push_back({"ashikhmin-shirley alpha " + num(a), Lobe::ashikhmin_shirley(a, a),
                           th, Axis::Mirror, std::min(1.0, 2 * a), 1.5, 1.2});
            out.push_back({"ashikhmin-shirley alpha " + num(a) + " x 3",
                           Lobe::ashikhmin_shirley(a, 3 * a), th, Axis::Mirror,
                           std::min(1.0, 6 * a), 1.5, 1.2});
        }
    }
    for (double a : {0.01, 0.2})
        for (double th : {30.0, 150.0}) {
            out.push_back({"ggx refraction alpha " + num(a),
                           Lobe::refraction(Microfacet::ggx(a), 1.5), th, Axis::Refract,
                           std::min(1.0, 2 * a), 1.5, 1.2});
            out.push_back({"beckmann refraction alpha " + num(a),
                           Lobe::refraction(Microfacet{Microfacet::Kind::Beckmann, a, a}, 1.5),
                           th, Axis::Refract, std::min(1.0, 2 * a), 1.5, 1.2});
        }
    // The Principled model with its newer inputs: anisotropy, specular tint, a Beckmann
    // glass with its own transmission roughness.
    for (double th : {30.0, 70.0}) {
        PrincipledParams p = principled(Color(0.9, 0.5, 0.2), 0.5, 0.04, 0);
        p.anisotropic = 0.8;
        p.specular_tint = 0.7;
        out.push_back({"principled anisotropic tinted", Bsdf::principled(p), th, Axis::Mirror,
                       0.5, 1.5, 1.2});
        PrincipledParams g = principled(Color(1, 1, 1), 0, 0.01, 1);
        g.glass_distribution = Microfacet::Kind::Beckmann;
        g.transmission_roughness = 0.5;
        g.specular_tint = 0.5;
        out.push_back({"beckmann glass frosted", Bsdf::principled(g), th + 100, Axis::Refract,
                       0.1, 1.5});
    }
    return out;
}

struct SmoothCase {
    double ior, theta_o;
};
std::vector<SmoothCase> smooth_cases() {
    std::vector<SmoothCase> out;
    for (double ior : {1.0001, 1.33, 1.5, 2.4, 100.0})
        for (double th : {0.0, 60.0, 85.0, 150.0, 110.0}) out.push_back({ior, th});
    return out;
}

// One significance level for every test in this file.
double per_test_alpha() {
    static const int tests = static_cast<int>(configs().size() + smooth_cases().size());
    return chi2::sidak(kFamilyAlpha, tests);
}

struct Outcome {
    chi2::Result chi2;
    double mean_weight = 0, weight_stderr = 0;
    double energy = 0;  // the integral of f |cos| (channel mean) over the sphere
    double max_weight_err = 0, max_pdf_err = 0;
    long delta_samples = 0;
    double failed = 0, expected_failed = 0;
};

// Samples kSamples directions with sample(), bins them, and compares with `density`
// integrated over the bins. Axis::Refract (a dielectric with two sharp lobes) bins the side
// of wo around the mirror direction and the other side around the refracted one, so that
// each lobe's peak sits at the pole of a fine grid and is integrated accurately.
Outcome run_chi2(const Config& c, uint64_t seed,
                 const std::function<double(const Vec3&, const Vec3&)>& density) {
    const Vec3 wo = dir_from(c.theta_o);
    const Vec3 mirror(-wo.x, -wo.y, wo.z);
    const bool broad = c.width >= 0.5;
    const int n_theta = broad ? 10 : 24, n_phi = broad ? 20 : 16;
    struct Part {
        chi2::SphereGrid grid;
        int side;  // 0: whole sphere, +1: wo's side only, -1: the other side only
    };
    std::vector<Part> parts;
    if (c.axis == Axis::Refract) {
        Vec3 t = refracted(wo, c.eta);
        if (t.z * wo.z > 0) t = Vec3(0, 0, wo.z > 0 ? -1.0 : 1.0);  // total internal reflection
        parts.push_back({chi2::SphereGrid(Frame::from_normal(mirror), n_theta, n_phi, c.width), 1});
        parts.push_back({chi2::SphereGrid(Frame::from_normal(t), n_theta, n_phi, c.width), -1});
    } else {
        const Vec3 axis = c.axis == Axis::Mirror ? mirror : Vec3(0, 0, 1);
        parts.push_back({chi2::SphereGrid(Frame::from_normal(axis), n_theta, n_phi, c.width), 0});
    }
    auto side_of = [&](const Vec3& wi) { return wi.z * wo.z > 0 ? 1 : -1; };
    auto bin_of = [&](const Vec3& wi) {
        int offset = 0;
        for (const Part& p : parts) {
            if (p.side == 0 || p.side == side_of(wi)) return offset + p.grid.bin_of(wi);
            offset += p.grid.bins();
        }
        return offset;  // not reached: the parts cover the sphere
    };
    int bins = 0;
    for (const Part& p : parts) bins += p.grid.bins();
    Outcome out;
    std::vector<double> observed(static_cast<size_t>(bins) + 1, 0.0);
    chi2::Rng rng(seed);
    double weight_sum = 0, weight_sum2 = 0;
    for (int i = 0; i < kSamples; ++i) {
        const double u1 = rng.next(), u2 = rng.next();
        BsdfSample bs;
        if (!c.bsdf.sample(wo, u1, u2, &bs)) {
            observed.back() += 1;
            continue;
        }
        if (bs.delta) {
            ++out.delta_samples;
            continue;
        }
        observed[static_cast<size_t>(bin_of(bs.wi))] += 1;
        const Color w = bs.weight;
        weight_sum += (w.r + w.g + w.b) / 3;
        weight_sum2 += sqr((w.r + w.g + w.b) / 3);
        const double p = c.bsdf.pdf(wo, bs.wi);
        const Color f = c.bsdf.eval(wo, bs.wi) * (std::fabs(bs.wi.z) / p);
        out.max_pdf_err = std::max(out.max_pdf_err, std::fabs(bs.pdf - p) / p);
        out.max_weight_err =
            std::max(out.max_weight_err, std::fabs(f.g - w.g) / std::max(std::fabs(f.g), 1e-300));
    }
    out.mean_weight = weight_sum / kSamples;
    out.weight_stderr =
        std::sqrt(std::max(0.0, weight_sum2 / kSamples - sqr(out.mean_weight)) / kSamples);
    std::vector<double> expected;
    double total = 0;
    for (const Part& p : parts) {
        for (double e : p.grid.integrate(
                 [&](const Vec3& wi) {
                     return p.side == 0 || p.side == side_of(wi) ? density(wo, wi) : 0.0;
                 },
                 1e-9)) {
            total += e;
            expected.push_back(e * kSamples);
        }
    }
    for (const Part& p : parts)
        for (double e : p.grid.integrate(
                 [&](const Vec3& wi) {
                     if (p.side != 0 && p.side != side_of(wi)) return 0.0;
                     const Color f = c.bsdf.eval(wo, wi);
                     return (f.r + f.g + f.b) / 3 * std::fabs(wi.z);
                 },
                 1e-9))
            out.energy += e;
    // Samples that found no direction: the pdf's mass missing from the sphere.
    out.failed = observed.back();
    out.expected_failed = std::max(0.0, 1 - total) * kSamples;
    expected.push_back(out.expected_failed);
    out.chi2 = chi2::chi2_test(observed, expected, kSamples);
    return out;
}

class BsdfChi2 : public ::testing::TestWithParam<size_t> {};

TEST_P(BsdfChi2, SamplingMatchesPdf) {
    static const std::vector<Config> all = configs();
    const Config& c = all[GetParam()];
    ASSERT_FALSE(c.bsdf.all_delta()) << c.name;
    const Outcome o = run_chi2(c, 1000 + GetParam(), [&](const Vec3& wo, const Vec3& wi) {
        return c.bsdf.pdf(wo, wi);
    });
    std::printf("chi2 %-44s theta_o %5.1f: chi2 %8.2f dof %3d p %.4f, failed %.0f (expected "
                "%.1f), mean f cos/pdf %.6f (integral %.6f)\n",
                c.name.c_str(), c.theta_o, o.chi2.chi2, o.chi2.dof, o.chi2.pvalue, o.failed,
                o.expected_failed, o.mean_weight, o.energy);
    SCOPED_TRACE(c.name + " theta_o " + num(c.theta_o));
    EXPECT_EQ(o.delta_samples, 0);
    EXPECT_GE(o.chi2.pvalue, per_test_alpha()) << "chi2 " << o.chi2.chi2 << " dof " << o.chi2.dof;
    EXPECT_GT(o.chi2.dof, 5);
    EXPECT_LE(o.mean_weight, c.max_energy);
    if (c.cycles_weight) return;
    EXPECT_NEAR(o.mean_weight, o.energy, 4 * o.weight_stderr + 1e-3)
        << "mean weight " << o.mean_weight << " +- " << o.weight_stderr << ", integral "
        << o.energy;
    EXPECT_LT(o.max_pdf_err, 1e-9);
    EXPECT_LT(o.max_weight_err, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Case13, BsdfChi2, ::testing::Range<size_t>(0, configs().size()));

TEST(BsdfChi2Smooth, ReflectRefractChoiceFollowsFresnel) {
    int index = 0;
    for (const SmoothCase& sc : smooth_cases()) {
        const Bsdf b = Bsdf::principled(principled(Color(1, 1, 1), 0, 0, 1, sc.ior));
        ASSERT_TRUE(b.all_delta());
        const Vec3 wo = dir_from(sc.theta_o);
        const Vec3 mirror(-wo.x, -wo.y, wo.z), refr = refracted(wo, sc.ior);
        const double F = fresnel_dielectric(wo.z, sc.ior);
        chi2::Rng rng(77 + static_cast<uint64_t>(index++));
        std::vector<double> observed(3, 0.0);  // reflected, refracted, other
        double max_weight_err = 0;
        for (int i = 0; i < kSamples; ++i) {
            const double u1 = rng.next(), u2 = rng.next();
            BsdfSample bs;
            if (!b.sample(wo, u1, u2, &bs)) {
                observed[2] += 1;
                continue;
            }
            EXPECT_TRUE(bs.delta);
            const bool is_reflect = length(bs.wi - mirror) < 1e-9 && bs.wi.z * wo.z > 0;
            const bool is_refract = length(bs.wi - refr) < 1e-9 && bs.wi.z * wo.z < 0;
            observed[is_reflect ? 0 : is_refract ? 1 : 2] += 1;
            max_weight_err = std::max(max_weight_err, std::fabs(bs.weight.g - 1.0));
            if (is_reflect) {
                EXPECT_NEAR(bs.pdf, F, 1e-12);
            } else if (is_refract) {
                EXPECT_NEAR(bs.pdf, 1 - F, 1e-12);
            }
        }
        const std::vector<double> expected = {F * kSamples, (1 - F) * kSamples, 0.0};
        const chi2::Result r = chi2::chi2_test(observed, expected, kSamples);
        // With both outcomes likely the statistic has one degree of freedom; with one of them
        // below the pooling threshold all samples must take the likely one.
        std::printf("smooth dielectric ior %g theta_o %5.1f: F %.6f, reflected %.0f refracted "
                    "%.0f other %.0f, chi2 %.3f dof %d p %.4f\n",
                    sc.ior, sc.theta_o, F, observed[0], observed[1], observed[2], r.chi2, r.dof,
                    r.pvalue);
        SCOPED_TRACE("ior " + num(sc.ior) + " theta_o " + num(sc.theta_o));
        EXPECT_EQ(observed[2], 0.0);
        EXPECT_GE(r.pvalue, per_test_alpha());
        EXPECT_LT(max_weight_err, 1e-12);
    }
}

// Toon's sampled weight is Cycles': the intensity at (cone angle) * u1, where the cone is
// size + smooth (both times 90 degrees) and the fade runs from size to size + smooth.
TEST(ToonLobe, SampledWeightIsCyclesIntensityAtConeTimesU1) {
    const Lobe toon = Lobe::toon(false, 0.4, 0.2);  // full to 36 degrees, zero from 54
    const Vec3 wo = dir_from(20);
    for (double u1 : {0.1, 0.5, 0.7, 0.8, 0.95}) {
        BsdfSample bs;
        ASSERT_TRUE(toon.sample(wo, u1, 0.3, &bs));
        const double angle = 54.0 * u1;  // degrees
        const double expect = angle < 36 ? 1.0 : 1 - (angle - 36) / 18;
        EXPECT_NEAR(bs.weight.g, expect, 1e-9) << u1;
        // The direction itself is uniform in cos within the cone, u1 = 0 at its rim.
        const double zmin = std::cos(54 * kPi / 180);
        EXPECT_NEAR(bs.wi.z, zmin + (1 - zmin) * u1, 1e-9);
        double pdf;
        toon.eval(wo, bs.wi, &pdf);
        EXPECT_NEAR(bs.pdf, pdf, 1e-12);
    }
}

TEST(BsdfChi2Method, PvaluesAndIntegrationAreRight) {
    // Tabulated chi-square quantiles: P(X > 3.841 | 1) = 0.05, P(X > 18.307 | 10) = 0.05,
    // P(X > 135.807 | 100) = 0.01.
    EXPECT_NEAR(chi2::chi2_pvalue(3.841459, 1), 0.05, 1e-6);
    EXPECT_NEAR(chi2::chi2_pvalue(18.307038, 10), 0.05, 1e-6);
    EXPECT_NEAR(chi2::chi2_pvalue(135.806723, 100), 0.01, 1e-6);
    EXPECT_NEAR(chi2::sidak(0.01, 1), 0.01, 1e-15);
    // The bin integrals of a density that integrates to 1 (Lambert; Phong n = 1e5 20 degrees
    // from the normal, which loses nothing below the horizon) add up to 1 on both grids.
    // (A sharp lobe must sit at the grid's pole, as run_chi2 arranges.)
    for (double width : {1.0, 1e-3}) {
        const Vec3 wo = dir_from(20);
        const chi2::SphereGrid g(Frame::from_normal(Vec3(-wo.x, -wo.y, wo.z)), 24, 16, width);
        const Bsdf b = width < 0.5 ? Bsdf::phong(Color(0, 0, 0), Color(1, 1, 1), 1e5)
                                   : Bsdf::lambert(Color(1, 1, 1));
        double sum = 0;
        for (double v : g.integrate([&](const Vec3& wi) { return b.pdf(wo, wi); }, 1e-9))
            sum += v;
        EXPECT_NEAR(sum, 1.0, 1e-6) << width;
    }
}

TEST(BsdfChi2Method, RejectsASlightlyWrongPdf) {
    // Negative control: Phong n = 100 sampled but judged against the pdf of n = 104 (a lobe
    // 2% narrower), and Lambert against a cos^1.05 density.
    const Config phong{"phong 100 vs 104", Bsdf::phong(Color(0, 0, 0), Color(1, 1, 1), 100), 30,
                       Axis::Mirror, 0.1};
    const Bsdf wrong = Bsdf::phong(Color(0, 0, 0), Color(1, 1, 1), 104);
    const Outcome a = run_chi2(phong, 5, [&](const Vec3& wo, const Vec3& wi) {
        return wrong.pdf(wo, wi);
    });
    std::printf("negative control phong 100 vs 104: p %.3g\n", a.chi2.pvalue);
    EXPECT_LT(a.chi2.pvalue, 1e-6);
    const Config lam{"lambert vs cos^1.05", Bsdf::lambert(Color(1, 1, 1)), 30, Axis::Normal, 1};
    const Outcome b = run_chi2(lam, 6, [](const Vec3&, const Vec3& wi) {
        return wi.z > 0 ? (2.05 / (2 * kPi)) * std::pow(wi.z, 1.05) : 0.0;
    });
    std::printf("negative control lambert vs cos^1.05: p %.3g\n", b.chi2.pvalue);
    EXPECT_LT(b.chi2.pvalue, 1e-3);
}

}  // namespace
}  // namespace glint::render

namespace glint::render {
namespace {

// Multiscatter GGX (multiscatter.h): a white surface loses nothing but what the 10-bounce walk
// cuts off, where single scattering loses a good part at high roughness; and eval(), an
// estimate, integrates to about what the walk's samples carry.
TEST(MultiGgxLobe, WhiteFurnaceAndEvalAgreeWithTheWalk) {
    for (double alpha : {0.25, 0.6, 1.0})
        for (double theta : {20.0, 60.0, 80.0}) {
            const Lobe multi = Lobe::multi_ggx(MultiGgx{alpha, alpha, false, Color(1, 1, 1)});
            const Lobe single = Lobe::reflection(Microfacet::ggx(alpha));
            const Vec3 wo = dir_from(theta);
            chi2::Rng rng(5 + static_cast<uint64_t>(alpha * 100 + theta));
            const int n = 1 << 16;
            double walk = 0, one = 0, integral = 0;
            for (int i = 0; i < n; ++i) {
                const double u1 = rng.next(), u2 = rng.next();
                BsdfSample bs;
                if (multi.sample(wo, u1, u2, &bs)) walk += bs.weight.g;
                if (single.sample(wo, u1, u2, &bs)) one += bs.weight.g;
                // The eval's integral over the hemisphere by cosine-weighted directions.
                const double r = std::sqrt(u1), phi = 2 * kPi * u2;
                const Vec3 wi(r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - u1));
                double pdf;
                integral += multi.eval(wo, wi, &pdf).g / (wi.z / kPi);
            }
            walk /= n;
            one /= n;
            integral /= n;
            SCOPED_TRACE("alpha " + num(alpha) + " theta " + num(theta));
            std::printf("multi ggx alpha %g theta %g: walk %.4f single %.4f eval integral %.4f\n", alpha, theta, walk, one, integral);
            EXPECT_GT(walk, 0.97);
            EXPECT_LE(walk, 1.0 + 1e-9);
            EXPECT_GE(walk, one);
            if (alpha == 1.0) {
                EXPECT_LT(one, 0.93);
            }
            // Measured: within 1% except at alpha >= 0.6 near normal view, where the eval
            // estimate integrates to 0.86-0.96 of the walk (alpha 1 at 20 degrees: 0.862).
            // The walks follow Cycles' mf_eval and mf_sample step by step and the add-on's
            // Z-test against Cycles passes; whether Cycles' own pair differs the same way is
            // not measured yet.
            EXPECT_NEAR(integral, walk, 0.15);
        }
}

// Walk and eval statistics of a Multiscatter GGX glass lobe for one view: what the walk's
// samples carry into each hemisphere, and the eval's integral over each (by cosine-weighted
// directions above and below); the transmission also within the directions at least as steep
// as wo (|wi.z| >= |wo.z|, where the eval walks from wo).
struct GlassStats {
    double walk_r = 0, walk_t = 0, eval_r = 0, eval_t = 0;
    double walk_t_steep = 0, eval_t_steep = 0;
    int bad = 0;  // non-finite eval, pdf or weight, or a negative one
};

GlassStats glass_stats(const Lobe& lobe, const Vec3& wo, uint64_t seed, int n) {
    GlassStats st;
    chi2::Rng rng(seed);
    const bool above = wo.z > 0;
    for (int i = 0; i < n; ++i) {
        const double u1 = rng.next(), u2 = rng.next();
        BsdfSample bs;
        if (lobe.sample(wo, u1, u2, &bs)) {
            const double w = bs.weight.g;
            if (!std::isfinite(w) || w < 0 || !std::isfinite(bs.pdf) || !(bs.pdf > 0)) ++st.bad;
            if ((bs.wi.z > 0) == above) {
                st.walk_r += w;
            } else {
                st.walk_t += w;
                if (std::fabs(bs.wi.z) >= std::fabs(wo.z)) st.walk_t_steep += w;
            }
        }
        const double r = std::sqrt(u1), phi = 2 * kPi * u2;
        const Vec3 up(r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - u1));
        for (const Vec3& wi : {up, Vec3(up.x, up.y, -up.z)}) {
            double pdf;
            const double f = lobe.eval(wo, wi, &pdf).g;
            if (!std::isfinite(f) || f < 0 || !std::isfinite(pdf) || pdf < 0) ++st.bad;
            const double v = f / (up.z / kPi);
            if ((wi.z > 0) == above) {
                st.eval_r += v;
            } else {
                st.eval_t += v;
                if (up.z >= std::fabs(wo.z)) st.eval_t_steep += v;
            }
        }
    }
    for (double* v : {&st.walk_r, &st.walk_t, &st.eval_r, &st.eval_t, &st.walk_t_steep,
                      &st.eval_t_steep})
        *v /= n;
    return st;
}

// The single-scattering glass that glint draws for a GGX Glass BSDF, for comparison.
double single_glass_albedo(double alpha, double eta, const Vec3& wo, uint64_t seed, int n) {
    PrincipledParams p;
    p.base = Color(1, 1, 1);
    p.roughness = std::sqrt(alpha);
    p.transmission = 1;
    p.ior = eta;
    const Bsdf single = Bsdf::principled(p);
    chi2::Rng rng(seed);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        BsdfSample bs;
        const double u1 = rng.next(), u2 = rng.next();
        if (single.sample(wo, u1, u2, &bs)) sum += bs.weight.g;
    }
    return sum / n;
}

// Multiscatter GGX glass (Cycles' dielectric walk): a white, clear dielectric neither absorbs
// nor loses light on the microsurface, so reflection and transmission together carry all of
// it (but for what the 10-scattering walk cuts off), from outside and from inside, where
// single scattering loses more and more with roughness.
TEST(MultiGlassLobe, WhiteFurnaceConservesEnergy) {
    const int n = 1 << 15;
    for (double alpha : {0.1, 0.3, 0.6, 1.0})
        for (double theta : {20.0, 60.0, 80.0, 120.0, 160.0}) {
            const Lobe multi = Lobe::multi_glass(MultiGlass{alpha, 1.45, Color(1, 1, 1)});
            const Vec3 wo = dir_from(theta);
            const uint64_t seed = 11 + static_cast<uint64_t>(alpha * 100 + theta);
            const GlassStats st = glass_stats(multi, wo, seed, n);
            const double walk = st.walk_r + st.walk_t;
            const double one = single_glass_albedo(alpha, 1.45, wo, seed, n);
            SCOPED_TRACE("alpha " + num(alpha) + " theta " + num(theta));
            std::printf("multi glass alpha %g theta %g: walk %.4f (R %.4f T %.4f) single %.4f\n",
                        alpha, theta, walk, st.walk_r, st.walk_t, one);
            EXPECT_EQ(st.bad, 0);
            EXPECT_LE(walk, 1.0 + 1e-9);
            EXPECT_GT(walk, 0.95);
            EXPECT_GE(walk, one - 0.005);
            if (alpha >= 0.6 && theta >= 60) {
                EXPECT_LT(one, 0.9);
                EXPECT_GT(walk - one, 0.1);
            }
        }
}

// The walk's estimate of eval() against what its samples carry, for the plain lobe and for
// the Principled BSDF's Fresnel-tinted one (white here, so it conserves energy too). Cycles
// 3.4's pair does not agree for transmission, and glint follows it: its glass phase function
// leaves out Walter's eta^2, so the single refraction that eval() computes is the walk's
// density over eta^2 (where the eval walks from the viewer: wi the steeper direction), while
// light that scattered more than once before crossing needs no such factor; and where wi is
// the shallower direction eval() walks back from wi with eta unchanged. So reflection is
// compared whole, and transmission towards steeper directions: within 8% scaled by eta^2
// where single scattering dominates (alpha 0.3; measured 1.4-6%), and between the two
// scalings at alpha 0.6 (measured: 0.55 / 0.55, 0.95 / 0.80, 0.12 / 0.13 eval x eta^2 /
// walk).
TEST(MultiGlassLobe, EvalAgreesWithTheWalk) {
    const int n = 1 << 17;
    const double ior = 1.45;
    for (bool fresnel : {false, true})
        for (double alpha : {0.3, 0.6})
            for (double theta : {20.0, 60.0, 130.0}) {
                const Lobe multi = Lobe::multi_glass(
                    MultiGlass{alpha, ior, Color(1, 1, 1), fresnel, Color(1, 1, 1)});
                const Vec3 wo = dir_from(theta);
                const double eta = wo.z > 0 ? ior : 1 / ior;
                const GlassStats st =
                    glass_stats(multi, wo, 101 + static_cast<uint64_t>(alpha * 100 + theta), n);
                SCOPED_TRACE(std::string(fresnel ? "fresnel" : "plain") + " alpha " +
                             num(alpha) + " theta " + num(theta));
                std::printf("multi glass %s alpha %g theta %g: walk R %.4f T %.4f (steep %.4f), "
                            "eval R %.4f T %.4f (steep %.4f x eta^2 = %.4f)\n",
                            fresnel ? "fresnel" : "plain", alpha, theta, st.walk_r, st.walk_t,
                            st.walk_t_steep, st.eval_r, st.eval_t, st.eval_t_steep,
                            st.eval_t_steep * eta * eta);
                EXPECT_EQ(st.bad, 0);
                EXPECT_GT(st.walk_r + st.walk_t, 0.95);
                EXPECT_NEAR(st.eval_r, st.walk_r, 0.1 * st.walk_r + 0.005);
                const double scaled = st.eval_t_steep * eta * eta;
                if (alpha < 0.5) {
                    EXPECT_NEAR(scaled, st.walk_t_steep, 0.08 * st.walk_t_steep + 0.005);
                } else {
                    const double lo = std::min(scaled, st.eval_t_steep);
                    const double hi = std::max(scaled, st.eval_t_steep);
                    EXPECT_GT(st.walk_t_steep, 0.95 * lo);
                    EXPECT_LT(st.walk_t_steep, 1.05 * hi);
                }
            }
}

// The tints as Cycles applies them in the walk: the Glass BSDF's colour on every scattering
// after the first (the first is in the closure's weight); the Principled glass's base colour
// on each refraction and its cspec0 (through the Fresnel interpolation) on each reflection.
TEST(MultiGlassLobe, TintsFollowCycles) {
    const Vec3 wo = dir_from(30);
    auto walk = [&](const MultiGlass& m, Color* r, Color* t) {
        const Lobe lobe = Lobe::multi_glass(m);
        chi2::Rng rng(77);
        const int n = 1 << 15;
        *r = Color();
        *t = Color();
        for (int i = 0; i < n; ++i) {
            BsdfSample bs;
            const double u1 = rng.next(), u2 = rng.next();
            if (lobe.sample(wo, u1, u2, &bs)) (bs.wi.z > 0 ? *r : *t) += bs.weight * (1.0 / n);
        }
    };
    Color r, t;
    // Glass BSDF of colour (1, 0.5, 0.5): mostly one scattering, so little tint; more where
    // roughness makes light scatter several times.
    walk(MultiGlass{0.3, 1.45, Color(1, 0.5, 0.5)}, &r, &t);
    const double smooth = (r.g + t.g) / (r.r + t.r);
    walk(MultiGlass{1.0, 1.45, Color(1, 0.5, 0.5)}, &r, &t);
    const double rough = (r.g + t.g) / (r.r + t.r);
    std::printf("glass tint kept: alpha 0.3 %.4f, alpha 1 %.4f\n", smooth, rough);
    EXPECT_GT(smooth, 0.9);
    EXPECT_LT(smooth, 1.0);
    EXPECT_LT(rough, smooth - 0.02);
    // Principled: base colour on refraction, white cspec0.
    walk(MultiGlass{0.3, 1.45, Color(1, 0.5, 0.5), true, Color(1, 1, 1)}, &r, &t);
    std::printf("fresnel, tinted base: R %.4f %.4f T %.4f %.4f\n", r.r, r.g, t.r, t.g);
    EXPECT_NEAR(t.g / t.r, 0.5, 0.03);
    EXPECT_GT(r.g / r.r, 0.9);
    // Principled: white base, cspec0 (1, 0.5, 0.5) on reflection (about cspec0 at 30 degrees).
    walk(MultiGlass{0.3, 1.45, Color(1, 1, 1), true, Color(1, 0.5, 0.5)}, &r, &t);
    std::printf("fresnel, tinted cspec0: R %.4f %.4f T %.4f %.4f\n", r.r, r.g, t.r, t.g);
    EXPECT_NEAR(r.g / r.r, 0.5, 0.05);
    EXPECT_GT(t.g / t.r, 0.97);
}

}  // namespace
}  // namespace glint::render
