// Argument checking shared by the evaluators' EvalStencils (CpuEvaluator, TbbEvaluator), so that
// every evaluator accepts and rejects exactly the same calls.
#pragma once

#include "far/stencil_table.h"
#include "kernels/stencil_kernel.h"
#include "osd/buffer_descriptor.h"

namespace quadtri::detail {

// Checks the arguments of an EvalStencils call and resolves end < 0 to table.numStencils().
// Throws std::invalid_argument on an invalid descriptor, differing source and destination
// lengths, a range outside [0, table.numStencils()] or start > end, and (only when the range is
// not empty) a null buffer. Returns false when [start, end) is empty: nothing to evaluate.
bool checkEvalArguments(const float* src, const BufferDescriptor& srcDesc, const float* dst,
                        const BufferDescriptor& dstDesc, const StencilTable& table, int start, int& end);

// The table's arrays as the kernel reads them.
inline kernels::StencilArrays stencilArrays(const StencilTable& table) {
    return kernels::StencilArrays{table.offsets.data(), table.indices.data(), table.weightOffsets.data(),
                                  table.weights.data()};
}

}  // namespace quadtri::detail
