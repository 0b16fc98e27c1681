// Blender's Wave, Magic, Gradient, Checker and Brick Texture nodes evaluated as Cycles 3.4
// evaluates them (kernel/svm/wave.h, magic.h, gradient.h, checker.h, brick.h), in single
// precision and with the arithmetic of Blender's x86-64 CPU kernel, so values match Blender's
// renders. Each takes the node's input sockets (Blender's defaults in the structs) and its
// enum/int settings, and gives its outputs.
#pragma once

#include "render/shader/float3.h"

namespace glint::render::shader {

// ---- Wave Texture (ShaderNodeTexWave) ----

enum class WaveType { BANDS, RINGS };
enum class WaveBandsDirection { X, Y, Z, DIAGONAL };
enum class WaveRingsDirection { X, Y, Z, SPHERICAL };
enum class WaveProfile { SIN, SAW, TRI };

struct WaveTextureParams {
    WaveType type = WaveType::BANDS;                             // wave_type
    WaveBandsDirection bands_direction = WaveBandsDirection::X;  // bands_direction
    WaveRingsDirection rings_direction = WaveRingsDirection::X;  // rings_direction
    WaveProfile profile = WaveProfile::SIN;                      // wave_profile
};

struct WaveTextureInputs {
    float3 vector;
    float scale = 5.0f;
    float distortion = 0.0f;
    float detail = 2.0f;
    float detail_scale = 1.0f;
    float detail_roughness = 0.5f;
    float phase_offset = 0.0f;
};

struct WaveTextureOutput {
    float3 color;  // (fac, fac, fac)
    float fac = 0.0f;
};

WaveTextureOutput wave_texture(const WaveTextureInputs& in, const WaveTextureParams& params);

// ---- Magic Texture (ShaderNodeTexMagic) ----

struct MagicTextureParams {
    int turbulence_depth = 2;  // 0 .. 10
};

struct MagicTextureInputs {
    float3 vector;
    float scale = 5.0f;
    float distortion = 1.0f;
};

struct MagicTextureOutput {
    float3 color;
    float fac = 0.0f;  // the colour's average
};

MagicTextureOutput magic_texture(const MagicTextureInputs& in, const MagicTextureParams& params);

// ---- Gradient Texture (ShaderNodeTexGradient) ----

enum class GradientType {
    LINEAR,
    QUADRATIC,
    EASING,
    DIAGONAL,
    SPHERICAL,
    QUADRATIC_SPHERE,
    RADIAL,
};

struct GradientTextureParams {
    GradientType type = GradientType::LINEAR;  // gradient_type
};

struct GradientTextureInputs {
    float3 vector;
};

struct GradientTextureOutput {
    float3 color;      // (fac, fac, fac)
    float fac = 0.0f;  // clamped to [0, 1]
};

GradientTextureOutput gradient_texture(const GradientTextureInputs& in,
                                       const GradientTextureParams& params);

// ---- Checker Texture (ShaderNodeTexChecker; no settings) ----

struct CheckerTextureInputs {
    float3 vector;
    float3 color1{0.8f};
    float3 color2{0.2f};
    float scale = 5.0f;
};

struct CheckerTextureOutput {
    float3 color;
    float fac = 0.0f;  // 1 where color1 shows, 0 where color2
};

CheckerTextureOutput checker_texture(const CheckerTextureInputs& in);

// ---- Brick Texture (ShaderNodeTexBrick) ----

struct BrickTextureParams {
    float offset = 0.5f;       // offset: shift of every offset_frequency-th row, in bricks
    int offset_frequency = 2;  // 1 .. 99
    float squash = 1.0f;       // squash: brick width factor of every squash_frequency-th row
    int squash_frequency = 2;  // 1 .. 99
};

struct BrickTextureInputs {
    float3 vector;
    float3 color1{0.8f};
    float3 color2{0.2f};
    float3 mortar{0.0f};
    float scale = 5.0f;
    float mortar_size = 0.02f;
    float mortar_smooth = 0.1f;
    float bias = 0.0f;
    float brick_width = 0.5f;
    float row_height = 0.25f;
};

struct BrickTextureOutput {
    float3 color;      // brick colour (color1..color2 by Cycles' per-brick noise and bias),
                       // blended to mortar by fac
    float fac = 0.0f;  // mortar: 1 in the mortar, 0 inside a brick
};

BrickTextureOutput brick_texture(const BrickTextureInputs& in, const BrickTextureParams& params);

// Cycles' per-brick integer noise in [0, 1) (brick.h's brick_noise).
float brick_noise(unsigned n);

}  // namespace glint::render::shader
