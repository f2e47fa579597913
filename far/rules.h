// Subdivision rules: the mask of every child vertex over the parent level's vertices.
#pragma once

#include <vector>

#include "far/options.h"
#include "far/refine_topology.h"
#include "far/stencil_table.h"
#include "far/topology.h"

namespace quadtri {

// A stencil table whose weights are kept in double, as built; StencilTable stores float.
struct StencilTableD {
    int numSourceVertices = 0;
    std::vector<int> sizes;
    std::vector<int> offsets;
    std::vector<int> indices;
    std::vector<double> weights;
};

// η of the Stam-Loop correction v2 = v1 + η (v1 - v0) for a smooth vertex with nE incident
// edges, nQ quad-like and nT triangular faces (DESIGN.md §2.1).
double stamLoopEta(int nE, int nQ, int nT);

// Masks of the child vertices of `parent`, in the child order of `numbering`.
StencilTableD buildLevelStencils(const Topology& parent, const ChildNumbering& numbering, const Options& options);

}  // namespace quadtri

namespace quadtri {

// The float table stored for evaluation.
StencilTable toFloatTable(const StencilTableD& table);

// outer ∘ inner: stencils of `outer` (over inner's stencils) expanded over inner's sources.
StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner);

}  // namespace quadtri
