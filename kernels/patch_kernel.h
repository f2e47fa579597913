// The level-patch loop, shared by the serial and threaded evaluators (docs/patches.md): each
// regular patch gathers its points once and writes its grid's vertices through its basis. The
// tangents are summed relative to the first point, as the limit loop sums them
// (kernels/limit_kernel.h), and the normal is their normalised cross product, (0, 0, 0) where
// they are parallel.
#pragma once

#include <cstdint>

namespace quadtri {
inline namespace v0 {
namespace kernels {

// The largest rate (LevelPatchTable::kMaxRate): a grid line's index fits a byte.
constexpr int kMaxRate = 128;

// LevelPatchTable's arrays (far/level_patch_table.h).
struct LevelPatchArrays {
    int rate;
    const std::uint8_t* patchBasis;
    const int* pointOffsets;
    const int* patchPoints;
    const int* outputOffsets;
    const std::uint16_t* outputCells;
    const float* curveWeights;
    const float* boxSplineWeights;
    int lineWidth;  // the same weights as runs over the grid lines, for the 8-wide loops
    const float* curveWeightLines;
    const float* boxSplineWeightLines;
};

// Patches [start, end) from 3-float sources, output o written at element o (positions, normals:
// either may be null). The table's stencils are the limit loop's (kernels/limit_kernel.h), their
// outputs starting at element numPatchOutputs.
void evalLevelPatches(const float* src, int srcStride, const LevelPatchArrays& a, float* position, int positionStride,
                      float* normal, int normalStride, int start, int end);
// The same loops built with AVX2 + FMA (patch_kernel_avx2.cpp), where built in.
void evalLevelPatchesAvx2(const float* src, int srcStride, const LevelPatchArrays& a, float* position,
                          int positionStride, float* normal, int normalStride, int start, int end);

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
