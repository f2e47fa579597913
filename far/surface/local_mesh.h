// A base face's neighbourhood refined locally, one level at a time towards a point
// (docs/surface.md, "Local refinement"): at each level only the faces within a few rings of the
// followed sub-face are kept, as a topology of their own, each vertex with its weights over the
// base neighbourhood's vertices.
#pragma once

#include <algorithm>
#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "far/limit/limit_deeper.h"
#include "far/limit/limit_scratch.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// A vertex's weights over the columns: its nonzero ones, by increasing column.
struct SparseRow {
    const int* columns;
    const double* weights;
    int size;
};

struct LocalMesh {
    Topology topology;   // the kept faces, in full
    int face = -1;       // the followed sub-face, in topology's numbering
    int numColumns = 0;  // the base neighbourhood's vertices
    // Per vertex of topology its row: rowColumns and rowWeights [rowOffsets[v], rowOffsets[v + 1]).
    // Sparse: a vertex deep in the refinement reads a few dozen of a cut's hundreds of columns.
    std::vector<int> rowOffsets{0}, rowColumns;
    std::vector<double> rowWeights;

    SparseRow row(int v) const {
        const int first = rowOffsets[std::size_t(v)];
        return {rowColumns.data() + first, rowWeights.data() + first, rowOffsets[std::size_t(v) + 1] - first};
    }
};

// Sums of weighted rows over numColumns columns, column by column in the order the rows are
// added (the arithmetic of a dense sum, without its zeros).
class RowAccumulator {
public:
    explicit RowAccumulator(int numColumns = 0) { resize(numColumns); }
    void resize(int numColumns);
    void add(double weight, const SparseRow& row);
    // The sum's nonzero columns by increasing column, as (column, weight) to `emit`; then empty.
    template <class Emit>
    void take(Emit&& emit) {
        std::sort(touched_.begin(), touched_.end());
        for (int j : touched_) {
            if (sum_[std::size_t(j)] != 0.0) emit(j, sum_[std::size_t(j)]);
            sum_[std::size_t(j)] = 0.0;
            seen_[std::size_t(j)] = 0;
        }
        touched_.clear();
    }

private:
    std::vector<double> sum_;
    std::vector<unsigned char> seen_;
    std::vector<int> touched_;
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
