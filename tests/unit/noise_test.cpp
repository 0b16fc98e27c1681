// POV-Ray 3.7's noise: values POV-Ray produced (bozo, which is Noise() itself, rendered at
// 16 bits for noise_generator 1, 2 and 3) and the algorithm's exact properties.
#include "core/noise.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

struct NoiseSample {
    int generator;
    Vec3 p;
    double value;
};

const NoiseSample kPovNoise[] = {
    {2, {-5.875000000000001, 2.8750000000000004, -1.2333333333333334}, 0.410605020218204},
    {2, {-1.0416666666666663, 0.6249999999999999, -1.2333333333333334}, 0.6431372549019608},
    {2, {3.0416666666666674, -3.208333333333334, -1.2333333333333334}, 0.6504005493247883},
    {2, {5.541666666666667, 3.8750000000000004, -1.2333333333333334}, 0.5152819104295414},
    {2, {-3.6250000000000004, -4.875000000000001, -1.2333333333333334}, 0.3637445639734493},
    {1, {-5.875000000000001, 2.8750000000000004, -1.2333333333333334}, 0.28578622110322727},
    {1, {-1.0416666666666663, 0.6249999999999999, -1.2333333333333334}, 0.7604791332875562},
    {1, {3.0416666666666674, -3.208333333333334, -1.2333333333333334}, 0.7753109025711452},
    {1, {5.541666666666667, 3.8750000000000004, -1.2333333333333334}, 0.499473563744564},
    {1, {-3.6250000000000004, -4.875000000000001, -1.2333333333333334}, 0.1901426718547341},
    {3, {-5.875000000000001, 2.8750000000000004, -1.2333333333333334}, 0.381551842526894},
    {3, {-1.0416666666666663, 0.6249999999999999, -1.2333333333333334}, 0.35680170901045244},
    {3, {3.0416666666666674, -3.208333333333334, -1.2333333333333334}, 0.30777447165636684},
    {3, {5.541666666666667, 3.8750000000000004, -1.2333333333333334}, 0.6254062714579995},
    {3, {-3.6250000000000004, -4.875000000000001, -1.2333333333333334}, 0.4584420538643473},
};

TEST(NoisePov, MatchesPovRayForEveryGenerator) {
    for (const NoiseSample& s : kPovNoise)
        EXPECT_NEAR(noise(s.p, s.generator), s.value, 2e-5)
            << "generator " << s.generator << " at " << s.p.x << "," << s.p.y << "," << s.p.z;
}

TEST(Noise, RangeAndDeterminism) {
    for (int gen = 1; gen <= 3; ++gen) {
        double lo = 1, hi = 0;
        for (int i = 0; i < 20000; ++i) {
            Vec3 p(std::sin(i * 0.731) * 50, std::cos(i * 0.197) * 50, i * 0.0137 - 100);
            double v = noise(p, gen);
            ASSERT_GE(v, 0.0);
            ASSERT_LE(v, 1.0);
            ASSERT_EQ(v, noise(p, gen));
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        // Generator 2 stretches the raw range to nearly all of [0, 1]; 1 stays narrower.
        EXPECT_LT(lo, gen == 1 ? 0.35 : 0.1) << gen;
        EXPECT_GT(hi, gen == 1 ? 0.65 : 0.9) << gen;
    }
}

TEST(Noise, ContinuousAcrossLatticeCells) {
    // The s-curve weights make the lattice noise continuous where the cell changes, negative
    // coordinates (POV-Ray's "JB fix") included.
    for (double c : {-3.0, -1.0, 0.0, 1.0, 7.0}) {
        Vec3 a(c - 1e-9, 0.37, -2.61), b(c + 1e-9, 0.37, -2.61);
        EXPECT_NEAR(noise(a, 2), noise(b, 2), 1e-7) << c;
        Vec3 da = dnoise(a), db = dnoise(b);
        EXPECT_NEAR(da.x, db.x, 1e-7) << c;
        EXPECT_NEAR(da.y, db.y, 1e-7) << c;
        EXPECT_NEAR(da.z, db.z, 1e-7) << c;
    }
}

TEST(Noise, TurbulenceSumsOctaves) {
    const Vec3 p(0.3, -1.7, 2.2);
    TurbulenceParams one{1, 0.5, 2.0};
    // One octave: a single noise call, spread to 2n - 0.5 and clamped for generator 2.
    EXPECT_DOUBLE_EQ(turbulence(p, one, 1), noise(p, 1));
    EXPECT_DOUBLE_EQ(turbulence(p, one, 2), std::clamp(2 * noise(p, 2) - 0.5, 0.0, 1.0));
    TurbulenceParams two{2, 0.5, 2.0};
    EXPECT_DOUBLE_EQ(turbulence(p, two, 1), noise(p, 1) + 0.5 * noise(p * 2.0, 1));
    Vec3 d1 = dturbulence(p, one), d2 = dturbulence(p, two), dn = dnoise(p * 2.0);
    EXPECT_DOUBLE_EQ(d1.x, dnoise(p).x);
    EXPECT_DOUBLE_EQ(d2.y, d1.y + 0.5 * dn.y);
}

TEST(Noise, HashAndPatternRandoms) {
    // boost's mt19937 (default seed) through uniform_real: the first draw is 3499211612 / 2^32.
    EXPECT_DOUBLE_EQ(pattern_random(0), 3499211612.0 / 4294967296.0);
    EXPECT_DOUBLE_EQ(pattern_random(32768), pattern_random(0));
    for (int i = -5; i < 5; ++i) {
        int h = hash3d(i, 2 * i, -3 * i);
        EXPECT_GE(h, 0);
        EXPECT_LT(h, 4096);
        // Only the low 12 bits of each coordinate matter.
        EXPECT_EQ(h, hash3d(i + 4096, 2 * i, -3 * i));
    }
    EXPECT_NE(hash3d(0, 0, 0), hash3d(1, 0, 0));
}

}  // namespace
}  // namespace glint
