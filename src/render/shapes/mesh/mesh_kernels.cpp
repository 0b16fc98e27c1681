#include "render/shapes/mesh/mesh_kernels.h"

namespace glint::render {
namespace kernels_base {
extern const MeshKernels kKernels;
}
#if defined(__x86_64__) && defined(GLINT_HAVE_AVX2_KERNELS)
namespace kernels_avx2 {
extern const MeshKernels kKernels;
}
#endif

const MeshKernels& mesh_kernels_base() { return kernels_base::kKernels; }

const MeshKernels* mesh_kernels_avx2() {
#if defined(__x86_64__) && defined(GLINT_HAVE_AVX2_KERNELS)
    // Every CPU with AVX2 so far has FMA too, which the box test uses; asked for all the same.
    static const bool has = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return has ? &kernels_avx2::kKernels : nullptr;
#else
    return nullptr;
#endif
}

const MeshKernels& mesh_kernels() {
    static const MeshKernels& k = mesh_kernels_avx2() ? *mesh_kernels_avx2() : mesh_kernels_base();
    return k;
}

}  // namespace glint::render
