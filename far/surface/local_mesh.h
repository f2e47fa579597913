// A base face's neighbourhood refined locally, one level at a time towards a point
// (docs/surface.md, "Local refinement"): at each level only the faces within a few rings of the
// followed sub-face are kept, as a topology of their own, each vertex with its weights over the
// base neighbourhood's vertices.
#pragma once

#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "far/limit/limit_deeper.h"
#include "far/limit/limit_scratch.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

struct LocalMesh {
    Topology topology;        // the kept faces, in full
    int face = -1;            // the followed sub-face, in topology's numbering
    int numColumns = 0;       // the base neighbourhood's vertices
    std::vector<double> rows;  // per vertex of topology, numColumns weights
    const double* row(int v) const { return rows.data() + std::size_t(v) * std::size_t(numColumns); }
};

// Sharpness a face-varying channel's value mesh takes at every level, beyond what refinement
// carries down (docs/surface.md, "Face-varying values"): its boundary vertices (seams, the mesh's
// boundary) kept linear, or everything linear.
enum class Sharpen { None, Boundaries, All };

// The faces of `base` within `rings` rings of `face`, each vertex its own column; `columns`
// receives the base vertex of each column.
LocalMesh cutBase(const Topology& base, int face, int rings, const Options& options, WalkScratch& scratch,
                  std::vector<int>& columns, Sharpen sharpen = Sharpen::None);

// One level down: `mesh` refined by the scheme, the neighbourhood of the followed face's child
// `child` kept (children in refine_topology's order: corner i's first, a triangle split in four's
// middle last). `nodes`, when not null, receives the local numbers of the followed face's child
// vertices: a quad's 9 row by row in its (s, t) ((0,0), (½,0), (1,0), (0,½), ..., (1,1)), a
// triangle split in four's 6 (its corners, then the midpoints of edges 0, 1, 2).
LocalMesh refineTowards(const LocalMesh& mesh, int child, int rings, const Options& options, WalkScratch& scratch,
                        std::vector<int>* nodes = nullptr, Sharpen sharpen = Sharpen::None);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
