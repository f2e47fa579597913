// The level-patch kernel's entry point: the loops of kernels/patch_kernel_loops.h for the baseline
// CPU, or their AVX2 + FMA build where the CPU has both (checked once per process).
#include "kernels/patch_kernel.h"

#include "kernels/cpu_features.h"
#include "kernels/patch_kernel_loops.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {

void evalLevelPatches(const float* src, int srcStride, const LevelPatchArrays& a, float* position, int positionStride,
                      float* normal, int normalStride, int start, int end) {
#if defined(QUADTRI_HAVE_AVX2_KERNELS)
    if (cpuRunsAvx2Kernels()) {
        evalLevelPatchesAvx2(src, srcStride, a, position, positionStride, normal, normalStride, start, end);
        return;
    }
#endif
    levelPatchLoop(src, srcStride, a, position, positionStride, normal, normalStride, start, end);
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
