// Schaefer-Warren unzipping (docs/schemes/schaefer_warren.md, §1): before each round, a vertex on
// the tri/quad network gets one copy for the triangle side and one for the quad side, so that each
// piece is subdivided on its own and the averaging pass zips the seam closed, C2 across it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

enum class Piece { Triangle, Quad };

// The network: seam edges (a triangle on one side, a quad or n-gon on the other) that are not
// infinitely sharp. Boundaries, non-manifold and infinitely sharp edges are never unzipped.
bool isNetworkEdge(const Topology& topology, int edge);

// The two copies of every vertex of a level:
//   v_t = v + (1/48) Σ_k (w_k − v),   v_q = v − (1/48) Σ_k (w_k − v),
// w_k the far ends of v's network edges (α = ½ in the paper's family). Off the network both
// copies are v itself, and so are they at a crease or corner vertex with a semi-sharp crease
// (unzip.cpp). Only the vertices that split have rows: the network is a set of curves, so past
// the first level or two they are a small part of a level, and a pure triangle or quad level has
// none (whole tables, a row per vertex, were a fifth of a pure mesh's build).
struct UnzippedCopies {
    // Per vertex: 1 where it splits. A mask asks this of every point it reads (tens of times), so
    // it is a byte: the rows (below) are read for the few that split.
    std::vector<std::uint8_t> splitting;
    // Per vertex: its row, or -1 where its copies are itself.
    std::vector<int> rowOf;
    // Row r, one per splitting vertex in vertex order: entries [offsets[r], offsets[r + 1]), the
    // vertex first, then the far ends of its network edges. Both copies read the same sources;
    // each piece has its own weights.
    std::vector<int> offsets, indices;
    std::vector<double> triangleWeights, quadWeights;
    // All of them empty where no vertex of the level splits.

    bool splits(int v) const { return !splitting.empty() && splitting[v]; }
    const std::vector<double>& weightsOf(Piece piece) const {
        return piece == Piece::Triangle ? triangleWeights : quadWeights;
    }
};

UnzippedCopies unzipCopies(const Topology& topology);
// The same for `vertices` (sorted) alone: the others neither split nor have rows.
UnzippedCopies unzipCopies(const Topology& topology, const std::vector<int>& vertices);

// Bytes unzipCopies may take for a level (SchemeRules::extraLevelBytes); `topology` may hold its
// faces only (a looser bound then).
std::size_t unzipBytesBound(const Topology& topology);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
