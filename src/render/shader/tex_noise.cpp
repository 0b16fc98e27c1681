#include "render/shader/tex_noise.h"

#include <climits>
#include <cmath>
#include <cstdint>

#include "render/shader/cycles_hash.h"

namespace glint::render::shader {
namespace {

using u32 = std::uint32_t;

// Small local point types for the 2D and 4D variants (float3 is the shared one).
struct V2 {
    float x, y;
};
struct V4 {
    float x, y, z, w;
};
V2 operator*(V2 a, float s) { return {a.x * s, a.y * s}; }
V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
V4 operator*(V4 a, float s) { return {a.x * s, a.y * s, a.z * s, a.w * s}; }
V4 operator+(V4 a, V4 b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
float4 to_float4(V4 a) { return {a.x, a.y, a.z, a.w}; }

// float -> int as x86's truncating conversion does: out of range and NaN give INT_MIN.
int trunc_to_int(float f) {
    return (f >= -2147483648.0f && f < 2147483648.0f) ? static_cast<int>(f) : INT_MIN;
}

// floor(x) as a cell index and x minus it.
float floor_frac(float x, u32& cell) {
    const float f = std::floor(x);
    cell = static_cast<u32>(trunc_to_int(f));
    return x - f;
}

float ensure_finite(float v) { return std::isfinite(v) ? v : 0.0f; }

// a * b + c rounded once. Blender's x86-64 CPU kernel (built for AVX2 with FMA and
// floating-point contraction) fuses these multiply-adds: the explicit madd() of its vector
// Perlin code and the ones the compiler contracted. Fusing the same ones here gives its
// values bit for bit (checked against Blender 3.4.1 renders); std::fma rounds the same way
// on any machine.
float madd(float a, float b, float c) { return std::fma(a, b, c); }

// Quintic fade 6t^5 - 15t^4 + 10t^3; the scalar 1D form and the vector kernels' form
// (t*t) * (t * ...) round differently, so both are kept.
float fade_poly(float t) { return madd(t, madd(t, 6.0f, -15.0f), 10.0f); }
float fade_scalar(float t) { return t * t * t * fade_poly(t); }
float fade_vector(float t) { return (t * t) * (t * fade_poly(t)); }

// The vector kernels' blend, t b + (1 - t) a.
float blend(float a, float b, float t) { return madd(t, b, (1.0f - t) * a); }

float flip_if(float v, u32 condition) { return condition != 0 ? -v : v; }

float grad1(u32 hash, float x) {
    const u32 h = hash & 15u;
    const float g = static_cast<float>(1u + (h & 7u));
    return flip_if(g, h & 8u) * x;
}

float grad2(u32 hash, float x, float y) {
    const u32 h = hash & 7u;
    const float u = h < 4 ? x : y;
    const float v = 2.0f * (h < 4 ? y : x);
    return flip_if(u, h & 1u) + flip_if(v, h & 2u);
}

float grad3(u32 hash, float x, float y, float z) {
    const u32 h = hash & 15u;
    const float u = h < 8 ? x : y;
    const float v = h < 4 ? y : ((h == 12 || h == 14) ? x : z);
    return flip_if(u, h & 1u) + flip_if(v, h & 2u);
}

float grad4(u32 hash, float x, float y, float z, float w) {
    const u32 h = hash & 31u;
    const float u = h < 24 ? x : y;
    const float v = h < 16 ? y : z;
    const float s = h < 8 ? z : w;
    return flip_if(u, h & 1u) + flip_if(v, h & 2u) + flip_if(s, h & 4u);
}

// ---- the Noise texture's seeds ----

float seed_offset(float seed, float component) {
    return 100.0f + hash_float2_to_float(seed, component) * 100.0f;
}
float seed_offset_1d(float seed) { return 100.0f + hash_float_to_float(seed) * 100.0f; }
V2 seed_offset_2d(float seed) { return {seed_offset(seed, 0.0f), seed_offset(seed, 1.0f)}; }
float3 seed_offset_3d(float seed) {
    return {seed_offset(seed, 0.0f), seed_offset(seed, 1.0f), seed_offset(seed, 2.0f)};
}
V4 seed_offset_4d(float seed) {
    return {seed_offset(seed, 0.0f), seed_offset(seed, 1.0f), seed_offset(seed, 2.0f),
            seed_offset(seed, 3.0f)};
}

// ---- dimension-generic helpers: one overload per point type ----

// Signed noise plus c, with the scale's multiply fused into the add as Cycles' kernel has it.
float perlin_at(float p) { return ensure_finite(perlin_1d(p)); }
float perlin_at(V2 p) { return ensure_finite(perlin_2d(p.x, p.y)); }
float perlin_at(float3 p) { return ensure_finite(perlin_3d(p.x, p.y, p.z)); }
float perlin_at(V4 p) { return ensure_finite(perlin_4d(p.x, p.y, p.z, p.w)); }
float scale_of(float) { return 0.25f; }
float scale_of(V2) { return 0.6616f; }
float scale_of(float3) { return 0.9820f; }
float scale_of(V4) { return 0.8344f; }
template <class P>
float snoise_plus(P p, float c) {
    return madd(scale_of(p), perlin_at(p), c);
}
float snoise_at(float p) { return snoise_1d(p); }
float snoise_at(V2 p) { return snoise_2d(p.x, p.y); }
float snoise_at(float3 p) { return snoise_3d(p); }
float snoise_at(V4 p) { return snoise_4d(to_float4(p)); }

float noise_at(float p) { return noise_1d(p); }
float noise_at(V2 p) { return noise_2d(p.x, p.y); }
float noise_at(float3 p) { return noise_3d(p); }
float noise_at(V4 p) { return noise_4d(to_float4(p)); }

template <class P>
float fractal_sum(P p, float octaves, float roughness) {
    float frequency = 1.0f;
    float amplitude = 1.0f;
    float total_amplitude = 0.0f;
    float sum = 0.0f;
    octaves = std::fmin(std::fmax(octaves, 0.0f), 15.0f);
    const float rough = std::fmin(std::fmax(roughness, 0.0f), 1.0f);
    const int whole = trunc_to_int(octaves);
    for (int i = 0; i <= whole; ++i) {
        sum = madd(noise_at(p * frequency), amplitude, sum);
        total_amplitude += amplitude;
        amplitude *= rough;
        frequency *= 2.0f;
    }
    const float part = octaves - std::floor(octaves);
    if (part == 0.0f) return sum / total_amplitude;
    const float extended = madd(noise_at(p * frequency), amplitude, sum);
    const float lower = sum / total_amplitude;
    const float upper = extended / (total_amplitude + amplitude);
    return (1.0f - part) * lower + part * upper;
}

// ---- Musgrave's five fractals (Musgrave et al., "Texturing and Modeling"), generic ----

template <class P>
float musgrave_fbm(P p, float H, float lacunarity, float octaves) {
    float value = 0.0f;
    float weight = 1.0f;
    const float gain_per_octave = std::pow(lacunarity, -H);
    const int whole = trunc_to_int(octaves);
    for (int i = 0; i < whole; ++i) {
        value = madd(snoise_at(p), weight, value);
        weight *= gain_per_octave;
        p = p * lacunarity;
    }
    const float part = octaves - std::floor(octaves);
    if (part != 0.0f) value = madd(part * snoise_at(p), weight, value);
    return value;
}

template <class P>
float musgrave_multifractal(P p, float H, float lacunarity, float octaves) {
    float value = 1.0f;
    float weight = 1.0f;
    const float gain_per_octave = std::pow(lacunarity, -H);
    const int whole = trunc_to_int(octaves);
    for (int i = 0; i < whole; ++i) {
        value *= madd(weight, snoise_at(p), 1.0f);
        weight *= gain_per_octave;
        p = p * lacunarity;
    }
    const float part = octaves - std::floor(octaves);
    if (part != 0.0f) value *= madd(part * weight, snoise_at(p), 1.0f);
    return value;
}

template <class P>
float musgrave_hetero_terrain(P p, float H, float lacunarity, float octaves, float offset) {
    const float gain_per_octave = std::pow(lacunarity, -H);
    float weight = gain_per_octave;
    float value = snoise_plus(p, offset);
    p = p * lacunarity;
    const int whole = trunc_to_int(octaves);
    for (int i = 1; i < whole; ++i) {
        value = madd(snoise_plus(p, offset) * weight, value, value);
        weight *= gain_per_octave;
        p = p * lacunarity;
    }
    const float part = octaves - std::floor(octaves);
    if (part != 0.0f) {
        const float increment = snoise_plus(p, offset) * weight * value;
        value = madd(part, increment, value);
    }
    return value;
}

template <class P>
float musgrave_hybrid_multifractal(P p, float H, float lacunarity, float octaves, float offset,
                                   float gain) {
    const float gain_per_octave = std::pow(lacunarity, -H);
    float amplitude = 1.0f;
    float value = 0.0f;
    float weight = 1.0f;
    const int whole = trunc_to_int(octaves);
    for (int i = 0; weight > 0.001f && i < whole; ++i) {
        if (weight > 1.0f) weight = 1.0f;
        const float signal = snoise_plus(p, offset) * amplitude;
        amplitude *= gain_per_octave;
        value = madd(weight, signal, value);
        weight *= gain * signal;
        p = p * lacunarity;
    }
    const float part = octaves - std::floor(octaves);
    if (part != 0.0f && weight > 0.001f) {
        if (weight > 1.0f) weight = 1.0f;
        const float signal = snoise_plus(p, offset) * amplitude;
        value = madd(part * weight, signal, value);
    }
    return value;
}

template <class P>
float musgrave_ridged_multifractal(P p, float H, float lacunarity, float octaves, float offset,
                                   float gain) {
    const float gain_per_octave = std::pow(lacunarity, -H);
    float amplitude = gain_per_octave;
    float signal = offset - std::fabs(snoise_at(p));
    signal *= signal;
    float value = signal;
    const int whole = trunc_to_int(octaves);
    for (int i = 1; i < whole; ++i) {
        p = p * lacunarity;
        const float weight = std::fmin(std::fmax(signal * gain, 0.0f), 1.0f);
        signal = offset - std::fabs(snoise_at(p));
        signal *= signal;
        signal *= weight;
        value = madd(signal, amplitude, value);
        amplitude *= gain_per_octave;
    }
    return value;
}

template <class P>
float musgrave_at(P p, const MusgraveTextureParams& params, float H, float lacunarity,
                  float octaves, float offset, float gain) {
    switch (params.type) {
        case MusgraveType::MULTIFRACTAL:
            return musgrave_multifractal(p, H, lacunarity, octaves);
        case MusgraveType::FBM:
            return musgrave_fbm(p, H, lacunarity, octaves);
        case MusgraveType::HYBRID_MULTIFRACTAL:
            return musgrave_hybrid_multifractal(p, H, lacunarity, octaves, offset, gain);
        case MusgraveType::RIDGED_MULTIFRACTAL:
            return musgrave_ridged_multifractal(p, H, lacunarity, octaves, offset, gain);
        case MusgraveType::HETERO_TERRAIN:
            return musgrave_hetero_terrain(p, H, lacunarity, octaves, offset);
    }
    return 0.0f;
}

}  // namespace

// ---- Perlin noise ----

// Each Perlin function is built three times, for x86-64 with AVX2 and FMA (Haswell on), with
// FMA alone and without, and the loader picks one: FMA fuses madd() in one instruction
// instead of a call to libm's fmaf, AVX2 hashes perlin_3d's eight corners in one register
// (together 1.5x on a volume of Noise). std::fma rounds once either way, the hashes are
// integer, and nothing else is contracted (ISO C++ mode), so all three give the same bits.
// (Not under AddressSanitizer: the loader runs the clones' resolver before the sanitizer's
// runtime is up.)
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__)
#define GLINT_FMA_CLONES __attribute__((target_clones("arch=haswell", "fma", "default")))
#else
#define GLINT_FMA_CLONES
#endif

GLINT_FMA_CLONES float perlin_1d(float x) {
    u32 X;
    const float fx = floor_frac(x, X);
    const float u = fade_scalar(fx);
    const float a = grad1(hash_uint(X), fx);
    const float b = grad1(hash_uint(X + 1u), fx - 1.0f);
    return a + u * (b - a);
}

GLINT_FMA_CLONES float perlin_2d(float x, float y) {
    u32 X, Y;
    const float fx = floor_frac(x, X), fy = floor_frac(y, Y);
    const float u = fade_vector(fx), v = fade_vector(fy);
    const float gx1 = fx - 1.0f, gy1 = fy - 1.0f;
    const float g00 = grad2(hash_uint2(X, Y), fx, fy);
    const float g01 = grad2(hash_uint2(X, Y + 1u), fx, gy1);
    const float g10 = grad2(hash_uint2(X + 1u, Y), gx1, fy);
    const float g11 = grad2(hash_uint2(X + 1u, Y + 1u), gx1, gy1);
    return blend(blend(g00, g10, u), blend(g01, g11, u), v);
}

GLINT_FMA_CLONES float perlin_3d(float x, float y, float z) {
    u32 C[3];
    const float f[3] = {floor_frac(x, C[0]), floor_frac(y, C[1]), floor_frac(z, C[2])};
    const float u = fade_vector(f[0]), v = fade_vector(f[1]), w = fade_vector(f[2]);
    // g[i][j][k]: the corner (X + i, Y + j, Z + k). The eight hashes side by side, one lane
    // each (the AVX2 build does them in one register).
    u32 h[8];
    for (u32 n = 0; n < 8; ++n)
        h[n] = hash_uint3(C[0] + (n >> 2), C[1] + ((n >> 1) & 1u), C[2] + (n & 1u));
    float g[2][2][2];
    for (u32 i = 0; i < 2; ++i)
        for (u32 j = 0; j < 2; ++j)
            for (u32 k = 0; k < 2; ++k)
                g[i][j][k] = grad3(h[i * 4 + j * 2 + k], i ? f[0] - 1.0f : f[0],
                                   j ? f[1] - 1.0f : f[1], k ? f[2] - 1.0f : f[2]);
    // Along x, then y, then z.
    float along_y[2];
    for (int k = 0; k < 2; ++k)
        along_y[k] = blend(blend(g[0][0][k], g[1][0][k], u), blend(g[0][1][k], g[1][1][k], u), v);
    return blend(along_y[0], along_y[1], w);
}

GLINT_FMA_CLONES float perlin_4d(float x, float y, float z, float w) {
    u32 C[4];
    const float f[4] = {floor_frac(x, C[0]), floor_frac(y, C[1]), floor_frac(z, C[2]),
                        floor_frac(w, C[3])};
    const float u = fade_vector(f[0]), v = fade_vector(f[1]), t = fade_vector(f[2]),
                s = fade_vector(f[3]);
    // The AVX kernel blends along w first, then x, y and z.
    float g[2][2][2];
    for (u32 i = 0; i < 2; ++i)
        for (u32 j = 0; j < 2; ++j)
            for (u32 k = 0; k < 2; ++k) {
                const float gx = i ? f[0] - 1.0f : f[0];
                const float gy = j ? f[1] - 1.0f : f[1];
                const float gz = k ? f[2] - 1.0f : f[2];
                const float w0 =
                    grad4(hash_uint4(C[0] + i, C[1] + j, C[2] + k, C[3]), gx, gy, gz, f[3]);
                const float w1 = grad4(hash_uint4(C[0] + i, C[1] + j, C[2] + k, C[3] + 1u), gx, gy,
                                       gz, f[3] - 1.0f);
                g[i][j][k] = blend(w0, w1, s);
            }
    float along_y[2];
    for (int k = 0; k < 2; ++k)
        along_y[k] = blend(blend(g[0][0][k], g[1][0][k], u), blend(g[0][1][k], g[1][1][k], u), v);
    return blend(along_y[0], along_y[1], t);
}

float snoise_1d(float p) { return 0.2500f * ensure_finite(perlin_1d(p)); }
float snoise_2d(float x, float y) { return 0.6616f * ensure_finite(perlin_2d(x, y)); }
float snoise_3d(float3 p) { return 0.9820f * ensure_finite(perlin_3d(p.x, p.y, p.z)); }
float snoise_4d(float4 p) { return 0.8344f * ensure_finite(perlin_4d(p.x, p.y, p.z, p.w)); }

float noise_1d(float p) { return 0.5f * snoise_1d(p) + 0.5f; }
float noise_2d(float x, float y) { return 0.5f * snoise_2d(x, y) + 0.5f; }
float noise_3d(float3 p) { return 0.5f * snoise_3d(p) + 0.5f; }
float noise_4d(float4 p) { return 0.5f * snoise_4d(p) + 0.5f; }

float fractal_noise_1d(float p, float octaves, float roughness) {
    return fractal_sum(p, octaves, roughness);
}
float fractal_noise_2d(float x, float y, float octaves, float roughness) {
    return fractal_sum(V2{x, y}, octaves, roughness);
}
float fractal_noise_3d(float3 p, float octaves, float roughness) {
    return fractal_sum(p, octaves, roughness);
}
float fractal_noise_4d(float4 p, float octaves, float roughness) {
    return fractal_sum(V4{p.x, p.y, p.z, p.w}, octaves, roughness);
}

// ---- Noise Texture ----

NoiseTextureOutput noise_texture(const NoiseTextureInputs& in, const NoiseTextureParams& params,
                                 bool color_needed) {
    const float3 co = in.vector * in.scale;
    const float w = in.w * in.scale;
    const float d = in.distortion;
    const float oct = in.detail;
    const float rough = in.roughness;
    NoiseTextureOutput out;
    switch (params.dimensions) {
        case NoiseDimensions::D1: {
            float p = w;
            if (d != 0.0f) p = madd(snoise_1d(p + seed_offset_1d(0.0f)), d, p);
            out.fac = fractal_sum(p, oct, rough);
            if (color_needed)
                out.color = {out.fac, fractal_sum(p + seed_offset_1d(1.0f), oct, rough),
                             fractal_sum(p + seed_offset_1d(2.0f), oct, rough)};
            break;
        }
        case NoiseDimensions::D2: {
            V2 p{co.x, co.y};
            if (d != 0.0f)
                p = V2{madd(snoise_at(p + seed_offset_2d(0.0f)), d, p.x),
                       madd(snoise_at(p + seed_offset_2d(1.0f)), d, p.y)};
            out.fac = fractal_sum(p, oct, rough);
            if (color_needed)
                out.color = {out.fac, fractal_sum(p + seed_offset_2d(2.0f), oct, rough),
                             fractal_sum(p + seed_offset_2d(3.0f), oct, rough)};
            break;
        }
        case NoiseDimensions::D3: {
            // Here the kernel adds the distortion without fusing (float3 is an SSE vector).
            float3 p = co;
            if (d != 0.0f)
                p += float3(snoise_3d(p + seed_offset_3d(0.0f)) * d,
                            snoise_3d(p + seed_offset_3d(1.0f)) * d,
                            snoise_3d(p + seed_offset_3d(2.0f)) * d);
            out.fac = fractal_sum(p, oct, rough);
            if (color_needed)
                out.color = {out.fac, fractal_sum(p + seed_offset_3d(3.0f), oct, rough),
                             fractal_sum(p + seed_offset_3d(4.0f), oct, rough)};
            break;
        }
        case NoiseDimensions::D4: {
            V4 p{co.x, co.y, co.z, w};
            if (d != 0.0f)
                p = V4{madd(snoise_at(p + seed_offset_4d(0.0f)), d, p.x),
                       madd(snoise_at(p + seed_offset_4d(1.0f)), d, p.y),
                       madd(snoise_at(p + seed_offset_4d(2.0f)), d, p.z),
                       madd(snoise_at(p + seed_offset_4d(3.0f)), d, p.w)};
            out.fac = fractal_sum(p, oct, rough);
            if (color_needed)
                out.color = {out.fac, fractal_sum(p + seed_offset_4d(4.0f), oct, rough),
                             fractal_sum(p + seed_offset_4d(5.0f), oct, rough)};
            break;
        }
    }
    return out;
}

// ---- Musgrave Texture ----

MusgraveTextureOutput musgrave_texture(const MusgraveTextureInputs& in,
                                       const MusgraveTextureParams& params) {
    const float H = std::fmax(in.dimension, 1e-5f);
    const float octaves = std::fmin(std::fmax(in.detail, 0.0f), 15.0f);
    const float lacunarity = std::fmax(in.lacunarity, 1e-5f);
    const float s = in.scale;
    MusgraveTextureOutput out;
    switch (params.dimensions) {
        case NoiseDimensions::D1:
            out.fac = musgrave_at(in.w * s, params, H, lacunarity, octaves, in.offset, in.gain);
            break;
        case NoiseDimensions::D2:
            out.fac = musgrave_at(V2{in.vector.x, in.vector.y} * s, params, H, lacunarity, octaves,
                                  in.offset, in.gain);
            break;
        case NoiseDimensions::D3:
            out.fac =
                musgrave_at(in.vector * s, params, H, lacunarity, octaves, in.offset, in.gain);
            break;
        case NoiseDimensions::D4:
            out.fac = musgrave_at(V4{in.vector.x, in.vector.y, in.vector.z, in.w} * s, params, H,
                                  lacunarity, octaves, in.offset, in.gain);
            break;
    }
    return out;
}

// ---- White Noise Texture ----

WhiteNoiseOutput white_noise_texture(const WhiteNoiseInputs& in, const WhiteNoiseParams& params) {
    const float3 v = in.vector;
    WhiteNoiseOutput out;
    switch (params.dimensions) {
        case NoiseDimensions::D1:
            out.value = hash_float_to_float(in.w);
            out.color = hash_float_to_float3(in.w);
            break;
        case NoiseDimensions::D2:
            out.value = hash_float2_to_float(v.x, v.y);
            out.color = hash_float2_to_float3(v.x, v.y);
            break;
        case NoiseDimensions::D3:
            out.value = hash_float3_to_float(v);
            out.color = hash_float3_to_float3(v);
            break;
        case NoiseDimensions::D4:
            out.value = hash_float4_to_float({v.x, v.y, v.z, in.w});
            out.color = hash_float4_to_float3({v.x, v.y, v.z, in.w});
            break;
    }
    return out;
}

}  // namespace glint::render::shader
