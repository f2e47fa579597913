// The masks of a level's child vertices: the crease rules every scheme shares, around the
// scheme's own masks (far/schemes/scheme.h).
#pragma once

#include <cstdint>
#include <vector>

#include <quadtri/far/options.h>
#include "far/topology/refine_topology.h"
#include <quadtri/far/stencil_table.h>
#include <quadtri/far/topology.h>
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// Masks of the child vertices of `parent`, in the child order of `numbering` (which must split
// triangles as options.scheme does).
// Masks are accumulated in double; Table is StencilTable (float weights, pooled: what the
// Refiner stores) or StencilTableD (double weights, for exact tests and composition).
// Large levels are built on the calling TBB arena's threads; the table does not depend on
// how many there are.
// `childEdgeSharpness` (parallel to parent.vertEdges), when given, replaces the sharpness the
// children of each vertex's edges would decay to from the parent's own: a face-varying channel's
// value mesh takes the mesh's (docs/face_varying.md).
// `wanted` (one flag per child), when given, limits the masks built to the children flagged; the
// others get empty stencils. A flagged child's stencil has the indices and weights it has in the
// whole table (a factorized table composes only the rows it reads: far/refiner.cpp).
template <typename Table>
Table buildLevelStencils(const Topology& parent, const ChildNumbering& numbering, const Options& options,
                         const std::vector<float>* childEdgeSharpness = nullptr,
                         const std::vector<std::uint8_t>* wanted = nullptr);

// The masks of `children` (child indices in the order of `numbering`) alone, stencil k the
// mask of children[k]: each has the indices and weights it has in buildLevelStencils' whole
// table. `faces` (sorted) must hold every face within the scheme's surfaceRings() of a child's
// parent face: only those are prepared. What an edit recomputes (far/edit/).
template <typename Table>
Table buildChildStencils(const Topology& parent, const ChildNumbering& numbering, const Options& options,
                         const std::vector<int>& children, const std::vector<int>& faces);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
