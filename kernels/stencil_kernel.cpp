// The stencil kernel's entry point: the portable loops of kernels/stencil_kernel.h, or for 3- and
// 4-float data the AVX2 + FMA loops where the CPU has both (checked once per process).
#include "kernels/stencil_kernel.h"

#include "kernels/cpu_features.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {

bool stencilKernelUsesAvx2() { return cpuRunsAvx2Kernels(); }

void evalStencils(const float* src, int srcStride, float* dst, int dstStride, int width, const StencilArrays& t,
                  int start, int end) {
#if defined(QUADTRI_HAVE_AVX2_KERNELS)
    if ((width == 3 || width == 4) && stencilKernelUsesAvx2()) {
        if (width == 3)
            evalStencils3Avx2(src, srcStride, dst, dstStride, t, start, end);
        else
            evalStencils4Avx2(src, srcStride, dst, dstStride, t, start, end);
        return;
    }
#endif
    evalStencilsPortable(src, srcStride, dst, dstStride, width, t, start, end);
}

void evalStencilRuns(const float* src, int srcStride, float* dst, int dstStride, int width,
                     const StencilRunArrays& r, int start, int end) {
#if defined(QUADTRI_HAVE_AVX2_KERNELS)
    if ((width == 3 || width == 4) && stencilKernelUsesAvx2()) {
        if (width == 3)
            evalStencilRuns3Avx2(src, srcStride, dst, dstStride, r, start, end);
        else
            evalStencilRuns4Avx2(src, srcStride, dst, dstStride, r, start, end);
        return;
    }
#endif
    // The portable loops read every stencil's arrays anyway: the runs change nothing for them.
    evalStencilsPortable(src, srcStride, dst, dstStride, width, r.table, start, end);
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
