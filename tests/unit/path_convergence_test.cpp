// VALIDATION.md case 16: the path tracer converges at the Monte Carlo rate. A tiny image of a
// scene with direct light (a rectangular area light with soft shadows), indirect light between
// a coloured sphere and a floor, and a grey environment is rendered at 16 .. 1024 spp (several
// renders with their own seeds at each) and compared with a high-spp reference; relMSE =
// mean((x - r)^2 / (r^2 + 0.01)) must fall with slope -1 +- 0.1 on log-log axes.
//
// The reference is not exact: relMSE(n) measured against a reference of N_ref samples is
// v / n + v_ref, with v_ref the reference's own variance term. The reference is the mean of K
// renders with separate seeds, so v_ref is estimated per pixel from their spread and
// subtracted before the fit. N_ref = 8 x 1024 rather than VALIDATION.md's 32k keeps the test
// near 8 s of CPU; with the subtraction the fit does not depend on N_ref (v_ref is about
// v / 8192, 12% of relMSE at 1024 spp; left in, it flattens the fitted slope by about 0.025).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/log.h"
#include "render/render.h"
#include "unit/path_test_util.h"

namespace glint::render {
namespace {

scene::Scene convergence_scene() {
    scene::Scene s;
    s.camera.location = Vec3(0, 0.6, -3.5);
    s.camera.direction = normalize(Vec3(0, -0.2, 1));
    s.camera.up = Vec3(0, 1, 0.2) * (1 / std::sqrt(1.04));
    s.background = scene::ColorFT(Color(0.15, 0.2, 0.25));
    s.materials.push_back(path_test::lambert(Color(0.8, 0.6, 0.4)));
    s.materials.push_back(path_test::lambert(Color(0.75, 0.75, 0.75)));
    scene::Object ball;
    ball.shape = scene::Sphere{Vec3(-0.3, 0, 0), 1};
    ball.material = 0;
    s.objects.push_back(ball);
    scene::Object floor;
    floor.shape = scene::Plane{Vec3(0, 1, 0), -1};
    floor.material = 1;
    s.objects.push_back(floor);
    scene::Light l;
    l.location = Vec3(2, 3, -1);
    l.color = Color(1.5, 1.5, 1.5);
    scene::AreaLight a;
    a.axis1 = Vec3(1.5, 0, 0);
    a.axis2 = Vec3(0, 0, 1.5);
    l.area = a;
    s.lights.push_back(l);
    return s;
}

constexpr int kWidth = 16, kHeight = 12;

std::vector<double> render_values(const scene::Scene& s, int spp, uint32_t seed) {
    RenderOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.integrator = IntegratorKind::Path;
    o.spp = spp;
    o.max_depth = 5;
    o.seed = seed;
    o.threads = 2;
    Diagnostics diag;
    const RenderResult r = render(s, o, diag);
    EXPECT_EQ(r.nonfinite_paths, 0u);
    std::vector<double> v;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 3; ++c) v.push_back(r.image.pixel(x, y)[c]);
    return v;
}

TEST(PathConvergence, RelMseFallsAsOneOverSpp) {
    const scene::Scene s = convergence_scene();
    // Reference: K renders of kRefSpp samples with their own seeds (N_ref = K * kRefSpp).
    constexpr int kRefRenders = 8, kRefSpp = 1024;
    std::vector<std::vector<double>> refs;
    for (int k = 0; k < kRefRenders; ++k)
        refs.push_back(render_values(s, kRefSpp, 1000 + static_cast<uint32_t>(k)));
    const size_t n = refs[0].size();
    std::vector<double> ref(n, 0.0), ref_var(n, 0.0);  // mean and variance of the mean
    for (size_t i = 0; i < n; ++i) {
        double s1 = 0, s2 = 0;
        for (const auto& r : refs) {
            s1 += r[i];
            s2 += r[i] * r[i];
        }
        ref[i] = s1 / kRefRenders;
        ref_var[i] = std::max(0.0, s2 / kRefRenders - ref[i] * ref[i]) / (kRefRenders - 1);
    }
    double ref_term = 0, mean_ref = 0;
    for (size_t i = 0; i < n; ++i) {
        ref_term += ref_var[i] / (ref[i] * ref[i] + 0.01);
        mean_ref += ref[i];
    }
    ref_term /= n;
    mean_ref /= n;
    ASSERT_GT(mean_ref, 0.05);

    std::vector<double> xs, ys;
    int step = 0;
    for (int spp = 16; spp <= 1024; spp *= 2, ++step) {
        // Averaged over renders with their own seeds (at least 6, and 1536 samples per pixel
        // in all below 256 spp): a few shadowed pixels lit only indirectly carry a third of
        // the error, and one render's luck there would move the fit.
        const int runs = std::max(6, 1536 / spp);
        double rel = 0;
        for (int run = 0; run < runs; ++run) {
            const std::vector<double> img =
                render_values(s, spp, 10 + static_cast<uint32_t>(step * 1000 + run));
            for (size_t i = 0; i < n; ++i)
                rel += (img[i] - ref[i]) * (img[i] - ref[i]) / (ref[i] * ref[i] + 0.01);
        }
        rel /= static_cast<double>(n) * runs;
        const double corrected = rel - ref_term;
        std::printf("spp %5d: relMSE %.4g, minus the reference's own term %.3g: %.4g\n", spp,
                    rel, ref_term, corrected);
        ASSERT_GT(corrected, 0.0);
        xs.push_back(std::log(spp));
        ys.push_back(std::log(corrected));
    }
    // Least-squares slope of log relMSE against log spp.
    double mx = 0, my = 0;
    for (size_t i = 0; i < xs.size(); ++i) {
        mx += xs[i];
        my += ys[i];
    }
    mx /= xs.size();
    my /= xs.size();
    double sxy = 0, sxx = 0, resid = 0;
    for (size_t i = 0; i < xs.size(); ++i) {
        sxy += (xs[i] - mx) * (ys[i] - my);
        sxx += (xs[i] - mx) * (xs[i] - mx);
    }
    const double slope = sxy / sxx;
    for (size_t i = 0; i < xs.size(); ++i) {
        const double e = ys[i] - (my + slope * (xs[i] - mx));
        resid += e * e;
    }
    const double slope_se = std::sqrt(resid / (xs.size() - 2) / sxx);
    std::printf("convergence: mean reference %.4f (N_ref %d spp), slope %.4f +- %.3f\n",
                mean_ref, kRefRenders * kRefSpp, slope, slope_se);
    EXPECT_NEAR(slope, -1.0, 0.1);
}

}  // namespace
}  // namespace glint::render
