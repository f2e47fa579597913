#include "osd/cpu_evaluator.h"

#include <stdexcept>
#include <string>

#include "kernels/stencil_kernel.h"

namespace quadtri {

void CpuEvaluator::EvalStencils(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                const BufferDescriptor& dstDesc, const StencilTable& table, int start, int end) {
    if (end < 0) end = table.numStencils();
    if (!srcDesc.isValid() || !dstDesc.isValid())
        throw std::invalid_argument("EvalStencils: invalid BufferDescriptor (need length > 0, stride >= length, offset >= 0)");
    if (srcDesc.length != dstDesc.length)
        throw std::invalid_argument("EvalStencils: source length " + std::to_string(srcDesc.length) +
                                    " differs from destination length " + std::to_string(dstDesc.length));
    if (start < 0 || start > end || end > table.numStencils())
        throw std::invalid_argument("EvalStencils: range [" + std::to_string(start) + ", " + std::to_string(end) +
                                    ") outside the table's " + std::to_string(table.numStencils()) + " stencils");
    if (start == end) return;
    if (!src || !dst) throw std::invalid_argument("EvalStencils: null buffer");
    const kernels::StencilArrays arrays{table.sizes.data(), table.offsets.data(), table.indices.data(),
                                        table.weights.data()};
    kernels::evalStencils(src + srcDesc.offset, srcDesc.stride, dst + dstDesc.offset, dstDesc.stride, dstDesc.length,
                          arrays, start, end);
}

}  // namespace quadtri
