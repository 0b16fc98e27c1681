// Blender's procedural texture nodes as Cycles 3.4 evaluates them (render/shader/tex_*.h):
// reference values that Cycles itself rendered, and the functions' exact properties.
//
// The reference tables (shader_textures_refs_*.inc) were produced by
//     blender -b --factory-startup --python tests/shader/make_texture_refs.py
// with Blender 3.4.1 (Cycles on the CPU, x86-64 AVX2 kernel): every row is one face of a grid
// filling an orthographic camera's view pixel for pixel, whose material holds the node with
// the row's settings and socket values; the sample point comes from face attributes (exact
// float32, whatever the pixel's sample position) and the output feeds an Emission shader
// (strength 1) read back from a 32-bit float OpenEXR (1 sample, filter 0.01 px, 'Standard'
// view). The implementation reproduces the kernel's arithmetic, multiply-add fusing included,
// so nearly all values match bit for bit; the tolerance (2e-5 of max(1, |value|)) leaves room
// only for the rare last-bit differences seen (1D Perlin noise, one Brick mortar value).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/shader/cycles_hash.h"
#include "render/shader/tex_noise.h"
#include "render/shader/tex_procedural.h"
#include "render/shader/tex_voronoi.h"

namespace glint::render::shader {
namespace {

using enum NoiseDimensions;
using enum MusgraveType;
using enum VoronoiFeature;
using enum VoronoiMetric;
using enum GradientType;

// Which output a Voronoi row holds: Color, Position, or (Distance, W, Radius).
enum class VoronoiOut { COLOR, POSITION, SCALARS };
enum class BrickOut { COLOR, FAC };

struct NoiseRef {
    NoiseTextureParams params;
    NoiseTextureInputs in;
    float3 color;  // Color; its x is Fac
};
struct WhiteNoiseRef {
    WhiteNoiseParams params;
    WhiteNoiseInputs in;
    float3 color;  // Color, or (Value, -1, -1) for a row that rendered Value
};
struct MusgraveRef {
    MusgraveTextureParams params;
    MusgraveTextureInputs in;
    float fac;
};
struct VoronoiRef {
    VoronoiTextureParams params;
    VoronoiTextureInputs in;
    VoronoiOut out;
    float3 value;
};
struct WaveRef {
    WaveTextureParams params;
    WaveTextureInputs in;
    float fac;
};
struct MagicRef {
    MagicTextureParams params;
    MagicTextureInputs in;
    float3 color;
};
struct GradientRef {
    GradientTextureParams params;
    GradientTextureInputs in;
    float fac;
};
struct CheckerRef {
    CheckerTextureInputs in;
    float3 color;
};
struct BrickRef {
    BrickTextureParams params;
    BrickTextureInputs in;
    BrickOut out;
    float3 value;
};

#include "shader_textures_refs_noise.inc"
#include "shader_textures_refs_procedural.inc"
#include "shader_textures_refs_voronoi.inc"

constexpr float kRefTolerance = 2e-5f;

void expect_ref(float got, float want, size_t row) {
    EXPECT_NEAR(got, want, kRefTolerance * std::max(1.0f, std::fabs(want))) << "row " << row;
}
void expect_ref(float3 got, float3 want, size_t row) {
    expect_ref(got.x, want.x, row);
    expect_ref(got.y, want.y, row);
    expect_ref(got.z, want.z, row);
}

// ---- Cycles' renders ----

TEST(ShaderTexturesCycles, Noise) {
    for (size_t i = 0; i < std::size(kNoiseRefs); ++i) {
        const NoiseRef& r = kNoiseRefs[i];
        expect_ref(noise_texture(r.in, r.params).color, r.color, i);
    }
}

TEST(ShaderTexturesCycles, WhiteNoise) {
    for (size_t i = 0; i < std::size(kWhiteNoiseRefs); ++i) {
        const WhiteNoiseRef& r = kWhiteNoiseRefs[i];
        const WhiteNoiseOutput out = white_noise_texture(r.in, r.params);
        if (r.color.y == -1.0f)
            expect_ref(out.value, r.color.x, i);
        else
            expect_ref(out.color, r.color, i);
    }
}

TEST(ShaderTexturesCycles, Musgrave) {
    for (size_t i = 0; i < std::size(kMusgraveRefs); ++i) {
        const MusgraveRef& r = kMusgraveRefs[i];
        expect_ref(musgrave_texture(r.in, r.params).fac, r.fac, i);
    }
}

TEST(ShaderTexturesCycles, Voronoi) {
    for (size_t i = 0; i < std::size(kVoronoiRefs); ++i) {
        const VoronoiRef& r = kVoronoiRefs[i];
        const VoronoiTextureOutput o = voronoi_texture(r.in, r.params);
        const float3 got = r.out == VoronoiOut::COLOR      ? o.color
                           : r.out == VoronoiOut::POSITION ? o.position
                                                           : float3(o.distance, o.w, o.radius);
        expect_ref(got, r.value, i);
    }
}

TEST(ShaderTexturesCycles, Wave) {
    for (size_t i = 0; i < std::size(kWaveRefs); ++i)
        expect_ref(wave_texture(kWaveRefs[i].in, kWaveRefs[i].params).fac, kWaveRefs[i].fac, i);
}

TEST(ShaderTexturesCycles, Magic) {
    for (size_t i = 0; i < std::size(kMagicRefs); ++i)
        expect_ref(magic_texture(kMagicRefs[i].in, kMagicRefs[i].params).color, kMagicRefs[i].color,
                   i);
}

TEST(ShaderTexturesCycles, Gradient) {
    for (size_t i = 0; i < std::size(kGradientRefs); ++i)
        expect_ref(gradient_texture(kGradientRefs[i].in, kGradientRefs[i].params).fac,
                   kGradientRefs[i].fac, i);
}

TEST(ShaderTexturesCycles, Checker) {
    for (size_t i = 0; i < std::size(kCheckerRefs); ++i)
        expect_ref(checker_texture(kCheckerRefs[i].in).color, kCheckerRefs[i].color, i);
}

TEST(ShaderTexturesCycles, Brick) {
    for (size_t i = 0; i < std::size(kBrickRefs); ++i) {
        const BrickRef& r = kBrickRefs[i];
        const BrickTextureOutput o = brick_texture(r.in, r.params);
        expect_ref(r.out == BrickOut::COLOR ? o.color : float3(o.fac), r.value, i);
    }
}

// ---- hashes ----

// The lookup3 hashes themselves are checked against Cycles by the White Noise references
// (Value and Color hash the point's bits with hash_uint .. hash_uint4).

TEST(ShaderTexturesHash, FloatMappings) {
    EXPECT_EQ(uint_to_float_incl(0), 0.0f);
    EXPECT_EQ(uint_to_float_incl(0xFFFFFFFFu), 1.0f);
    EXPECT_LT(uint_to_float_excl(0xFFFFFFFFu), 1.0f);
    // Floats hash by their bits: 0 and -0 differ, and the float hash is the word hash.
    EXPECT_NE(hash_float_to_float(0.0f), hash_float_to_float(-0.0f));
    EXPECT_EQ(hash_float_to_float(1.0f), hash_uint_to_float(0x3f800000u));
    EXPECT_EQ(hash_float2_to_float(1.0f, 2.0f), hash_uint2_to_float(0x3f800000u, 0x40000000u));
    const float3 c = hash_float3_to_float3({0.5f, -3.0f, 7.25f});
    EXPECT_EQ(c.x, hash_float3_to_float({0.5f, -3.0f, 7.25f}));
    EXPECT_EQ(c.y, hash_float4_to_float({0.5f, -3.0f, 7.25f, 1.0f}));
    EXPECT_EQ(c.z, hash_float4_to_float({0.5f, -3.0f, 7.25f, 2.0f}));
    const float4 q = hash_float4_to_float4({1.0f, 2.0f, 3.0f, 4.0f});
    EXPECT_EQ(q.y, hash_float4_to_float({4.0f, 1.0f, 2.0f, 3.0f}));
    EXPECT_EQ(hash_float2_to_float2(1.0f, 2.0f).y, hash_float3_to_float({1.0f, 2.0f, 1.0f}));
    EXPECT_EQ(hash_string(""), 0u);
    EXPECT_EQ(hash_string("ab"), 97u * 37u + 98u);
}

// ---- Perlin and fractal noise ----

TEST(ShaderTexturesNoise, PerlinVanishesOnTheLattice) {
    for (float i = -3.0f; i <= 3.0f; i += 1.0f) {
        EXPECT_EQ(perlin_1d(i), 0.0f);
        EXPECT_EQ(perlin_2d(i, 2.0f - i), 0.0f);
        EXPECT_EQ(perlin_3d(i, -i, 5.0f), 0.0f);
        EXPECT_EQ(perlin_4d(i, 1.0f, -2.0f, i), 0.0f);
    }
}

TEST(ShaderTexturesNoise, RangesAndContinuity) {
    float lo = 1.0f, hi = 0.0f;
    for (int k = 0; k < 4000; ++k) {
        const float3 p(k * 0.0173f - 30.0f, std::sin(k * 0.37f) * 9.0f, k * 0.0031f);
        const float w = k * -0.011f;
        const float n[4] = {noise_1d(p.x), noise_2d(p.x, p.y), noise_3d(p),
                            noise_4d({p.x, p.y, p.z, w})};
        for (float v : n) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        // A small step moves the noise a little: the gradient is bounded.
        const float e = 1e-3f;
        EXPECT_NEAR(noise_3d(p + float3(e, 0.0f, 0.0f)), noise_3d(p), 0.01f);
        EXPECT_NEAR(noise_2d(p.x, p.y + e), noise_2d(p.x, p.y), 0.01f);
    }
    EXPECT_GE(lo, 0.0f);
    EXPECT_LE(hi, 1.0f);
    EXPECT_LT(lo, 0.2f);  // and it does spread over the range
    EXPECT_GT(hi, 0.8f);
}

TEST(ShaderTexturesNoise, NonFiniteInputGivesMidGrey) {
    EXPECT_EQ(snoise_3d({INFINITY, 0.0f, 0.0f}), 0.0f);
    EXPECT_EQ(noise_1d(NAN), 0.5f);
}

TEST(ShaderTexturesNoise, FractalDetailInterpolatesOctaves) {
    const float3 p(0.37f, -1.2f, 2.9f);
    EXPECT_EQ(fractal_noise_3d(p, 0.0f, 0.5f), noise_3d(p));
    EXPECT_EQ(fractal_noise_3d(p, -4.0f, 0.5f), noise_3d(p));  // detail clamps to [0, 15]
    EXPECT_EQ(fractal_noise_3d(p, 40.0f, 0.5f), fractal_noise_3d(p, 15.0f, 0.5f));
    const float lo = fractal_noise_3d(p, 2.0f, 0.6f), hi = fractal_noise_3d(p, 3.0f, 0.6f);
    EXPECT_NEAR(fractal_noise_3d(p, 2.25f, 0.6f), 0.75f * lo + 0.25f * hi, 1e-6f);
    // Roughness 0 keeps only the first octave.
    EXPECT_NEAR(fractal_noise_3d(p, 6.0f, 0.0f), noise_3d(p), 1e-7f);
}

TEST(ShaderTexturesNoise, NoiseTextureOutputs) {
    NoiseTextureInputs in;
    in.vector = float3(0.3f, 0.8f, -0.1f);
    in.w = 1.7f;
    for (NoiseDimensions d : {D1, D2, D3, D4}) {
        const NoiseTextureOutput full = noise_texture(in, {d});
        EXPECT_EQ(full.color.x, full.fac);
        EXPECT_NE(full.color.y, full.fac);
        const NoiseTextureOutput bare = noise_texture(in, {d}, false);
        EXPECT_EQ(bare.fac, full.fac);
        EXPECT_EQ(bare.color, float3(0.0f));
        EXPECT_EQ(noise_texture(in, {d}).fac, full.fac);  // deterministic
    }
    // 1D reads W only, 2D only x and y.
    NoiseTextureInputs moved = in;
    moved.vector = float3(-5.0f, 2.0f, 9.0f);
    EXPECT_EQ(noise_texture(moved, {D1}).fac, noise_texture(in, {D1}).fac);
    moved = in;
    moved.vector.z = 42.0f;
    moved.w = -3.0f;
    EXPECT_EQ(noise_texture(moved, {D2}).fac, noise_texture(in, {D2}).fac);
    // Fac with 0 detail at scale 1 is the noise itself.
    in.scale = 1.0f;
    in.detail = 0.0f;
    EXPECT_EQ(noise_texture(in, {D3}).fac, noise_3d(in.vector));
}

TEST(ShaderTexturesNoise, WhiteNoiseValueIsColorX) {
    WhiteNoiseInputs in;
    in.vector = float3(0.25f, -7.5f, 3.0f);
    in.w = 0.125f;
    for (NoiseDimensions d : {D1, D2, D3, D4}) {
        const WhiteNoiseOutput o = white_noise_texture(in, {d});
        EXPECT_EQ(o.value, o.color.x);
        for (float c : {o.color.x, o.color.y, o.color.z}) {
            EXPECT_GE(c, 0.0f);
            EXPECT_LE(c, 1.0f);
        }
    }
    EXPECT_EQ(white_noise_texture(in, {D3}).value, hash_float3_to_float(in.vector));
}

TEST(ShaderTexturesNoise, MusgraveOneOctave) {
    MusgraveTextureInputs in;
    in.vector = float3(0.41f, 0.13f, -0.77f);
    in.scale = 1.0f;
    in.detail = 1.0f;
    in.offset = 0.5f;
    const float s = snoise_3d(in.vector);
    EXPECT_EQ(musgrave_texture(in, {FBM, D3}).fac, s);
    EXPECT_NEAR(musgrave_texture(in, {MULTIFRACTAL, D3}).fac, s + 1.0f, 1e-6f);
    EXPECT_NEAR(musgrave_texture(in, {HETERO_TERRAIN, D3}).fac, 0.5f + s, 1e-6f);
    EXPECT_NEAR(musgrave_texture(in, {RIDGED_MULTIFRACTAL, D3}).fac,
                (0.5f - std::fabs(s)) * (0.5f - std::fabs(s)), 1e-6f);
    in.detail = 0.0f;
    EXPECT_EQ(musgrave_texture(in, {FBM, D3}).fac, 0.0f);
    EXPECT_EQ(musgrave_texture(in, {MULTIFRACTAL, D3}).fac, 1.0f);
}

// ---- Voronoi ----

TEST(ShaderTexturesVoronoi, FeaturesAgreeWithEachOther) {
    for (int k = 0; k < 200; ++k) {
        VoronoiTextureInputs in;
        in.vector = float3(k * 0.071f - 7.0f, std::cos(k * 1.3f) * 3.0f, k * 0.013f);
        in.w = std::sin(k * 0.7f) * 2.0f;
        for (NoiseDimensions d : {D1, D2, D3, D4}) {
            const VoronoiTextureOutput f1 = voronoi_texture(in, {d, F1, EUCLIDEAN});
            const VoronoiTextureOutput f2 = voronoi_texture(in, {d, F2, EUCLIDEAN});
            EXPECT_LE(f1.distance, f2.distance);
            EXPECT_GE(f1.distance, 0.0f);
            // Smooth F1 with no smoothness is F1 over the wider search.
            VoronoiTextureInputs sharp = in;
            sharp.smoothness = 0.0f;
            const VoronoiTextureOutput s = voronoi_texture(sharp, {d, SMOOTH_F1, EUCLIDEAN});
            EXPECT_NEAR(s.distance, f1.distance, 1e-5f);
            const float edge = voronoi_texture(in, {d, DISTANCE_TO_EDGE, EUCLIDEAN}).distance;
            EXPECT_GE(edge, -1e-6f);
            EXPECT_LE(edge, f2.distance * in.scale);
            EXPECT_GT(voronoi_texture(in, {d, N_SPHERE_RADIUS, EUCLIDEAN}).radius, 0.0f);
        }
    }
}

TEST(ShaderTexturesVoronoi, NoRandomnessIsTheIntegerLattice) {
    VoronoiTextureInputs in;
    in.vector = float3(0.33f, 0.52f, -0.07f);
    in.w = 0.61f;
    in.scale = 1.0f;
    in.randomness = 0.0f;
    const VoronoiTextureOutput o3 = voronoi_texture(in, {D3, F1, EUCLIDEAN});
    EXPECT_EQ(o3.position, float3(0.0f, 1.0f, 0.0f));
    EXPECT_NEAR(o3.distance, len(in.vector - float3(0.0f, 1.0f, 0.0f)), 1e-6f);
    const VoronoiTextureOutput o4 = voronoi_texture(in, {D4, F1, MANHATTAN});
    EXPECT_EQ(o4.w, 1.0f);
    EXPECT_NEAR(o4.distance, 0.33f + 0.48f + 0.07f + 0.39f, 1e-6f);
    EXPECT_NEAR(voronoi_texture(in, {D3, N_SPHERE_RADIUS, EUCLIDEAN}).radius, 0.5f, 1e-6f);
    EXPECT_NEAR(voronoi_texture(in, {D1, F1, EUCLIDEAN}).w, 1.0f, 0.0f);
    EXPECT_NEAR(voronoi_texture(in, {D1, DISTANCE_TO_EDGE, EUCLIDEAN}).distance, 0.11f, 1e-6f);
}

TEST(ShaderTexturesVoronoi, DimensionsReadTheirCoordinates) {
    VoronoiTextureInputs a;
    a.vector = float3(1.3f, -0.4f, 2.2f);
    a.w = 0.9f;
    VoronoiTextureInputs b = a;
    b.vector.z = -8.0f;
    b.w = 5.0f;
    const VoronoiTextureOutput oa = voronoi_texture(a, {D2, F1, CHEBYCHEV});
    const VoronoiTextureOutput ob = voronoi_texture(b, {D2, F1, CHEBYCHEV});
    EXPECT_EQ(oa.distance, ob.distance);
    EXPECT_EQ(oa.position, ob.position);
    EXPECT_EQ(oa.position.z, 0.0f);
    // 1D measures |a - b| whatever the metric.
    EXPECT_EQ(voronoi_texture(a, {D1, F2, MINKOWSKI}).distance,
              voronoi_texture(a, {D1, F2, EUCLIDEAN}).distance);
    // Minkowski with exponent 1 and 2 is Manhattan and Euclidean.
    VoronoiTextureInputs m = a;
    m.exponent = 1.0f;
    EXPECT_NEAR(voronoi_texture(m, {D3, F1, MINKOWSKI}).distance,
                voronoi_texture(m, {D3, F1, MANHATTAN}).distance, 1e-5f);
    m.exponent = 2.0f;
    EXPECT_NEAR(voronoi_texture(m, {D3, F1, MINKOWSKI}).distance,
                voronoi_texture(m, {D3, F1, EUCLIDEAN}).distance, 1e-5f);
}

// ---- Wave, Magic, Gradient, Checker, Brick ----

TEST(ShaderTexturesProcedural, WaveRangeAndColor) {
    WaveTextureInputs in;
    in.distortion = 2.0f;
    for (int k = 0; k < 300; ++k) {
        in.vector = float3(k * 0.013f - 2.0f, std::sin(k * 0.2f), k * 0.007f);
        for (WaveProfile profile : {WaveProfile::SIN, WaveProfile::SAW, WaveProfile::TRI}) {
            WaveTextureParams params;
            params.type = k % 2 ? WaveType::RINGS : WaveType::BANDS;
            params.profile = profile;
            const WaveTextureOutput o = wave_texture(in, params);
            EXPECT_GE(o.fac, 0.0f);
            EXPECT_LE(o.fac, 1.0f);
            EXPECT_EQ(o.color, float3(o.fac));
        }
    }
    // Without distortion, X bands depend on x only.
    WaveTextureInputs a, b;
    a.vector = float3(0.2f, 0.5f, 0.9f);
    b.vector = float3(0.2f, -3.0f, 7.0f);
    EXPECT_EQ(wave_texture(a, {}).fac, wave_texture(b, {}).fac);
}

TEST(ShaderTexturesProcedural, MagicDepthZeroAndFac) {
    MagicTextureInputs in;
    in.vector = float3(0.1f, 0.2f, 0.3f);
    in.scale = 1.0f;
    in.distortion = 0.0f;
    const MagicTextureOutput o = magic_texture(in, {0});
    // Depth 0: sin((x + y + z) 5s), cos((-x + y - z) 5s), -cos((-x - y + z) 5s).
    EXPECT_NEAR(o.color.x, 0.5f - std::sin(3.0f), 1e-5f);
    EXPECT_NEAR(o.color.y, 0.5f - std::cos(-1.0f), 1e-5f);
    EXPECT_NEAR(o.color.z, 0.5f + std::cos(0.0f), 1e-5f);
    for (int depth = 0; depth <= 10; ++depth) {
        in.distortion = 1.5f;
        const MagicTextureOutput m = magic_texture(in, {depth});
        EXPECT_NEAR(m.fac, (m.color.x + m.color.y + m.color.z) / 3.0f, 1e-6f);
    }
}

TEST(ShaderTexturesProcedural, GradientTypes) {
    const float3 p(0.6f, 0.3f, 0.0f);
    auto fac = [&](GradientType t, float3 v) { return gradient_texture({v}, {t}).fac; };
    EXPECT_EQ(fac(LINEAR, p), 0.6f);
    EXPECT_EQ(fac(LINEAR, float3(1.7f, 0.0f, 0.0f)), 1.0f);  // clamped
    EXPECT_NEAR(fac(QUADRATIC, p), 0.36f, 1e-7f);
    EXPECT_NEAR(fac(EASING, p), 0.648f, 1e-6f);
    EXPECT_NEAR(fac(DIAGONAL, p), 0.45f, 1e-7f);
    EXPECT_NEAR(fac(SPHERICAL, p), 0.999999f - std::sqrt(0.45f), 1e-6f);
    EXPECT_NEAR(fac(QUADRATIC_SPHERE, p), std::pow(0.999999f - std::sqrt(0.45f), 2.0f), 1e-6f);
    EXPECT_EQ(fac(SPHERICAL, float3(1.0f, 0.0f, 0.0f)), 0.0f);
    EXPECT_NEAR(fac(RADIAL, float3(0.0f, 1.0f, 0.0f)), 0.75f, 1e-7f);
    EXPECT_NEAR(fac(RADIAL, float3(-1.0f, -1e-9f, 0.0f)), 0.0f, 1e-6f);
    EXPECT_EQ(gradient_texture({p}, {EASING}).color, float3(fac(EASING, p)));
}

TEST(ShaderTexturesProcedural, CheckerAlternates) {
    CheckerTextureInputs in;
    in.scale = 1.0f;
    in.color1 = float3(1.0f, 0.0f, 0.0f);
    in.color2 = float3(0.0f, 0.0f, 1.0f);
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j) {
            in.vector = float3(i + 0.5f, j + 0.5f, 0.5f);
            const CheckerTextureOutput o = checker_texture(in);
            const bool first = ((i + j) % 2 + 2) % 2 == 1;
            EXPECT_EQ(o.fac, first ? 1.0f : 0.0f) << i << " " << j;
            EXPECT_EQ(o.color, first ? in.color1 : in.color2);
        }
}

TEST(ShaderTexturesProcedural, BrickMortarAndTint) {
    BrickTextureInputs in;
    in.scale = 1.0f;
    in.mortar = float3(0.0f, 1.0f, 0.0f);
    // On a row boundary: mortar.
    in.vector = float3(0.3f, 0.5f, 0.0f);
    BrickTextureOutput o = brick_texture(in, {});
    EXPECT_EQ(o.fac, 1.0f);
    EXPECT_EQ(o.color, in.mortar);
    // In the middle of a brick of the second (not offset) row: brick colour between color1
    // and color2.
    in.vector = float3(0.25f, 0.375f, 0.0f);
    o = brick_texture(in, {});
    EXPECT_EQ(o.fac, 0.0f);
    EXPECT_GE(o.color.x, 0.2f - 1e-6f);
    EXPECT_LE(o.color.x, 0.8f + 1e-6f);
    // Bias 1 makes every brick color2.
    in.bias = 1.0f;
    EXPECT_NEAR(brick_texture(in, {}).color.x, 0.2f, 1e-6f);
    for (unsigned n : {0u, 1u, 65536u, 0xFFFFFFFFu}) {
        EXPECT_GE(brick_noise(n), 0.0f);
        EXPECT_LT(brick_noise(n), 1.0f);
    }
    // Mortar factor stays in [0, 1] and is continuous-ish across the smooth band.
    in.bias = 0.0f;
    for (int k = 0; k < 500; ++k) {
        in.vector = float3(k * 0.0137f, k * 0.0071f, 0.0f);
        const float f = brick_texture(in, {0.3f, 3, 1.5f, 2}).fac;
        EXPECT_GE(f, 0.0f);
        EXPECT_LE(f, 1.0f);
    }
}

}  // namespace
}  // namespace glint::render::shader
