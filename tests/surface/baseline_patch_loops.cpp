// The level-patch loops as the library's baseline build has them (on x86-64 the one-point-a-register
// SSE loops), for test_level_patches: a CPU with AVX2 runs the library's 8-wide loops instead,
// so the tests call these directly.
#include "kernels/patch_kernel_loops.h"

namespace quadtri::test {

void baselinePatchLoop(const float* src, const kernels::LevelPatchArrays& a, float* position, float* normal,
                       int numPatches) {
    kernels::levelPatchLoop(src, 3, a, position, 3, normal, 3, 0, numPatches);
}

}  // namespace quadtri::test
