// The mesh kernels for CPUs with AVX2 (this file is built with -mavx2; mesh_kernels() calls it
// only where the CPU has AVX2).
#define GLINT_SIMD_NS kernels_avx2
#define GLINT_SIMD_NAME "avx2"
#include "render/shapes/mesh/mesh_kernels.inc"
