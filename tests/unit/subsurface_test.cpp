// Subsurface scattering (render/bsdf/bssrdf.h, render/media/subsurface.h): the random walk
// under a flat half-space gives back the surface albedo it was set up for (what Cycles'
// albedo-to-medium fits promise), with and without anisotropy; the walk stays in its own
// object; the BSSRDF's setup moves channels of too small a radius to diffuse; a closure set
// picks the BSSRDF by its share; the exit lobe and the retro-reflection lobe keep energy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "core/log.h"
#include "render/bsdf/closure_set.h"
#include "render/media/subsurface.h"
#include "render/prepare/prepared_scene.h"
#include "unit/pov_test_util.h"

namespace glint {
namespace {

using render::Bssrdf;
using render::Hit;

struct Walks {
    Color mean, stderr_;
    double exit_distance = 0;  // mean distance from the entry to the exit
};

// Walks into the top face (z = 0) of a parsed scene's first object, from the origin.
struct Walker {
    std::unique_ptr<render::PreparedScene> prepared;
    Hit entry;
    std::mt19937_64 rng;
    std::uniform_real_distribution<double> u{0, 1};
    uint64_t rays = 0;

    Walker(const std::string& pov, uint64_t seed) : rng(seed) {
        scene::Scene s = pov::testing::parse(pov);
        Diagnostics diag;
        render::RenderOptions opts;
        opts.integrator = render::IntegratorKind::Path;
        prepared = render::prepare(s, opts, diag);
        entry.p_error = Vec3(1e-12, 1e-12, 1e-12);
        entry.ng = entry.n = Vec3(0, 0, 1);
        entry.object = 0;
    }
    // One walk, its throughput starting at the albedo (which the walk divides out again).
    bool next(const Bssrdf& b, Color* beta, Hit* exit, Vec3* dir) {
        *beta = b.albedo;
        const std::function<double()> random = [this] { return u(rng); };
        return render::subsurface_walk(*prepared->geometry, b, entry, Vec3(0, 0, 1), random,
                                       beta, exit, dir, &rays);
    }
};

// `n` walks: the mean throughput where they leave (0 for lost ones) and how far they go.
Walks walk(const std::string& pov, const Bssrdf& b, int n, uint64_t seed = 1) {
    Walker walker(pov, seed);
    Color sum, sum2;
    double dist = 0;
    for (int i = 0; i < n; ++i) {
        Color beta;
        Hit exit;
        Vec3 dir;
        if (!walker.next(b, &beta, &exit, &dir)) beta = Color();
        else dist += length(exit.p - walker.entry.p);
        sum += beta;
        sum2 += beta * beta;
    }
    Walks w;
    w.mean = sum / n;
    const Color var = sum2 / n - w.mean * w.mean;
    w.stderr_ = Color(std::sqrt(var.r / n), std::sqrt(var.g / n), std::sqrt(var.b / n));
    w.exit_distance = dist / n;
    return w;
}

Bssrdf bssrdf(const Color& albedo, const Color& radius, double g, bool fixed = false) {
    Bssrdf b;
    b.weight = albedo;
    b.albedo = albedo;
    b.radius = radius;
    b.anisotropy = g;
    b.n = Vec3(0, 0, 1);
    Color diffuse;
    b.setup(fixed, 1.4, &diffuse);
    return b;
}

const char* kHalfSpace = "box { <-100, -100, -100> <100, 100, 0> }";

// The same half-space by the plainest walk there is (no guiding, no channel sampling): free
// flights of the medium's extinction, absorption as a weight, Henyey-Greenstein turns, and
// after nine bounces the isotropic medium of the similarity relation the walk also switches
// to; one channel. Its mean reflectance is what subsurface_walk must estimate.
double analog_reflectance(double albedo, double d, double g, int n, uint64_t seed) {
    double sigma_t, alpha;
    render::subsurface_coefficients(albedo, d, g, &sigma_t, &alpha);
    double scale = 1;
    if (alpha < 0.2) scale = alpha / 0.2, alpha = 0.2;
    const double sigma_t_iso = sigma_t * (1 - alpha * g);
    const double alpha_iso = alpha * (1 - g) / (1 - alpha * g);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
        const double r0 = std::sqrt(u(rng)), phi0 = 2 * kPi * u(rng);
        Vec3 d_(r0 * std::cos(phi0), r0 * std::sin(phi0), -std::sqrt(1 - r0 * r0));
        double z = 0, w = scale;
        for (int bounce = 0; bounce < render::kSubsurfaceMaxBounces && w > 1e-9; ++bounce) {
            const bool iso = bounce > 9;
            const double st = iso ? sigma_t_iso : sigma_t;
            z += d_.z * -std::log(1 - u(rng)) / st;
            if (z >= 0) {
                sum += w;
                break;
            }
            w *= iso ? alpha_iso : alpha;
            const double gb = iso ? 0.0 : g;
            double c;
            if (std::fabs(gb) < 1e-3) {
                c = 1 - 2 * u(rng);
            } else {
                const double k = (1 - gb * gb) / (1 - gb + 2 * gb * u(rng));
                c = (1 + gb * gb - k * k) / (2 * gb);
            }
            const double s = std::sqrt(std::max(0.0, 1 - c * c)), ph = 2 * kPi * u(rng);
            const render::Frame f = render::Frame::from_normal(d_);
            d_ = normalize(f.to_world(Vec3(s * std::cos(ph), s * std::sin(ph), c)));
        }
    }
    return sum / n;
}

TEST(Subsurface, GuidedWalkAgreesWithAnalogWalk) {
    for (double g : {0.0, 0.5}) {
        const Bssrdf b = bssrdf(Color(0.2, 0.5, 0.85), Color(0.1, 0.1, 0.1), g);
        const Walks w = walk(kHalfSpace, b, 100000, 11);
        const double a[3] = {analog_reflectance(0.2, b.radius.r, g, 400000, 5),
                             analog_reflectance(0.5, b.radius.g, g, 400000, 6),
                             analog_reflectance(0.85, b.radius.b, g, 400000, 7)};
        std::printf("g %.1f: walk %.4f %.4f %.4f (+- %.4f %.4f %.4f), analog %.4f %.4f %.4f\n",
                    g, w.mean.r, w.mean.g, w.mean.b, w.stderr_.r, w.stderr_.g, w.stderr_.b,
                    a[0], a[1], a[2]);
        // (The analog estimate's own standard error is under 0.001.)
        EXPECT_NEAR(w.mean.r, a[0], 4 * (w.stderr_.r + 0.001)) << "g " << g;
        EXPECT_NEAR(w.mean.g, a[1], 4 * (w.stderr_.g + 0.001)) << "g " << g;
        EXPECT_NEAR(w.mean.b, a[2], 4 * (w.stderr_.b + 0.001)) << "g " << g;
    }
}

// Cycles maps a surface albedo to the medium whose half-space reflects that much light back
// out under diffuse incidence (Chiang et al. 2016's fit, within 1.5% for isotropic media;
// with anisotropy it drifts: g = 0.5 reflects 0.91 for 0.85, in Cycles as here).
TEST(Subsurface, HalfSpaceReflectsTheAlbedo) {
    const Bssrdf b = bssrdf(Color(0.2, 0.5, 0.85), Color(0.1, 0.1, 0.1), 0);
    const Walks w = walk(kHalfSpace, b, 40000);
    EXPECT_NEAR(w.mean.r, 0.2, 0.03 * 0.2 + 4 * w.stderr_.r);
    EXPECT_NEAR(w.mean.g, 0.5, 0.03 * 0.5 + 4 * w.stderr_.g);
    EXPECT_NEAR(w.mean.b, 0.85, 0.03 * 0.85 + 4 * w.stderr_.b);
}

// The radius sets how far light travels: ten times the radius, about ten times as far.
TEST(Subsurface, ExitDistanceScalesWithTheRadius) {
    const Walks near = walk(kHalfSpace, bssrdf(Color(0.8, 0.8, 0.8), Color(0.01), 0), 4000);
    const Walks far = walk(kHalfSpace, bssrdf(Color(0.8, 0.8, 0.8), Color(0.1), 0), 4000);
    EXPECT_GT(near.exit_distance, 0);
    EXPECT_NEAR(far.exit_distance / near.exit_distance, 10, 1.5);
}

// A thin slab lets light through: the walk leaves by the far face too, and a box beside the
// object (another object) is not seen by it.
TEST(Subsurface, WalkSeesOnlyItsObject) {
    const std::string slab =
        "box { <-100, -100, -0.05> <100, 100, 0> }\n"
        "box { <-100, -100, -0.03> <100, 100, -0.02> }";  // inside the slab, another object
    const Bssrdf b = bssrdf(Color(0.9, 0.9, 0.9), Color(0.2, 0.2, 0.2), 0);
    Walker walker(slab, 3);
    int through = 0, back = 0;
    for (int i = 0; i < 2000; ++i) {
        Color beta;
        Hit exit;
        Vec3 dir;
        if (!walker.next(b, &beta, &exit, &dir)) continue;
        EXPECT_EQ(exit.object, 0);
        if (exit.p.z < -0.04) {
            ++through;
            EXPECT_LT(dir.z, 0);  // leaving by the bottom face, downwards
        } else {
            ++back;
            EXPECT_NEAR(exit.p.z, 0, 1e-9);
            EXPECT_GT(dir.z, 0);
        }
    }
    EXPECT_GT(through, 100);
    EXPECT_GT(back, 100);
}

TEST(Subsurface, SetupMovesTinyRadiiToDiffuse) {
    Bssrdf b;
    b.weight = Color(0.5, 0.4, 0.3);
    b.albedo = Color(0.8, 0.8, 0.8);
    b.radius = Color(1, 0, 1e-9);
    Color diffuse;
    EXPECT_EQ(b.setup(true, 1.4, &diffuse), 1);
    EXPECT_EQ(diffuse.r, 0);
    EXPECT_DOUBLE_EQ(diffuse.g, 0.4);
    EXPECT_DOUBLE_EQ(diffuse.b, 0.3);
    EXPECT_DOUBLE_EQ(b.weight.r, 0.5);
    EXPECT_EQ(b.weight.g, 0);
    EXPECT_NEAR(b.radius.r, 0.25 / kPi, 1e-12);  // fixed radius: 1 / (4 pi)
    EXPECT_NEAR(b.sample_weight(), 0.5 / 3, 1e-12);
    // The albedo-adjusted radius shrinks as the albedo falls (less light comes back from
    // deep inside) and is at most sqrt(3).
    Bssrdf lo = bssrdf(Color(0.1), Color(1), 0), hi = bssrdf(Color(0.9), Color(1), 0);
    EXPECT_GT(lo.radius.r, hi.radius.r);
    EXPECT_LE(lo.radius.r, std::sqrt(3.0));
    EXPECT_GT(hi.radius.r, 0);
}

TEST(Subsurface, ClosureSetPicksTheBssrdfByItsShare) {
    render::ClosureSet set(Vec3(0, 0, 1), Vec3(0, 0, 1));
    set.add(render::Bsdf::lambert(Color(1, 1, 1)), Color(0.3, 0.3, 0.3), Vec3(0, 0, 1), 0.3);
    Bssrdf b = bssrdf(Color(0.6, 0.6, 0.6), Color(0.1), 0);
    set.add(b);  // share 0.6 x 3 channels
    EXPECT_EQ(set.count(), 2);
    int picked = 0;
    const int n = 1000;
    for (int i = 0; i < n; ++i) {
        render::ClosureSample cs;
        ASSERT_TRUE(set.sample((i + 0.5) / n, 0.37, &cs));
        if (!cs.bssrdf) continue;
        ++picked;
        // Its weight over the pick's probability 1.8 / 2.1.
        EXPECT_NEAR(cs.weight.r, 0.6 * 2.1 / 1.8, 1e-9);
    }
    EXPECT_NEAR(picked / double(n), 1.8 / 2.1, 0.002);
    // The BSSRDF adds nothing to light sampling, but dilutes the mixture's pdf.
    double pdf = 0;
    const Color f = set.eval(normalize(Vec3(0.3, 0.1, 1)), &pdf);
    const double cos = normalize(Vec3(0.3, 0.1, 1)).z;
    EXPECT_NEAR(f.r, 0.3 * cos / kPi, 1e-9);
    EXPECT_NEAR(pdf, 0.3 / 2.1 * cos / kPi, 1e-9);
}

// Hemispherical reflectance of a lobe for light from `wo`, by quadrature in the local frame.
double albedo_of(const render::Lobe& lobe, const Vec3& wo) {
    double sum = 0;
    const int n = 400;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double z = (i + 0.5) / n, phi = 2 * kPi * (j + 0.5) / n;
            const double r = std::sqrt(1 - z * z);
            double pdf;
            sum += lobe.eval(wo, Vec3(r * std::cos(phi), r * std::sin(phi), z), &pdf).r;
        }
    return sum * 2 * kPi / (n * n);
}

TEST(Subsurface, ExitAndRetroReflectionLobes) {
    // Lambert x (1 - 0.5 (1 - cos)^5): 1 - 0.5 x 2 / 42 = 1 - 1/42 whatever the view.
    EXPECT_NEAR(albedo_of(render::Lobe::subsurface_exit(), Vec3(0, 0, 1)), 1 - 1.0 / 42, 1e-4);
    EXPECT_NEAR(albedo_of(render::Lobe::subsurface_exit(), normalize(Vec3(1, 0, 0.2))),
                1 - 1.0 / 42, 1e-4);
    // Retro-reflection is nothing for a smooth surface, and grows with roughness and grazing.
    const Vec3 graze = normalize(Vec3(1, 0, 0.3));
    EXPECT_NEAR(albedo_of(render::Lobe::retro_reflection(0), graze), 0, 1e-12);
    EXPECT_GT(albedo_of(render::Lobe::retro_reflection(1), graze),
              albedo_of(render::Lobe::retro_reflection(0.5), graze));
    EXPECT_GT(albedo_of(render::Lobe::retro_reflection(1), graze),
              albedo_of(render::Lobe::retro_reflection(1), Vec3(0, 0, 1)));
    // Sampling agrees with eval.
    render::BsdfSample bs;
    ASSERT_TRUE(render::Lobe::subsurface_exit().sample(Vec3(0, 0, 1), 0.3, 0.6, &bs));
    double pdf;
    const Color f = render::Lobe::subsurface_exit().eval(Vec3(0, 0, 1), bs.wi, &pdf);
    EXPECT_NEAR(bs.weight.r, f.r / pdf, 1e-12);
    EXPECT_TRUE(bs.diffuse);
}

}  // namespace
}  // namespace glint
