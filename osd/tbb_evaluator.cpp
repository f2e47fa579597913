#include <quadtri/osd/tbb_evaluator.h>

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "kernels/limit_kernel.h"
#include "kernels/patch_kernel.h"
#include "kernels/mesh_normal_kernel.h"
#include "kernels/stencil_kernel.h"
#include "osd/internal/eval_arguments.h"

namespace quadtri {
inline namespace v0 {

namespace {

// Stencils per task (blocked_range splits down to blocks of kGrain/2..kGrain): a block is
// microseconds of work, far above TBB's per-task cost, and small tables still split in two
// (docs/threads.md). Ranges shorter than two blocks run serially in the calling thread.
constexpr int kGrain = 2048;

// Runs body(begin, end) over [start, end): serially when the range is under two blocks of `grain`,
// else in blocks on the caller's arena (each block writes only its own rows).
template <class Body>
void forBlocks(int start, int end, int grain, const Body& body) {
    if (end - start < 2 * grain) {
        body(start, end);
        return;
    }
    tbb::parallel_for(tbb::blocked_range<int>(start, end, grain),
                      [&](const tbb::blocked_range<int>& r) { body(r.begin(), r.end()); });
}

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
    forBlocks(start, end, kGrain,
              [&](int b, int e) { kernels::evalStencils(s, srcStride, d, dstStride, width, arrays, b, e); });
}

void TbbEvaluator::EvalStencilRuns(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                   const BufferDescriptor& dstDesc, const StencilRuns& runs, int start, int end) {
    const kernels::StencilRunArrays arrays = detail::stencilRunArrays(runs);
    if (!detail::checkEvalArguments(src != nullptr, srcDesc, dst != nullptr, dstDesc, runs.numStencils(), start, end))
        return;
    const float* s = src + srcDesc.offset;
    float* d = dst + dstDesc.offset;
    const int srcStride = srcDesc.stride, dstStride = dstDesc.stride, width = dstDesc.length;
    // Blocks of whole chunks (kChunk-aligned, so a stretch's chunks are evaluated in mask order);
    // each block finds its first run by bisection, a few dozen loads for thousands of stencils.
    constexpr int chunk = StencilRuns::kChunk;
    const int firstUnit = start / chunk, lastUnit = (end + chunk - 1) / chunk;
    forBlocks(firstUnit, lastUnit, kGrain / chunk, [&](int u0, int u1) {
        const int b = u0 * chunk > start ? u0 * chunk : start, e = u1 * chunk < end ? u1 * chunk : end;
        kernels::evalStencilRuns(s, srcStride, d, dstStride, width, arrays, b, e);
    });
}

void TbbEvaluator::EvalMeshNormals(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                   const BufferDescriptor& dstDesc, const MeshNormalTable& table, int start, int end) {
    if (!detail::checkMeshNormalArguments(src != nullptr, srcDesc, dst != nullptr, dstDesc, table.numVertices, start,
                                          end))
        return;
    const kernels::MeshNormalArrays arrays = detail::meshNormalArrays(table);
    const float* s = src + srcDesc.offset;
    float* d = dst + dstDesc.offset;
    const int srcStride = srcDesc.stride, dstStride = dstDesc.stride;
    if (end - start < table.numVertices) {
        // A vertex gathers ~4 faces of 3-4 corners: about the cost of a stencil, so the same grain.
        forBlocks(start, end, kGrain,
                  [&](int b, int e) { kernels::evalMeshNormals(s, srcStride, d, dstStride, arrays, b, e); });
        return;
    }
    // On one thread the serial pass, which fuses what the parallel one does in four steps.
    if (tbb::this_task_arena::max_concurrency() == 1) {
        kernels::meshNormalsOfLevel(s, srcStride, d, dstStride, arrays, end, table.numFaces());
        return;
    }
    // The table's chunks of faces write disjoint rows (their seam vertices left out), so they run
    // in parallel; then the seam vertices gather their faces. Each row sums its faces in face
    // order, as CpuEvaluator's single pass does, whatever the thread count.
    forBlocks(0, end, 8 * kGrain, [&](int b, int e) { kernels::zeroRows(d, dstStride, b, e); });
    const int faces = table.numFaces(), chunk = table.facesPerChunk;
    tbb::parallel_for(tbb::blocked_range<int>(0, table.numChunks(), 1), [&](const tbb::blocked_range<int>& r) {
        kernels::scatterChunk(s, srcStride, d, dstStride, arrays, r.begin() * chunk, std::min(faces, r.end() * chunk));
    });
    const int* seams = table.seamVertices.data();
    forBlocks(0, int(table.seamVertices.size()), kGrain, [&](int b, int e) {
        for (int i = b; i < e; ++i) kernels::sumOfFaces(s, srcStride, arrays, seams[i], d + long(seams[i]) * dstStride);
    });
    forBlocks(0, end, 8 * kGrain, [&](int b, int e) { kernels::normalizeRows(d, dstStride, b, e); });
}

void TbbEvaluator::EvalLimitStencils(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                     const BufferDescriptor& positionDesc, float* dstDu, const BufferDescriptor& duDesc,
                                     float* dstDv, const BufferDescriptor& dvDesc, float* dstNormal,
                                     const BufferDescriptor& normalDesc, const LimitStencilTable& table,
                                     const MeshNormalTable* fallback, int start, int end) {
    detail::HostLimitCall c;
    if (!detail::hostLimitCall(c, src, srcDesc, dstPosition, positionDesc, dstDu, duDesc, dstDv, dvDesc, dstNormal,
                               normalDesc, table, fallback, start, end))
        return;
    // A limit stencil does three stencils' arithmetic over one support (plus a normal): half the
    // stencil grain keeps a block's work above TBB's per-task cost with room to balance.
    forBlocks(start, end, kGrain / 2, [&](int b, int e) {
        kernels::evalLimitStencils(c.src, srcDesc.stride, srcDesc.length, c.arrays, c.outputs, b, e);
    });
}

void TbbEvaluator::EvalLevelPatches(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                    const BufferDescriptor& positionDesc, float* dstNormal,
                                    const BufferDescriptor& normalDesc, const LevelPatchTable& table) {
    const detail::HostLevelPatchCall c =
        detail::levelPatchCall(src, srcDesc, dstPosition, positionDesc, dstNormal, normalDesc, table);
    // A patch writes about rate^2 points: blocks of patches near the stencil grain in points.
    const int patchGrain = std::max(1, kGrain / 4 / (table.rate() * table.rate()));
    forBlocks(0, table.numPatches(), patchGrain, [&](int b, int e) {
        kernels::evalLevelPatches(c.src, c.srcStride, c.patches, c.position, c.positionStride, c.normal,
                                  c.normalStride, b, e);
    });
    forBlocks(0, table.stencils.numStencils(), kGrain / 2, [&](int b, int e) {
        kernels::evalLimitStencils(c.src, c.srcStride, 3, c.stencils, c.stencilOutputs, b, e);
    });
}

}  // namespace v0
}  // namespace quadtri
