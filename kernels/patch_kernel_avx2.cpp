// The level-patch loops built with AVX2 + FMA (kernels/patch_kernel.cpp picks them at run time).
#include "kernels/patch_kernel.h"
#include "kernels/patch_kernel_loops.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {

void evalLevelPatchesAvx2(const float* src, int srcStride, const LevelPatchArrays& a, float* position,
                          int positionStride, float* normal, int normalStride, int start, int end) {
    levelPatchLoop(src, srcStride, a, position, positionStride, normal, normalStride, start, end);
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
