#include <quadtri/osd/tbb_evaluator.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "kernels/stencil_kernel.h"
#include "osd/internal/eval_arguments.h"

namespace quadtri {
inline namespace v0 {

namespace {

// Stencils per task (blocked_range splits down to blocks of kGrain/2..kGrain). A stencil costs
// ~4-8 ns at width 3 (6-14 entries), so a block is ~5-15 us of work, far above TBB's per-task
// cost. Measured on 2 idle cores: 48k- and 193k-stencil tables run ~2x faster with 2 threads than
// with 1 at any grain from 512 to 8192, and a 6k-stencil table still ~1.8x at this grain. Ranges
// shorter than two blocks run serially in the calling thread.
constexpr int kGrain = 2048;

}  // namespace

void TbbEvaluator::EvalStencils(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                const BufferDescriptor& dstDesc, const StencilTable& table, int start, int end) {
    if (!detail::checkEvalArguments(src != nullptr, srcDesc, dst != nullptr, dstDesc, table.numStencils(), start,
                                    end))
        return;
    const kernels::StencilArrays arrays = detail::stencilArrays(table);
    const float* s = src + srcDesc.offset;
    float* d = dst + dstDesc.offset;
    const int srcStride = srcDesc.stride, dstStride = dstDesc.stride, width = dstDesc.length;
    // Too few stencils to be worth splitting: run the kernel here, without spawning.
    if (end - start < 2 * kGrain) {
        kernels::evalStencils(s, srcStride, d, dstStride, width, arrays, start, end);
        return;
    }
    // Each block writes only its own destination rows; the tasks run in the caller's arena.
    tbb::parallel_for(tbb::blocked_range<int>(start, end, kGrain), [&](const tbb::blocked_range<int>& r) {
        kernels::evalStencils(s, srcStride, d, dstStride, width, arrays, r.begin(), r.end());
    });
}

}  // namespace v0
}  // namespace quadtri
