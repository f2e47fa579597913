// Schaefer-Warren unzipping (docs/schemes/schaefer_warren.md, §1): before each round, a vertex on
// the tri/quad network gets one copy for the triangle side and one for the quad side, so that each
// piece is subdivided on its own and the averaging pass zips the seam closed, C2 across it.
#pragma once

#include <quadtri/far/stencil_table.h>
#include <quadtri/far/topology.h>
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {

enum class Piece { Triangle, Quad };

// The network: seam edges (a triangle on one side, a quad or n-gon on the other) that are not
// infinitely sharp. Boundaries, non-manifold and infinitely sharp edges are never unzipped.
bool isNetworkEdge(const Topology& topology, int edge);

// Vertex v's copy for `piece`, one stencil per vertex of the level, over the level's vertices:
//   v_t = v + (1/48) Σ_k (w_k − v),   v_q = v − (1/48) Σ_k (w_k − v),
// w_k the far ends of v's network edges (α = ½ in the paper's family). Off the network a copy
// is v itself, and so is it at a crease or corner vertex with a semi-sharp crease (unzip.cpp).
StencilTableD unzipStencils(const Topology& topology, Piece piece);

}  // namespace v0
}  // namespace quadtri
