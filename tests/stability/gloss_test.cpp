// VALIDATION.md case 14 with the Whitted integrator: Phong exponents 0, 1e5 and 1e6 give no
// non-finite pixel, and the highlight sits where the mirror direction says: the brightest
// pixel is the centre one, whose ray meets the floor at the mirror point. (The path tracer's
// side of case 14, with GGX alpha 1e-6, is path_render_test's ExtremeGlossLobes test.)
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "stability_support.h"

namespace glint::stability {
namespace {

TEST(StabilityGloss, Case14PhongExtremeExponents) {
    const int w = 65, h = 49;  // odd: the centre pixel's ray is the camera's direction
    // The light (0, 4, 6) seen in the floor is (0, -4, 6): the camera at (0, 2, -3) sees it
    // through the origin (both at ratio 2:1 along the line), the look_at point.
    for (const char* size : {"0", "40", "1e5", "1e6"}) {
        const Image image =
            render_file("gloss.pov", std::string("#declare Size = ") + size + ";", w, h);
        const long bad = count_nonfinite(image);
        int bx = 0, by = 0;
        float best = -1;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (image.pixel(x, y)[0] > best) {
                    best = image.pixel(x, y)[0];
                    bx = x;
                    by = y;
                }
        const float centre = image.pixel(w / 2, h / 2)[0];
        const int dist = std::max(std::abs(bx - w / 2), std::abs(by - h / 2));
        std::printf(
            "case 14 whitted phong_size %s: non-finite %ld (bound 0); brightest pixel "
            "%.4g at (%d, %d), %d px from the mirror pixel (bound 0 for size >= 40); "
            "centre %.4g\n",
            size, bad, best, bx, by, dist, centre);
        EXPECT_EQ(bad, 0) << size;
        if (std::string(size) != "0") {
            EXPECT_EQ(centre, best) << size;  // ties allowed (a flat-topped highlight)
            EXPECT_GT(centre, 0.9f) << size;  // phong 1 at the peak: the highlight is there
        }
    }
}

}  // namespace
}  // namespace glint::stability
