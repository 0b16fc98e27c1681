#include "render/shader/cycles_hash.h"

#include <bit>

namespace glint::render::shader {
namespace {

using u32 = std::uint32_t;

u32 bits(float f) { return std::bit_cast<u32>(f); }

}  // namespace

float uint_to_float_incl(u32 n) {
    return static_cast<float>(n) * (1.0f / static_cast<float>(0xFFFFFFFFu));
}

float uint_to_float_excl(u32 n) { return static_cast<float>(n) * (1.0f / 4294967808.0f); }

float hash_uint_to_float(u32 kx) { return uint_to_float_incl(hash_uint(kx)); }
float hash_uint2_to_float(u32 kx, u32 ky) { return uint_to_float_incl(hash_uint2(kx, ky)); }
float hash_uint3_to_float(u32 kx, u32 ky, u32 kz) {
    return uint_to_float_incl(hash_uint3(kx, ky, kz));
}
float hash_uint4_to_float(u32 kx, u32 ky, u32 kz, u32 kw) {
    return uint_to_float_incl(hash_uint4(kx, ky, kz, kw));
}

float hash_float_to_float(float k) { return hash_uint_to_float(bits(k)); }
float hash_float2_to_float(float kx, float ky) { return hash_uint2_to_float(bits(kx), bits(ky)); }
float hash_float3_to_float(float3 k) {
    return hash_uint3_to_float(bits(k.x), bits(k.y), bits(k.z));
}
float hash_float4_to_float(float4 k) {
    return hash_uint4_to_float(bits(k.x), bits(k.y), bits(k.z), bits(k.w));
}

float3 hash_float2_to_float2(float kx, float ky) {
    return {hash_float2_to_float(kx, ky), hash_float3_to_float({kx, ky, 1.0f}), 0.0f};
}

float3 hash_float3_to_float3(float3 k) {
    return {hash_float3_to_float(k), hash_float4_to_float({k.x, k.y, k.z, 1.0f}),
            hash_float4_to_float({k.x, k.y, k.z, 2.0f})};
}

float4 hash_float4_to_float4(float4 k) {
    return {hash_float4_to_float(k), hash_float4_to_float({k.w, k.x, k.y, k.z}),
            hash_float4_to_float({k.z, k.w, k.x, k.y}), hash_float4_to_float({k.y, k.z, k.w, k.x})};
}

float3 hash_float_to_float3(float k) {
    return {hash_float_to_float(k), hash_float2_to_float(k, 1.0f), hash_float2_to_float(k, 2.0f)};
}

float3 hash_float2_to_float3(float kx, float ky) {
    return {hash_float2_to_float(kx, ky), hash_float3_to_float({kx, ky, 1.0f}),
            hash_float3_to_float({kx, ky, 2.0f})};
}

float3 hash_float4_to_float3(float4 k) {
    return {hash_float4_to_float(k), hash_float4_to_float({k.z, k.x, k.w, k.y}),
            hash_float4_to_float({k.w, k.z, k.y, k.x})};
}

u32 hash_string(const char* str) {
    u32 i = 0;
    // Cycles adds each char converted to uint, so bytes over 127 sign-extend as x86's signed
    // char does.
    for (; *str != '\0'; ++str) i = i * 37u + static_cast<u32>(static_cast<signed char>(*str));
    return i;
}

}  // namespace glint::render::shader
