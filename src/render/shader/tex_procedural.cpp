#include "render/shader/tex_procedural.h"

#include <climits>
#include <cmath>
#include <cstdint>

#include "render/shader/tex_noise.h"

namespace glint::render::shader {
namespace {

constexpr float kHalfPi = 1.5707963267948966f;  // Cycles' M_PI_2_F
constexpr float kTwoPi = 6.2831853071795864f;   // Cycles' M_2PI_F

// a * b + c rounded once, where Blender's x86-64 CPU kernel (AVX2, built with floating-point
// contraction) fuses the multiply-add.
float madd(float a, float b, float c) { return std::fma(a, b, c); }

float min_c(float a, float b) { return a < b ? a : b; }
float max_c(float a, float b) { return a > b ? a : b; }
float saturate(float a) { return min_c(max_c(a, 0.0f), 1.0f); }

// float -> int as x86's truncating conversion does: out of range and NaN give INT_MIN.
int trunc_to_int(float f) {
    return (f >= -2147483648.0f && f < 2147483648.0f) ? static_cast<int>(f) : INT_MIN;
}
int floor_to_int(float f) { return trunc_to_int(std::floor(f)); }

// Cycles' float3 length: SSE4.1 dpps adds x*x + y*y, then z*z.
float length3(float3 p) { return std::sqrt((p.x * p.x + p.y * p.y) + p.z * p.z); }

// (co * scale + 0.000001) * 0.999999, the nudge off unit coordinates that Cycles applies
// against precision trouble there; its kernel fuses the scaling into the add.
float3 scaled_nudged(float3 co, float scale) {
    return float3(madd(co.x, scale, 0.000001f), madd(co.y, scale, 0.000001f),
                  madd(co.z, scale, 0.000001f)) *
           0.999999f;
}

float wave(const WaveTextureParams& params, float3 co, float scale, float distortion, float detail,
           float detail_scale, float detail_roughness, float phase) {
    float3 p = scaled_nudged(co, scale);
    float n;
    if (params.type == WaveType::BANDS) {
        switch (params.bands_direction) {
            case WaveBandsDirection::X:
                n = p.x * 20.0f;
                break;
            case WaveBandsDirection::Y:
                n = p.y * 20.0f;
                break;
            case WaveBandsDirection::Z:
                n = p.z * 20.0f;
                break;
            default:
                n = (p.x + p.y + p.z) * 10.0f;
                break;
        }
    } else {
        float3 r = p;
        switch (params.rings_direction) {
            case WaveRingsDirection::X:
                r *= float3(0.0f, 1.0f, 1.0f);
                break;
            case WaveRingsDirection::Y:
                r *= float3(1.0f, 0.0f, 1.0f);
                break;
            case WaveRingsDirection::Z:
                r *= float3(1.0f, 1.0f, 0.0f);
                break;
            default:
                break;
        }
        n = length3(r) * 20.0f;
    }
    n += phase;
    if (distortion != 0.0f) {
        const float turbulence = fractal_noise_3d(p * detail_scale, detail, detail_roughness);
        n = madd(distortion, madd(turbulence, 2.0f, -1.0f), n);
    }
    switch (params.profile) {
        case WaveProfile::SIN:
            return 0.5f + 0.5f * std::sin(n - kHalfPi);
        case WaveProfile::SAW:
            n /= kTwoPi;
            return n - std::floor(n);
        case WaveProfile::TRI:
            n /= kTwoPi;
            return std::fabs(n - std::floor(n + 0.5f)) * 2.0f;
    }
    return 0.0f;
}

float3 magic(float3 p, float scale, int depth, float distortion) {
    // Reduced modulo 2 pi first, as Cycles does, against precision loss and overflow.
    const float px = std::fmod(p.x, kTwoPi);
    const float py = std::fmod(p.y, kTwoPi);
    const float pz = std::fmod(p.z, kTwoPi);
    float x = std::sin((px + py + pz) * 5.0f * scale);
    float y = std::cos((-px + py - pz) * 5.0f * scale);
    float z = -std::cos((-px - py + pz) * 5.0f * scale);
    // Each level of depth rewrites one coordinate from the others, in Cycles' fixed order.
    if (depth > 0) {
        x *= distortion;
        z *= distortion;
        // y's product is used only here, so the kernel fuses it into the subtraction.
        y = -std::cos(madd(-y, distortion, x) + z) * distortion;
    }
    if (depth > 1) x = std::cos(x - y - z) * distortion;
    if (depth > 2) z = std::sin(-x - y - z) * distortion;
    if (depth > 3) x = -std::cos(-x + y - z) * distortion;
    if (depth > 4) y = -std::sin(-x + y + z) * distortion;
    if (depth > 5) y = -std::cos(-x + y + z) * distortion;
    if (depth > 6) x = std::cos(x + y + z) * distortion;
    if (depth > 7) z = std::sin(x + y - z) * distortion;
    if (depth > 8) x = -std::cos(-x - y + z) * distortion;
    if (depth > 9) y = -std::sin(x - y + z) * distortion;
    if (distortion != 0.0f) {
        const float d = distortion * 2.0f;
        x /= d;
        y /= d;
        z /= d;
    }
    return {0.5f - x, 0.5f - y, 0.5f - z};
}

float gradient(float3 p, GradientType type) {
    const float x = p.x, y = p.y, z = p.z;
    switch (type) {
        case GradientType::LINEAR:
            return x;
        case GradientType::QUADRATIC: {
            const float r = std::fmax(x, 0.0f);
            return r * r;
        }
        case GradientType::EASING: {
            const float r = std::fmin(std::fmax(x, 0.0f), 1.0f);
            const float t = r * r;
            return madd(3.0f, t, -(2.0f * t * r));
        }
        case GradientType::DIAGONAL:
            return (x + y) * 0.5f;
        case GradientType::RADIAL:
            return std::atan2(y, x) / kTwoPi + 0.5f;
        case GradientType::SPHERICAL:
        case GradientType::QUADRATIC_SPHERE: {
            // Biased so that a unit vector gives exactly 0.
            const float len = std::sqrt(madd(z, z, madd(x, x, y * y)));
            const float r = std::fmax(0.999999f - len, 0.0f);
            return type == GradientType::QUADRATIC_SPHERE ? r * r : r;
        }
    }
    return 0.0f;
}

bool checker_first(float3 co, float scale) {
    const float3 p = scaled_nudged(co, scale);
    // Cycles takes |i| % 2 of each cell index; the low bit is the same parity.
    const unsigned xi = static_cast<unsigned>(floor_to_int(p.x)) & 1u;
    const unsigned yi = static_cast<unsigned>(floor_to_int(p.y)) & 1u;
    const unsigned zi = static_cast<unsigned>(floor_to_int(p.z)) & 1u;
    return (xi == yi) == (zi != 0);
}

// tint (per-brick noise plus bias, clamped) and mortar factor at p.
struct BrickSample {
    float tint;
    float mortar;
};

BrickSample brick(float3 p, const BrickTextureInputs& in, const BrickTextureParams& params) {
    float brick_width = in.brick_width;
    const float row_height = in.row_height;
    float offset = 0.0f;
    const int row = floor_to_int(p.y / row_height);
    if (params.offset_frequency != 0 && params.squash_frequency != 0) {
        brick_width *= (row % params.squash_frequency) != 0 ? 1.0f : params.squash;
        offset = (row % params.offset_frequency) != 0 ? 0.0f : brick_width * params.offset;
    }
    const float shifted = p.x + offset;
    const int column = floor_to_int(shifted / brick_width);
    const float x = shifted - brick_width * static_cast<float>(column);
    const float y = p.y - row_height * static_cast<float>(row);
    const unsigned id = (static_cast<unsigned>(row) << 16) + static_cast<unsigned>(column & 0xFFFF);
    const float tint = saturate(brick_noise(id) + in.bias);
    float edge = min_c(min_c(x, y), min_c(brick_width - x, row_height - y));
    float mortar;
    if (edge >= in.mortar_size) {
        mortar = 0.0f;
    } else if (in.mortar_smooth == 0.0f) {
        mortar = 1.0f;
    } else {
        edge = 1.0f - edge / in.mortar_size;
        if (edge < in.mortar_smooth) {
            const float t = edge / in.mortar_smooth;
            const float tt = t * t;
            mortar = madd(3.0f, tt, -(2.0f * tt * t));
        } else {
            mortar = 1.0f;
        }
    }
    return {tint, mortar};
}

// a (1 - t) + b t with the second product fused into the sum, as the kernel has it.
float3 mix_fused(float3 a, float3 b, float t) {
    const float u = 1.0f - t;
    return {madd(b.x, t, a.x * u), madd(b.y, t, a.y * u), madd(b.z, t, a.z * u)};
}

}  // namespace

WaveTextureOutput wave_texture(const WaveTextureInputs& in, const WaveTextureParams& params) {
    const float f = wave(params, in.vector, in.scale, in.distortion, in.detail, in.detail_scale,
                         in.detail_roughness, in.phase_offset);
    return {float3(f), f};
}

MagicTextureOutput magic_texture(const MagicTextureInputs& in, const MagicTextureParams& params) {
    const float3 c = magic(in.vector, in.scale, params.turbulence_depth, in.distortion);
    return {c, (c.x + c.y + c.z) * (1.0f / 3.0f)};
}

GradientTextureOutput gradient_texture(const GradientTextureInputs& in,
                                       const GradientTextureParams& params) {
    const float f = saturate(gradient(in.vector, params.type));
    return {float3(f), f};
}

CheckerTextureOutput checker_texture(const CheckerTextureInputs& in) {
    const bool first = checker_first(in.vector, in.scale);
    return {first ? in.color1 : in.color2, first ? 1.0f : 0.0f};
}

BrickTextureOutput brick_texture(const BrickTextureInputs& in, const BrickTextureParams& params) {
    const BrickSample s = brick(in.vector * in.scale, in, params);
    float3 color = in.color1;
    if (s.mortar != 1.0f) color = mix_fused(in.color1, in.color2, s.tint);
    return {mix_fused(color, in.mortar, s.mortar), s.mortar};
}

float brick_noise(unsigned n) {
    std::uint32_t v = (static_cast<std::uint32_t>(n) + 1013u) & 0x7fffffffu;
    v = (v >> 13) ^ v;
    const std::uint32_t m = (v * (v * v * 60493u + 19990303u) + 1376312589u) & 0x7fffffffu;
    return 0.5f * (static_cast<float>(m) / 1073741824.0f);
}

}  // namespace glint::render::shader
