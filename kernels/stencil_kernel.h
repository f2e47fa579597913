// The stencil loop: dst[i] = sum_k w[k] * src[indices[offsets[i]+k]] for k < offsets[i+1] -
// offsets[i] and i in [start, end), with w = weights + weightOffsets[i] (the weight pool of
// StencilTable). The serial and threaded evaluators both call evalStencils (one kernel, so their
// results are bitwise equal); the Vulkan shader mirrors the portable loops. docs/stencil_kernel.md
// says what each path costs.
#pragma once

#include <quadtri/osd/stencil_runs.h>

namespace quadtri {
inline namespace v0 {
namespace kernels {

struct StencilArrays {
    const int* offsets;        // numStencils + 1
    const int* indices;
    const int* weightOffsets;  // numStencils
    const float* weights;
};

// A StencilRuns' runs over its table's arrays.
struct StencilRunArrays {
    StencilArrays table;
    const StencilRun* runs;
    int numRuns;
    const StencilGroup* groups;
    const int* order;
};

// Width known at compile time: the accumulator lives in registers and the inner loop unrolls.
template <int Width>
inline void evalStencilsFixed(const float* src, int srcStride, float* dst, int dstStride, const StencilArrays& t,
                              int start, int end) {
    for (int i = start; i < end; ++i) {
        float acc[Width] = {};
        const int first = t.offsets[i], n = t.offsets[i + 1] - first;
        const int* idx = t.indices + first;
        const float* w = t.weights + t.weightOffsets[i];
        for (int k = 0; k < n; ++k) {
            const float* s = src + static_cast<long>(idx[k]) * srcStride;
            const float wk = w[k];
            for (int c = 0; c < Width; ++c) acc[c] += wk * s[c];
        }
        float* d = dst + static_cast<long>(i) * dstStride;
        for (int c = 0; c < Width; ++c) d[c] = acc[c];
    }
}

// Any width: accumulates straight into the destination element.
inline void evalStencilsGeneric(const float* src, int srcStride, float* dst, int dstStride, int width,
                                const StencilArrays& t, int start, int end) {
    for (int i = start; i < end; ++i) {
        float* d = dst + static_cast<long>(i) * dstStride;
        for (int c = 0; c < width; ++c) d[c] = 0.0f;
        const int first = t.offsets[i], n = t.offsets[i + 1] - first;
        const int* idx = t.indices + first;
        const float* w = t.weights + t.weightOffsets[i];
        for (int k = 0; k < n; ++k) {
            const float* s = src + static_cast<long>(idx[k]) * srcStride;
            const float wk = w[k];
            for (int c = 0; c < width; ++c) d[c] += wk * s[c];
        }
    }
}

// The portable loops: one sum per component, entries in order, a multiply and an add each. The
// reference the fast paths are tested against, and the path for widths other than 3 and 4.
// src and dst point at element 0 (descriptor offsets already applied).
inline void evalStencilsPortable(const float* src, int srcStride, float* dst, int dstStride, int width,
                         const StencilArrays& t, int start, int end) {
    switch (width) {
    case 1: evalStencilsFixed<1>(src, srcStride, dst, dstStride, t, start, end); break;
    case 2: evalStencilsFixed<2>(src, srcStride, dst, dstStride, t, start, end); break;
    case 3: evalStencilsFixed<3>(src, srcStride, dst, dstStride, t, start, end); break;
    case 4: evalStencilsFixed<4>(src, srcStride, dst, dstStride, t, start, end); break;
    default: evalStencilsGeneric(src, srcStride, dst, dstStride, width, t, start, end); break;
    }
}

// Stencils [start, end) of any width (kernels/stencil_kernel.cpp). Widths 3 and 4 take the AVX2 +
// FMA loop (kernels/stencil_kernel_avx2.cpp) where the CPU has it, decided once per process:
// fused multiply-adds and two partial sums per stencil, so its bits differ from the portable
// loops' by float rounding, and width 3 and width 4 (padded) give the same bits as each other.
void evalStencils(const float* src, int srcStride, float* dst, int dstStride, int width, const StencilArrays& t,
                  int start, int end);

// evalStencils over the runs of a StencilRuns: the same bits (the runs only spare the loop the
// per-stencil arrays inside them), stencils [start, end) of any width.
void evalStencilRuns(const float* src, int srcStride, float* dst, int dstStride, int width,
                     const StencilRunArrays& r, int start, int end);

// Whether evalStencils takes the AVX2 + FMA loop for widths 3 and 4 on this CPU.
bool stencilKernelUsesAvx2();

// The AVX2 + FMA loops of width 3 and 4 (any strides of at least the width).
void evalStencils3Avx2(const float* src, int srcStride, float* dst, int dstStride, const StencilArrays& t, int start,
                       int end);
void evalStencils4Avx2(const float* src, int srcStride, float* dst, int dstStride, const StencilArrays& t, int start,
                       int end);
void evalStencilRuns3Avx2(const float* src, int srcStride, float* dst, int dstStride, const StencilRunArrays& r,
                          int start, int end);
void evalStencilRuns4Avx2(const float* src, int srcStride, float* dst, int dstStride, const StencilRunArrays& r,
                          int start, int end);

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
