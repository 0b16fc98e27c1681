// Cycles' hash functions (Cycles 3.4, util/hash.h): Bob Jenkins' lookup3 mixing of one to
// four 32-bit words, and the float helpers built on it that hash the bit patterns of floats.
// White Noise, Voronoi, the Noise texture's seed offsets and the Object Info node's Random
// all read these, so they must give Cycles' bits exactly.
#pragma once

#include <cstdint>

#include "render/shader/float3.h"

namespace glint::render::shader {

namespace detail {

constexpr std::uint32_t rotl(std::uint32_t v, int k) { return (v << k) | (v >> (32 - k)); }

// lookup3's mix() and final() (http://burtleburtle.net/bob/c/lookup3.c), on three words.
// Inline: Perlin noise hashes eight corners per call, and volumes call it at every step.
struct Lookup3 {
    std::uint32_t a, b, c;

    explicit constexpr Lookup3(std::uint32_t words)
        : a(0xdeadbeefu + (words << 2) + 13u), b(a), c(a) {}

    constexpr void mix() {
        a -= c;
        a ^= rotl(c, 4);
        c += b;
        b -= a;
        b ^= rotl(a, 6);
        a += c;
        c -= b;
        c ^= rotl(b, 8);
        b += a;
        a -= c;
        a ^= rotl(c, 16);
        c += b;
        b -= a;
        b ^= rotl(a, 19);
        a += c;
        c -= b;
        c ^= rotl(b, 4);
        b += a;
    }

    constexpr void finish() {
        c ^= b;
        c -= rotl(b, 14);
        a ^= c;
        a -= rotl(c, 11);
        b ^= a;
        b -= rotl(a, 25);
        c ^= b;
        c -= rotl(b, 16);
        a ^= c;
        a -= rotl(c, 4);
        b ^= a;
        b -= rotl(a, 14);
        c ^= b;
        c -= rotl(b, 24);
    }
};

}  // namespace detail

// lookup3 hashes of one to four words (Cycles' hash_uint .. hash_uint4).
constexpr std::uint32_t hash_uint(std::uint32_t kx) {
    detail::Lookup3 h(1);
    h.a += kx;
    h.finish();
    return h.c;
}

constexpr std::uint32_t hash_uint2(std::uint32_t kx, std::uint32_t ky) {
    detail::Lookup3 h(2);
    h.b += ky;
    h.a += kx;
    h.finish();
    return h.c;
}

constexpr std::uint32_t hash_uint3(std::uint32_t kx, std::uint32_t ky, std::uint32_t kz) {
    detail::Lookup3 h(3);
    h.c += kz;
    h.b += ky;
    h.a += kx;
    h.finish();
    return h.c;
}

constexpr std::uint32_t hash_uint4(std::uint32_t kx, std::uint32_t ky, std::uint32_t kz,
                                   std::uint32_t kw) {
    detail::Lookup3 h(4);
    h.a += kx;
    h.b += ky;
    h.c += kz;
    h.mix();
    h.a += kw;
    h.finish();
    return h.c;
}

// [0, 2^32-1] -> [0, 1] inclusive, and [0, 1) exclusive (dividing by 4294967808).
float uint_to_float_incl(std::uint32_t n);
float uint_to_float_excl(std::uint32_t n);

// The word hashes mapped to [0, 1].
float hash_uint_to_float(std::uint32_t kx);
float hash_uint2_to_float(std::uint32_t kx, std::uint32_t ky);
float hash_uint3_to_float(std::uint32_t kx, std::uint32_t ky, std::uint32_t kz);
float hash_uint4_to_float(std::uint32_t kx, std::uint32_t ky, std::uint32_t kz, std::uint32_t kw);

// Floats hashed by their bit patterns into [0, 1]. Cycles' float2 arguments are passed as
// two floats here.
float hash_float_to_float(float k);
float hash_float2_to_float(float kx, float ky);
float hash_float3_to_float(float3 k);
float hash_float4_to_float(float4 k);

// Vector-valued hashes, each component in [0, 1]. hash_float2_to_float2 returns its pair in
// x and y (z is 0).
float3 hash_float2_to_float2(float kx, float ky);
float3 hash_float3_to_float3(float3 k);
float4 hash_float4_to_float4(float4 k);
float3 hash_float_to_float3(float k);
float3 hash_float2_to_float3(float kx, float ky);
float3 hash_float4_to_float3(float4 k);

// Cycles' string hash (i = i * 37 + c over the bytes, from i = 0).
std::uint32_t hash_string(const char* str);

}  // namespace glint::render::shader
