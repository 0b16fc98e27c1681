// VALIDATION.md case 3: exactly coplanar, overlapping triangles (and mesh faces and box faces)
// with different materials render the same image bit for bit at 1 and 2 threads, twice, with
// the Whitted integrator and with the path tracer: which surface wins a tie is decided by the
// geometry (lower index on equal t), never by the thread or the run.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "stability_support.h"

namespace glint::stability {
namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

TEST(StabilityCoplanar, Case3SameImageAcrossRunsAndThreadCounts) {
    const scene::Scene scene = load_scene("coplanar.pov", "", kWidth, kHeight);
    for (bool path : {false, true}) {
        auto render_at = [&](int threads) {
            if (path) return render_path_tracer(scene, kWidth, kHeight, 4, 8, 3, threads).image;
            return render_scene(scene, kWidth, kHeight, threads);
        };
        const Image first = render_at(1);
        ASSERT_EQ(first.rgba.size(), size_t{kWidth * kHeight * 4});
        long worst = 0;
        for (int threads : {2, 1, 2}) worst = std::max(worst, differing_values(first, render_at(threads)));
        // How the overlap of the two red/green triangles resolved (reported, not bounded: the
        // two planes' t values may differ in the last bit from pixel to pixel).
        long red = 0, green = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const float* p = first.pixel(x, y);
                if (p[0] > 4 * (p[1] + p[2]) && p[0] > 0.05f) ++red;
                if (p[1] > 4 * (p[0] + p[2]) && p[1] > 0.05f) ++green;
            }
        std::printf(
            "case 3 %s: differing film values at 1/2 threads, twice = %ld of %zu (bound "
            "0); red %ld, green %ld pixels\n",
            path ? "path" : "whitted", worst, first.rgba.size(), red, green);
        EXPECT_EQ(worst, 0) << (path ? "path" : "whitted");
        EXPECT_EQ(count_nonfinite(first), 0);
    }
}

}  // namespace
}  // namespace glint::stability
