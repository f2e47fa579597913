// Serial evaluator: applies a StencilTable to any per-vertex float data.
#pragma once

#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/far/stencil_table.h>
#include <quadtri/osd/buffer_descriptor.h>

namespace quadtri {
inline namespace v0 {

class CpuEvaluator {
public:
    // Evaluates stencils [start, end) of `table` (end < 0: up to the last stencil). Stencil i
    // writes destination element i, so a range fills exactly rows [start, end) of dst and leaves
    // the others untouched. Source elements are read at the table's indices. src and dst must not
    // overlap. Throws std::invalid_argument on an invalid descriptor, a length mismatch or a bad
    // range.
    static void EvalStencils(const float* src, const BufferDescriptor& srcDesc, float* dst,
                             const BufferDescriptor& dstDesc, const StencilTable& table, int start = 0,
                             int end = -1);

    // Area-weighted vertex normals of one level (MeshNormalTable): normals of vertices [start,
    // end) (end < 0: all) from that level's 3-float positions, unit length, (0, 0, 0) for a
    // vertex without faces of non-zero area. src and dst must not overlap. Throws
    // std::invalid_argument on descriptors that are invalid or not of length 3, a bad range or a
    // missing buffer.
    static void EvalMeshNormals(const float* src, const BufferDescriptor& srcDesc, float* dst,
                                const BufferDescriptor& dstDesc, const MeshNormalTable& table, int start = 0,
                                int end = -1);
};

}  // namespace v0
}  // namespace quadtri
