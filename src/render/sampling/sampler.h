// Deterministic per-pixel random numbers for the path tracer: every value depends only on
// (pixel, sample index, dimension, seed), never on the thread or the order tiles run in, so
// the image is bit-identical whatever the thread count.
//
// Dimensions are consumed in pairs. Each pair is a 2D Sobol point (the first two Sobol
// dimensions, which are well stratified in 2D) whose index is shuffled per pixel and per pair
// and whose coordinates are Owen-scrambled, with the hash-based nested uniform scramble of
// Burley, "Practical Hash-based Owen Scrambling" (JCGT 2020). Pairs use independent seeds
// (the padding approach), so any number of dimensions is available without tables.
#pragma once

#include <cstdint>

namespace glint::render {

// A well-mixing 32-bit hash (the finalizer of a 32-bit murmur-style mix).
constexpr uint32_t hash_u32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}
constexpr uint32_t hash_combine(uint32_t seed, uint32_t v) {
    return hash_u32(seed ^ (v + 0x9e3779b9U + (seed << 6) + (seed >> 2)));
}

// The bytes reversed in one instruction, then the bits within each byte.
inline uint32_t reverse_bits32(uint32_t x) {
    x = __builtin_bswap32(x);
    x = ((x >> 1) & 0x55555555U) | ((x & 0x55555555U) << 1);
    x = ((x >> 2) & 0x33333333U) | ((x & 0x33333333U) << 2);
    return ((x >> 4) & 0x0f0f0f0fU) | ((x & 0x0f0f0f0fU) << 4);
}

// Laine-Karras style permutation: each bit is flipped depending only on the bits below it,
// which in bit-reversed order is a nested uniform (Owen) scramble.
constexpr uint32_t lk_permute(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cU;
    x ^= x * 0xb82f1e52U;
    x ^= x * 0xc7afe638U;
    x ^= x * 0x8d22f6e6U;
    return x;
}
inline uint32_t owen_scramble(uint32_t x, uint32_t seed) {
    return reverse_bits32(lk_permute(reverse_bits32(x), seed));
}

// Sobol dimension 0 (van der Corput) and 1, as 32-bit fixed-point fractions.
inline uint32_t sobol0(uint32_t i) { return reverse_bits32(i); }
// Dimension 1 is linear over GF(2) in the bits of i, so it is the XOR of four table lookups,
// one per byte of i (the tables hold the images of every byte value at each byte position):
// a constant number of operations instead of a loop over 32 direction numbers.
struct Sobol1Tables {
    uint32_t t[4][256];
    constexpr Sobol1Tables() : t() {
        uint32_t dir[32] = {};
        uint32_t v = 1U << 31;
        for (int k = 0; k < 32; ++k, v ^= v >> 1) dir[k] = v;
        for (int b = 0; b < 4; ++b)
            for (uint32_t x = 0; x < 256; ++x) {
                uint32_t r = 0;
                for (int k = 0; k < 8; ++k)
                    if (x & (1U << k)) r ^= dir[b * 8 + k];
                t[b][x] = r;
            }
    }
};
inline constexpr Sobol1Tables kSobol1{};
inline uint32_t sobol1(uint32_t i) {
    return kSobol1.t[0][i & 0xffU] ^ kSobol1.t[1][(i >> 8) & 0xffU] ^
           kSobol1.t[2][(i >> 16) & 0xffU] ^ kSobol1.t[3][i >> 24];
}
// reverse_bits32(sobol1(i)), linear too, so the same four lookups in tables of reversed
// values: what the Owen scramble of dimension 1 starts from.
struct ReversedSobol1Tables {
    uint32_t t[4][256];
    constexpr ReversedSobol1Tables() : t() {
        for (int b = 0; b < 4; ++b)
            for (int x = 0; x < 256; ++x) {
                uint32_t v = kSobol1.t[b][x], r = 0;
                for (int k = 0; k < 32; ++k)
                    if (v & (1U << k)) r |= 1U << (31 - k);
                t[b][x] = r;
            }
    }
};
inline constexpr ReversedSobol1Tables kReversedSobol1{};
inline uint32_t reversed_sobol1(uint32_t i) {
    return kReversedSobol1.t[0][i & 0xffU] ^ kReversedSobol1.t[1][(i >> 8) & 0xffU] ^
           kReversedSobol1.t[2][(i >> 16) & 0xffU] ^ kReversedSobol1.t[3][i >> 24];
}

// Largest double below 1, so samples stay in [0, 1).
constexpr double kOneMinusEpsilon = 0x1.fffffffffffffp-1;

inline double to_unit(uint32_t v) {
    double u = v * 0x1p-32;
    return u < kOneMinusEpsilon ? u : kOneMinusEpsilon;
}

struct Sample2 {
    double u = 0, v = 0;
};

class PixelSampler {
public:
    PixelSampler() = default;
    PixelSampler(int x, int y, uint32_t sample, uint32_t seed)
        : pixel_seed_(hash_combine(hash_combine(hash_combine(seed, static_cast<uint32_t>(x)),
                                                static_cast<uint32_t>(y)),
                                   0x5bd1e995U)),
          reversed_index_(reverse_bits32(sample)) {}

    // The pair of dimensions (2 * pair, 2 * pair + 1): with the shuffled index
    // i = owen_scramble(index, s) = reverse(lk_permute(reverse(index))), dimension 0 is
    // owen_scramble(sobol0(i)) = reverse(lk_permute(reverse(reverse(i)))) and dimension 1
    // owen_scramble(sobol1(i)) = reverse(lk_permute(reversed_sobol1(i))). The same numbers
    // with four bit reversals fewer: reverse(index) is made once, the others cancel.
    Sample2 get2(uint32_t pair) const {
        const uint32_t s = hash_combine(pixel_seed_, pair);
        const uint32_t i = reverse_bits32(lk_permute(reversed_index_, s));
        return {to_unit(reverse_bits32(lk_permute(i, hash_combine(s, 1)))),
                to_unit(reverse_bits32(lk_permute(reversed_sobol1(i), hash_combine(s, 2))))};
    }
    // One dimension: the first of a pair.
    double get1(uint32_t pair) const {
        const uint32_t s = hash_combine(pixel_seed_, pair);
        const uint32_t i = reverse_bits32(lk_permute(reversed_index_, s));
        return to_unit(reverse_bits32(lk_permute(i, hash_combine(s, 1))));
    }

private:
    uint32_t pixel_seed_ = 0;
    uint32_t reversed_index_ = 0;  // reverse_bits32 of the sample index
};

}  // namespace glint::render
