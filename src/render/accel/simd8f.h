// Eight floats with the operations the eight-wide box test needs (mesh_kernels.inc), on the
// pattern of simd4.h: one ymm register in a translation unit built with AVX2, an array of eight
// elsewhere, the same IEEE operations in the same order either way. The includer names the
// namespace (GLINT_SIMD_NS).
#pragma once

#ifndef GLINT_SIMD_NS
#error "define GLINT_SIMD_NS before including simd8f.h"
#endif

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace glint::render::GLINT_SIMD_NS {

#if defined(__AVX2__)

struct F8 {
    __m256 v;
};

inline F8 splat8(float a) { return {_mm256_set1_ps(a)}; }
inline F8 load8(const float* p) { return {_mm256_load_ps(p)}; }  // 32-byte aligned
inline F8 operator-(F8 a, F8 b) { return {_mm256_sub_ps(a.v, b.v)}; }
inline F8 operator*(F8 a, F8 b) { return {_mm256_mul_ps(a.v, b.v)}; }
// a * b + c: rounded once with FMA (the AVX2 kernels are built with it), twice without. Only
// for bounds whose margins cover either.
#if defined(__FMA__)
inline F8 fmadd(F8 a, F8 b, F8 c) { return {_mm256_fmadd_ps(a.v, b.v, c.v)}; }
#else
inline F8 fmadd(F8 a, F8 b, F8 c) { return {_mm256_add_ps(_mm256_mul_ps(a.v, b.v), c.v)}; }
#endif
// a > b ? a : b and a < b ? a : b per lane (a NaN in a gives b), as vmaxps and vminps do.
inline F8 max(F8 a, F8 b) { return {_mm256_max_ps(a.v, b.v)}; }
inline F8 min(F8 a, F8 b) { return {_mm256_min_ps(a.v, b.v)}; }
// The lanes where a <= b, as bits.
inline int le_bits(F8 a, F8 b) { return _mm256_movemask_ps(_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)); }
inline void store8(float* out, F8 a) { _mm256_storeu_ps(out, a.v); }

#else

struct F8 {
    float v[8];
};

#define GLINT_F8_LANES(expr)          \
    do {                              \
        for (int k = 0; k < 8; ++k) { \
            expr;                     \
        }                             \
    } while (0)

inline F8 splat8(float a) { F8 r; GLINT_F8_LANES(r.v[k] = a); return r; }
inline F8 load8(const float* p) { F8 r; GLINT_F8_LANES(r.v[k] = p[k]); return r; }
inline F8 operator-(F8 a, F8 b) { F8 r; GLINT_F8_LANES(r.v[k] = a.v[k] - b.v[k]); return r; }
inline F8 operator*(F8 a, F8 b) { F8 r; GLINT_F8_LANES(r.v[k] = a.v[k] * b.v[k]); return r; }
inline F8 fmadd(F8 a, F8 b, F8 c) { F8 r; GLINT_F8_LANES(r.v[k] = a.v[k] * b.v[k] + c.v[k]); return r; }
inline F8 max(F8 a, F8 b) { F8 r; GLINT_F8_LANES(r.v[k] = a.v[k] > b.v[k] ? a.v[k] : b.v[k]); return r; }
inline F8 min(F8 a, F8 b) { F8 r; GLINT_F8_LANES(r.v[k] = a.v[k] < b.v[k] ? a.v[k] : b.v[k]); return r; }
inline int le_bits(F8 a, F8 b) { int m = 0; GLINT_F8_LANES(m |= (a.v[k] <= b.v[k]) << k); return m; }
inline void store8(float* out, F8 a) { GLINT_F8_LANES(out[k] = a.v[k]); }

#undef GLINT_F8_LANES

#endif

}  // namespace glint::render::GLINT_SIMD_NS
