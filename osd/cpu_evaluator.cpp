#include <quadtri/osd/cpu_evaluator.h>

#include "kernels/limit_kernel.h"
#include "kernels/mesh_normal_kernel.h"
#include "kernels/patch_kernel.h"
#include "kernels/stencil_kernel.h"
#include "osd/internal/eval_arguments.h"

namespace quadtri {
inline namespace v0 {

void CpuEvaluator::EvalStencils(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                const BufferDescriptor& dstDesc, const StencilTable& table, int start, int end) {
    if (!detail::checkEvalArguments(src != nullptr, srcDesc, dst != nullptr, dstDesc, table.numStencils(), start,
                                    end))
        return;
    kernels::evalStencils(src + srcDesc.offset, srcDesc.stride, dst + dstDesc.offset, dstDesc.stride, dstDesc.length,
                          detail::stencilArrays(table), start, end);
}

void CpuEvaluator::EvalStencilRuns(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                   const BufferDescriptor& dstDesc, const StencilRuns& runs, int start, int end) {
    const kernels::StencilRunArrays arrays = detail::stencilRunArrays(runs);
    if (!detail::checkEvalArguments(src != nullptr, srcDesc, dst != nullptr, dstDesc, runs.numStencils(), start, end))
        return;
    kernels::evalStencilRuns(src + srcDesc.offset, srcDesc.stride, dst + dstDesc.offset, dstDesc.stride,
                             dstDesc.length, arrays, start, end);
}

void CpuEvaluator::EvalMeshNormals(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                   const BufferDescriptor& dstDesc, const MeshNormalTable& table, int start, int end) {
    if (!detail::checkMeshNormalArguments(src != nullptr, srcDesc, dst != nullptr, dstDesc, table.numVertices, start,
                                          end))
        return;
    const kernels::MeshNormalArrays arrays = detail::meshNormalArrays(table);
    const float* s = src + srcDesc.offset;
    float* d = dst + dstDesc.offset;
    if (end - start < table.numVertices) {
        kernels::evalMeshNormals(s, srcDesc.stride, d, dstDesc.stride, arrays, start, end);
        return;
    }
    // A whole level face by face (kernels/mesh_normal_kernel.h).
    kernels::meshNormalsOfLevel(s, srcDesc.stride, d, dstDesc.stride, arrays, end, table.numFaces());
}

void CpuEvaluator::EvalLimitStencils(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                     const BufferDescriptor& positionDesc, float* dstDu, const BufferDescriptor& duDesc,
                                     float* dstDv, const BufferDescriptor& dvDesc, float* dstNormal,
                                     const BufferDescriptor& normalDesc, const LimitStencilTable& table,
                                     const MeshNormalTable* fallback, int start, int end) {
    detail::HostLimitCall c;
    if (!detail::hostLimitCall(c, src, srcDesc, dstPosition, positionDesc, dstDu, duDesc, dstDv, dvDesc, dstNormal,
                               normalDesc, table, fallback, start, end))
        return;
    kernels::evalLimitStencils(c.src, srcDesc.stride, srcDesc.length, c.arrays, c.outputs, start, end);
}

void CpuEvaluator::EvalLevelPatches(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                    const BufferDescriptor& positionDesc, float* dstNormal,
                                    const BufferDescriptor& normalDesc, const LevelPatchTable& table) {
    const detail::HostLevelPatchCall c =
        detail::levelPatchCall(src, srcDesc, dstPosition, positionDesc, dstNormal, normalDesc, table);
    kernels::evalLevelPatches(c.src, c.srcStride, c.patches, c.position, c.positionStride, c.normal, c.normalStride, 0,
                              table.numPatches());
    kernels::evalLimitStencils(c.src, c.srcStride, 3, c.stencils, c.stencilOutputs, 0, table.stencils.numStencils());
}

}  // namespace v0
}  // namespace quadtri
