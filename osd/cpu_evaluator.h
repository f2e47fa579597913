// Serial evaluator: applies a StencilTable to any per-vertex float data.
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

class QUADTRI_API CpuEvaluator {
public:
    // Evaluates stencils [start, end) of `table` (end < 0: up to the last stencil). Stencil i
    // writes destination element i, so a range fills exactly rows [start, end) of dst and leaves
    // the others untouched. Source elements are read at the table's indices. src and dst must not
    // overlap. Throws std::invalid_argument on an invalid descriptor, a length mismatch or a bad
    // range.
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

    // Area-weighted vertex normals of one level (MeshNormalTable): normals of vertices [start,
    // end) (end < 0: all) from that level's 3-float positions, unit length, (0, 0, 0) for a
    // vertex without faces of non-zero area. A whole level goes face by face, a shorter range
    // vertex by vertex: the same bits (docs/limit_evaluation.md). src and dst must not overlap. Throws
    // std::invalid_argument on descriptors that are invalid or not of length 3, a bad range or a
    // missing buffer.
    static void EvalMeshNormals(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                const BufferDescriptor& dstDesc, const MeshNormalTable& table, int start = 0,
                                int end = -1);

    // Limit positions, tangents and unit normals of stencils [start, end) of `table` (end < 0:
    // all) in one pass over each stencil's sources. Any of the four outputs may be omitted (a
    // null pointer: its descriptor is not read), not all of them; position, dU and dV have the
    // source's length, normals (normalize(dU x dV), 3 floats) need 3-float sources. Where the
    // tangents are parallel or zero (the sine of their angle below 1e-4) the normal is the
    // area-weighted face normal of `fallback` (a MeshNormalTable of the table's own level, only
    // for a table over that level's vertices: Refiner::limitStencils), else (0, 0, 0)
    // (docs/limit_evaluation.md). Stencil i writes element i of each output. Outputs must not
    // overlap the source or each other. Throws std::invalid_argument on bad descriptors,
    // lengths, fallback, range or a missing source.
    static void EvalLimitStencils(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                  const BufferDescriptor& positionDesc, float* dstDu, const BufferDescriptor& duDesc,
                                  float* dstDv, const BufferDescriptor& dvDesc, float* dstNormal,
                                  const BufferDescriptor& normalDesc, const LimitStencilTable& table,
                                  const MeshNormalTable* fallback = nullptr, int start = 0, int end = -1);

    // Level L's limit positions and unit normals from level K's positions (src: numSourceVertices
    // elements) through a LevelPatchTable (Refiner::levelPatches; docs/patches.md): point k of the
    // table (level-L vertex table.vertexOf(k)) written at element k of each output given (either
    // may be null, not both). Every descriptor of length 3. Throws std::invalid_argument on bad
    // descriptors or an inconsistent table.
    static void EvalLevelPatches(const float* src, const BufferDescriptor& srcDesc, float* dstPosition,
                                 const BufferDescriptor& positionDesc, float* dstNormal,
                                 const BufferDescriptor& normalDesc, const LevelPatchTable& table);
};

}  // namespace v0
}  // namespace quadtri
