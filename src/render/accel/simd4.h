// Four doubles with the operations the mesh kernels need (mesh_kernels.inc). A translation unit
// built with AVX2 gets one ymm register per value; any other gets an array of four, on which
// the same IEEE operations in the same order give the same results bit for bit, so an image
// does not depend on the machine's instruction set. Each includer names its own namespace
// (GLINT_SIMD_NS) so that the two layouts never meet in one program under one name.
#pragma once

#ifndef GLINT_SIMD_NS
#error "define GLINT_SIMD_NS before including simd4.h"
#endif

#include <cmath>
#include <cstdint>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace glint::render::GLINT_SIMD_NS {

#if defined(__AVX2__)

struct D4 {
    __m256d v;
};
struct M4 {  // a lane mask
    __m256d v;
};

inline D4 splat(double a) { return {_mm256_set1_pd(a)}; }
inline D4 make4(double a, double b, double c, double d) { return {_mm256_setr_pd(a, b, c, d)}; }
// Four floats, widened exactly.
inline D4 from_floats(const float* p) { return {_mm256_cvtps_pd(_mm_loadu_ps(p))}; }
// Floats at p[idx[0]], ..., p[idx[3]].
inline D4 gather_floats(const float* p, const int32_t idx[4]) {
    const __m128i i = _mm_loadu_si128(reinterpret_cast<const __m128i*>(idx));
    return {_mm256_cvtps_pd(_mm_i32gather_ps(p, i, 4))};
}
inline D4 operator+(D4 a, D4 b) { return {_mm256_add_pd(a.v, b.v)}; }
inline D4 operator-(D4 a, D4 b) { return {_mm256_sub_pd(a.v, b.v)}; }
inline D4 operator*(D4 a, D4 b) { return {_mm256_mul_pd(a.v, b.v)}; }
inline D4 operator/(D4 a, D4 b) { return {_mm256_div_pd(a.v, b.v)}; }
inline D4 abs(D4 a) { return {_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)}; }
// a > b ? a : b and a < b ? a : b per lane, exactly (a NaN in a gives b).
inline D4 max(D4 a, D4 b) { return {_mm256_max_pd(a.v, b.v)}; }
inline D4 min(D4 a, D4 b) { return {_mm256_min_pd(a.v, b.v)}; }
inline M4 operator<(D4 a, D4 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)}; }
inline M4 operator<=(D4 a, D4 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)}; }
inline M4 operator>(D4 a, D4 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)}; }
inline M4 operator>=(D4 a, D4 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GE_OQ)}; }
inline M4 operator==(D4 a, D4 b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_EQ_OQ)}; }
inline M4 operator|(M4 a, M4 b) { return {_mm256_or_pd(a.v, b.v)}; }
inline M4 operator&(M4 a, M4 b) { return {_mm256_and_pd(a.v, b.v)}; }
inline M4 and_not(M4 a, M4 b) { return {_mm256_andnot_pd(b.v, a.v)}; }  // a and not b
inline M4 select(M4 m, M4 a, M4 b) { return {_mm256_blendv_pd(b.v, a.v, m.v)}; }
inline int bits(M4 m) { return _mm256_movemask_pd(m.v); }
inline D4 select(M4 m, D4 a, D4 b) { return {_mm256_blendv_pd(b.v, a.v, m.v)}; }
// The lanes whose sign bit is set (-0 and negative NaNs included).
inline M4 sign_mask(D4 a) {
    return {_mm256_castsi256_pd(
        _mm256_cmpgt_epi64(_mm256_setzero_si256(), _mm256_castpd_si256(a.v)))};
}
inline void store(double* out, D4 a) { _mm256_storeu_pd(out, a.v); }

// Each lane rounded to the nearest float.
inline void to_floats(D4 a, float out[4]) { _mm_storeu_ps(out, _mm256_cvtpd_ps(a.v)); }

#else

struct D4 {
    double v[4];
};
struct M4 {
    bool v[4];
};

#define GLINT_D4_LANES(expr)          \
    do {                              \
        for (int k = 0; k < 4; ++k) { \
            expr;                     \
        }                             \
    } while (0)

inline D4 splat(double a) { return {{a, a, a, a}}; }
inline D4 make4(double a, double b, double c, double d) { return {{a, b, c, d}}; }
inline D4 from_floats(const float* p) { return {{p[0], p[1], p[2], p[3]}}; }
inline D4 gather_floats(const float* p, const int32_t idx[4]) {
    return {{p[idx[0]], p[idx[1]], p[idx[2]], p[idx[3]]}};
}
inline D4 operator+(D4 a, D4 b) { D4 r; GLINT_D4_LANES(r.v[k] = a.v[k] + b.v[k]); return r; }
inline D4 operator-(D4 a, D4 b) { D4 r; GLINT_D4_LANES(r.v[k] = a.v[k] - b.v[k]); return r; }
inline D4 operator*(D4 a, D4 b) { D4 r; GLINT_D4_LANES(r.v[k] = a.v[k] * b.v[k]); return r; }
inline D4 operator/(D4 a, D4 b) { D4 r; GLINT_D4_LANES(r.v[k] = a.v[k] / b.v[k]); return r; }
inline D4 abs(D4 a) { D4 r; GLINT_D4_LANES(r.v[k] = std::fabs(a.v[k])); return r; }
inline D4 max(D4 a, D4 b) { D4 r; GLINT_D4_LANES(r.v[k] = a.v[k] > b.v[k] ? a.v[k] : b.v[k]); return r; }
inline D4 min(D4 a, D4 b) { D4 r; GLINT_D4_LANES(r.v[k] = a.v[k] < b.v[k] ? a.v[k] : b.v[k]); return r; }
inline M4 operator<(D4 a, D4 b) { M4 r; GLINT_D4_LANES(r.v[k] = a.v[k] < b.v[k]); return r; }
inline M4 operator<=(D4 a, D4 b) { M4 r; GLINT_D4_LANES(r.v[k] = a.v[k] <= b.v[k]); return r; }
inline M4 operator>(D4 a, D4 b) { M4 r; GLINT_D4_LANES(r.v[k] = a.v[k] > b.v[k]); return r; }
inline M4 operator>=(D4 a, D4 b) { M4 r; GLINT_D4_LANES(r.v[k] = a.v[k] >= b.v[k]); return r; }
inline M4 operator==(D4 a, D4 b) { M4 r; GLINT_D4_LANES(r.v[k] = a.v[k] == b.v[k]); return r; }
inline M4 operator|(M4 a, M4 b) { M4 r; GLINT_D4_LANES(r.v[k] = a.v[k] || b.v[k]); return r; }
inline M4 operator&(M4 a, M4 b) { M4 r; GLINT_D4_LANES(r.v[k] = a.v[k] && b.v[k]); return r; }
inline M4 and_not(M4 a, M4 b) { M4 r; GLINT_D4_LANES(r.v[k] = a.v[k] && !b.v[k]); return r; }
inline M4 select(M4 m, M4 a, M4 b) { M4 r; GLINT_D4_LANES(r.v[k] = m.v[k] ? a.v[k] : b.v[k]); return r; }
inline int bits(M4 m) { return m.v[0] | m.v[1] << 1 | m.v[2] << 2 | m.v[3] << 3; }
inline D4 select(M4 m, D4 a, D4 b) { D4 r; GLINT_D4_LANES(r.v[k] = m.v[k] ? a.v[k] : b.v[k]); return r; }
inline M4 sign_mask(D4 a) { M4 r; GLINT_D4_LANES(r.v[k] = std::signbit(a.v[k])); return r; }
inline void store(double* out, D4 a) { GLINT_D4_LANES(out[k] = a.v[k]); }

inline void to_floats(D4 a, float out[4]) { GLINT_D4_LANES(out[k] = static_cast<float>(a.v[k])); }

#undef GLINT_D4_LANES

#endif

}  // namespace glint::render::GLINT_SIMD_NS
