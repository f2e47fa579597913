// The limit kernel's entry point: the portable loops of kernels/limit_kernel.h, or for 3-float
// data the AVX2 + FMA loop where the CPU has both (checked once per process).
#include "kernels/limit_kernel.h"

#include "kernels/cpu_features.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {

bool limitKernelUsesAvx2() { return cpuRunsAvx2Kernels(); }

void degenerateNormalOutOfLine(const float* src, int srcStride, const LimitOutputs& o, int i, float* d) {
    degenerateNormal(src, srcStride, o, i, d);
}

void evalLimitStencils(const float* src, int srcStride, int width, const LimitStencilArrays& t, const LimitOutputs& o,
                       int start, int end) {
#if defined(QUADTRI_HAVE_AVX2_KERNELS)
    if (width == 3 && limitKernelUsesAvx2()) {
        evalLimit3Avx2(src, srcStride, t, o, start, end);
        return;
    }
#endif
    evalLimitPortable(src, srcStride, width, t, o, start, end);
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
