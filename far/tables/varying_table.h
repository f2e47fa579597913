// Varying (linear) stencils of one level: docs/varying.md.
#pragma once

#include <quadtri/far/topology.h>
#include "far/topology/refine_topology.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// The children of `parent` (in `numbering`'s order) as linear interpolations of its vertices:
// a face point is its face's centroid, an edge point its edge's midpoint, a vertex point its
// vertex. Sharpness, boundaries and the scheme's masks play no part.
StencilTableD buildVaryingStencils(const Topology& parent, const ChildNumbering& numbering);

// An upper bound of that table's bytes, for the memory budget, from the parent's counts alone.
std::size_t varyingStencilBytes(const Topology& parent, const ChildNumbering& numbering);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
