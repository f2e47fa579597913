// Subdivision rules: the mask of every child vertex over the parent level's vertices.
#pragma once

#include <vector>

#include <quadtri/far/options.h>
#include "far/internal/refine_topology.h"
#include <quadtri/far/stencil_table.h>
#include <quadtri/far/topology.h>
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {

// η of the Stam-Loop correction v2 = v1 + η (v1 - v0) for a smooth vertex with nE incident
// edges, nQ quad-like and nT triangular faces (docs/schemes/stam_loop.md, §3).
double stamLoopEta(int nE, int nQ, int nT);

// Masks of the child vertices of `parent`, in the child order of `numbering`.
// Masks are accumulated in double; Table is StencilTable (float weights, pooled: what the
// Refiner stores) or StencilTableD (double weights, for exact tests and composition).
// Large levels are built on the calling TBB arena's threads; the table does not depend on
// how many there are.
template <typename Table>
Table buildLevelStencils(const Topology& parent, const ChildNumbering& numbering, const Options& options);

}  // namespace v0
}  // namespace quadtri
