// The mesh kernels for any x86-64 (and any other CPU): the same code on four-double arrays.
#define GLINT_SIMD_NS kernels_base
#define GLINT_SIMD_NAME "base"
#include "render/shapes/mesh/mesh_kernels.inc"
