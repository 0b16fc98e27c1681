// VALIDATION.md case 18: the demo scene (reflection, refraction, shadows, image texture)
// renders to the same film bit for bit with 1 and 2 threads, twice each; without anti-aliasing
// and with POV-Ray's adaptive methods 1 and 2 (whose extra samples depend on neighbouring
// pixels and on jitter, the likelier places for tile order to leak in).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "stability_support.h"

namespace glint::stability {
namespace {

scene::Scene demo_scene() {
    pov::ParseOptions options;
    options.include_dirs = {"/usr/share/povray-3.7/include"};
    Diagnostics diag;
    return pov::parse_file(std::string(GLINT_SOURCE_DIR) + "/scenes/demo.pov", options, diag);
}

void expect_same_at_one_and_two_threads(render::AaMode aa, const char* label) {
    const scene::Scene scene = demo_scene();
    const Image first = render_scene(scene, 320, 240, 1, aa);
    ASSERT_EQ(first.rgba.size(), size_t{320 * 240 * 4});
    const int runs[] = {2, 1, 2};
    for (int threads : runs) {
        const Image again = render_scene(scene, 320, 240, threads, aa);
        const long n = differing_values(first, again);
        std::printf(
            "case 18 whitted demo.pov %s, %d thread(s) vs 1 thread: differing float values = %ld "
            "of %zu "
            "(bound 0)\n",
            label, threads, n, first.rgba.size());
        EXPECT_EQ(n, 0) << label << ", " << threads << " threads";
    }
}

TEST(StabilityDeterminism, SameFilmAtOneAndTwoThreads) {
    expect_same_at_one_and_two_threads(render::AaMode::None, "no AA");
}

TEST(StabilityDeterminism, SameFilmAtOneAndTwoThreadsWithAdaptiveAa) {
    expect_same_at_one_and_two_threads(render::AaMode::Adaptive, "adaptive AA 0.3");
}

TEST(StabilityDeterminism, SameFilmAtOneAndTwoThreadsWithRecursiveAa) {
    expect_same_at_one_and_two_threads(render::AaMode::Adaptive2, "adaptive AA method 2 0.3");
}

TEST(StabilityDeterminism, PathTracerSameFilmAtOneAndTwoThreads) {
    const scene::Scene scene = demo_scene();
    const Image first = render_path_tracer(scene, 160, 120, 4, 8, 11, 1).image;
    ASSERT_EQ(first.rgba.size(), size_t{160 * 120 * 4});
    for (int threads : {2, 1, 2}) {
        const Image again = render_path_tracer(scene, 160, 120, 4, 8, 11, threads).image;
        const long n = differing_values(first, again);
        std::printf(
            "case 18 path demo.pov 4 spp, %d thread(s) vs 1 thread: differing float "
            "values = %ld of %zu (bound 0)\n",
            threads, n, first.rgba.size());
        EXPECT_EQ(n, 0) << threads << " threads";
    }
}

}  // namespace
}  // namespace glint::stability
