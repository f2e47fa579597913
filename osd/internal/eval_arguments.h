// Argument checking shared by every evaluator's EvalStencils (CpuEvaluator, TbbEvaluator,
// VulkanEvaluator), so that all of them accept and reject exactly the same calls with the same
// messages.
#pragma once

#include <quadtri/far/stencil_table.h>
#include "kernels/stencil_kernel.h"
#include <quadtri/osd/buffer_descriptor.h>

namespace quadtri {
inline namespace v0 {
namespace detail {

// Checks the arguments of an EvalStencils call over a table of `numStencils` stencils and
// resolves end < 0 to numStencils. srcPresent / dstPresent say whether the caller passed a
// buffer (a non-null pointer on the host, a non-null VkBuffer on a device). Throws
// std::invalid_argument on an invalid descriptor, differing source and destination lengths, a
// range outside [0, numStencils] or start > end, and (only when the range is not empty) a
// missing buffer. Returns false when [start, end) is empty: nothing to evaluate.
bool checkEvalArguments(bool srcPresent, const BufferDescriptor& srcDesc, bool dstPresent,
                        const BufferDescriptor& dstDesc, int numStencils, int start, int& end);

// The table's arrays as the kernel reads them.
inline kernels::StencilArrays stencilArrays(const StencilTable& table) {
    return kernels::StencilArrays{table.offsets.data(), table.indices.data(), table.weightOffsets.data(),
                                  table.weights.data()};
}

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
