// Blender's Noise Texture, Musgrave Texture and White Noise Texture nodes, evaluated as
// Cycles 3.4 evaluates them (kernel/svm/noise.h, fractal_noise.h, noisetex.h, musgrave.h,
// white_noise.h): the same lookup3 hashes, the same gradient tables and scale factors, the
// same octave loops, in single precision. The arithmetic follows Blender's x86-64 CPU kernel
// (its AVX2 variant: the vector Perlin code's interpolation order and the multiply-adds it
// fuses), so values match Blender 3.4.1's renders bit for bit but for a rare last-bit
// difference in 1D noise.
#pragma once

#include "render/shader/float3.h"

namespace glint::render::shader {

// The dimension menus of the Noise, Musgrave, Voronoi and White Noise nodes ('1D' .. '4D').
// 1D reads W only, 2D reads Vector.xy, 3D Vector, 4D Vector and W.
enum class NoiseDimensions { D1 = 1, D2 = 2, D3 = 3, D4 = 4 };

// ---- Perlin noise (Cycles' perlin_Nd, snoise_Nd, noise_Nd) ----

// Raw gradient noise at a point.
float perlin_1d(float x);
float perlin_2d(float x, float y);
float perlin_3d(float x, float y, float z);
float perlin_4d(float x, float y, float z, float w);

// Signed noise, about [-1, 1]: the raw noise (0 where it is not finite) times Cycles' per
// dimension factor (0.25, 0.6616, 0.982, 0.8344).
float snoise_1d(float p);
float snoise_2d(float x, float y);
float snoise_3d(float3 p);
float snoise_4d(float4 p);

// Unsigned noise, 0.5 * snoise + 0.5.
float noise_1d(float p);
float noise_2d(float x, float y);
float noise_3d(float3 p);
float noise_4d(float4 p);

// Fractal sum of unsigned noise: octaves in [0, 15] (a fractional part blends in one more
// octave), each at twice the frequency and roughness (clamped to [0, 1]) times the amplitude
// of the one before, normalized by the sum of amplitudes. Result in about [0, 1].
float fractal_noise_1d(float p, float octaves, float roughness);
float fractal_noise_2d(float x, float y, float octaves, float roughness);
float fractal_noise_3d(float3 p, float octaves, float roughness);
float fractal_noise_4d(float4 p, float octaves, float roughness);

// ---- Noise Texture (ShaderNodeTexNoise) ----

struct NoiseTextureParams {
    NoiseDimensions dimensions = NoiseDimensions::D3;  // noise_dimensions
};

// The node's input sockets, with Blender's defaults.
struct NoiseTextureInputs {
    float3 vector;
    float w = 0.0f;
    float scale = 5.0f;
    float detail = 2.0f;
    float roughness = 0.5f;
    float distortion = 0.0f;
};

struct NoiseTextureOutput {
    float fac = 0.0f;
    float3 color;  // (fac, two more fractal noises at Cycles' seeded offsets)
};

// Color is computed only when color_needed (Cycles skips it when the socket is unlinked);
// otherwise it is left zero.
NoiseTextureOutput noise_texture(const NoiseTextureInputs& in, const NoiseTextureParams& params,
                                 bool color_needed = true);

// ---- Musgrave Texture (ShaderNodeTexMusgrave) ----

enum class MusgraveType {
    MULTIFRACTAL,
    RIDGED_MULTIFRACTAL,
    HYBRID_MULTIFRACTAL,
    FBM,
    HETERO_TERRAIN,
};

struct MusgraveTextureParams {
    MusgraveType type = MusgraveType::FBM;             // musgrave_type
    NoiseDimensions dimensions = NoiseDimensions::D3;  // musgrave_dimensions
};

struct MusgraveTextureInputs {
    float3 vector;
    float w = 0.0f;
    float scale = 5.0f;
    float detail = 2.0f;
    float dimension = 2.0f;
    float lacunarity = 2.0f;
    float offset = 0.0f;
    float gain = 1.0f;
};

struct MusgraveTextureOutput {
    float fac = 0.0f;
};

MusgraveTextureOutput musgrave_texture(const MusgraveTextureInputs& in,
                                       const MusgraveTextureParams& params);

// ---- White Noise Texture (ShaderNodeTexWhiteNoise) ----

struct WhiteNoiseParams {
    NoiseDimensions dimensions = NoiseDimensions::D3;  // noise_dimensions
};

struct WhiteNoiseInputs {
    float3 vector;
    float w = 0.0f;
};

struct WhiteNoiseOutput {
    float value = 0.0f;  // in [0, 1]
    float3 color;        // each component in [0, 1]
};

WhiteNoiseOutput white_noise_texture(const WhiteNoiseInputs& in, const WhiteNoiseParams& params);

}  // namespace glint::render::shader
