// Threaded evaluator: the kernel of kernels/stencil_kernel.h over blocks of stencils, scheduled by
// oneTBB in the caller's task arena (its thread count); no global state.
#pragma once

#include <quadtri/export.h>
#include <quadtri/far/level_patch_table.h>
#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/far/stencil_table.h>
#include <quadtri/osd/buffer_descriptor.h>
#include <quadtri/osd/stencil_runs.h>

namespace quadtri {
inline namespace v0 {

class QUADTRI_API TbbEvaluator {
public:
    // Same contract as CpuEvaluator::EvalStencils: stencils [start, end) (end < 0: all), stencil i
    // writes destination element i, src and dst must not overlap, std::invalid_argument on bad
    // descriptors or ranges. Results are bit-identical to CpuEvaluator's.
    static void EvalStencils(const float* src, const BufferDescriptor& srcDesc, float* dst,
                             const BufferDescriptor& dstDesc, const StencilTable& table, int start = 0,
                             int end = -1);

    // EvalStencils through the runs of a table (StencilRuns, built once from it): the same bits,
    // without reading the table's per-stencil arrays inside a run (docs/stencil_kernel.md). Also
    // throws std::invalid_argument when the table's stencil count changed since the runs were built.
    // (Its own name, not an EvalStencils overload, so that &EvalStencils stays unambiguous.)
    static void EvalStencilRuns(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                const BufferDescriptor& dstDesc, const StencilRuns& runs, int start = 0,
                                int end = -1);

    // Same contract as CpuEvaluator::EvalMeshNormals, bit-identical results.
    static void EvalMeshNormals(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                const BufferDescriptor& dstDesc, const MeshNormalTable& table, int start = 0,
                                int end = -1);

    // Same contract as CpuEvaluator::EvalLimitStencils, bit-identical results.
    static void EvalLimitStencils(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                  const BufferDescriptor& positionDesc, float* dstDu, const BufferDescriptor& duDesc,
                                  float* dstDv, const BufferDescriptor& dvDesc, float* dstNormal,
                                  const BufferDescriptor& normalDesc, const LimitStencilTable& table,
                                  const MeshNormalTable* fallback = nullptr, int start = 0, int end = -1);

    // Same contract as CpuEvaluator::EvalLevelPatches, bit-identical results.
    static void EvalLevelPatches(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                 const BufferDescriptor& positionDesc, float* dstNormal,
                                 const BufferDescriptor& normalDesc, const LevelPatchTable& table);
};

}  // namespace v0
}  // namespace quadtri
