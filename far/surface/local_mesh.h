// A base face's neighbourhood refined locally, one level at a time towards a point
// (docs/surface.md, "Local refinement"): at each level only the faces within a few rings of the
// followed sub-face are kept, as a topology of their own, each vertex with its weights over the
// base neighbourhood's vertices.
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "far/limit/limit_deeper.h"
#include "far/limit/limit_scratch.h"
#include "far/surface/regular_patch.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// A vertex's weights over the columns: its nonzero ones, by increasing column.
struct SparseRow {
    const int* columns;
    const double* weights;
    int size;
};

// Rows of weights over columns: row r in columns and weights [offsets[r], offsets[r + 1]).
// Sparse: a vertex deep in the refinement reads a few dozen of a cut's hundreds of columns.
struct LocalRows {
    std::vector<int> offsets{0}, columns;
    std::vector<double> weights;

    SparseRow row(int r) const {
        const int first = offsets[std::size_t(r)];
        return {columns.data() + first, weights.data() + first, offsets[std::size_t(r) + 1] - first};
    }
    int size() const { return int(offsets.size()) - 1; }
};

struct LocalMesh {
    Topology topology;   // the kept faces, in full
    int face = -1;       // the followed sub-face, in topology's numbering
    int numColumns = 0;  // the base neighbourhood's vertices
    LocalRows rows;      // per vertex of topology its weights over the columns

    SparseRow row(int v) const { return rows.row(v); }
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

// Appends to `out` the sum of `weights[k]` times row `indices[k]` of `rows`, for k in [first, last).
void composeRow(const int* indices, const double* weights, int count, const LocalRows& rows, RowAccumulator& sum,
                LocalRows& out);

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

struct LocalShape;

// One level of local refinement from a shape towards one child of its face: the child's shape
// and each of its vertices' weights over the shape's vertices, in the order the level's stencils
// list them (so that rows composed through a step are refineTowards's, bit for bit).
struct LocalStep {
    LocalShape* child = nullptr;
    std::vector<int> offsets{0}, indices;
    std::vector<double> weights;
    std::vector<int> nodes;  // refineTowards's nodes, where the face is a quad or a triangle split in four
};

// A neighbourhood's shape: the topology a local mesh keeps, without its rows. Local meshes of one
// shape refine alike, so a shape keeps its steps and its patch, found once for every node of every
// face's tree that has it (docs/surface.md, "Shapes").
struct LocalShape {
    Topology topology;
    int face = -1;
    bool classified = false;
    PatchKind patch = PatchKind::None;  // the face's regular patch, if it is one
    std::vector<int> points;            // its points, in the basis's order
    std::vector<std::unique_ptr<LocalStep>> steps;  // per child of the face, made when first asked
    // One level down around all of the face's children (the nodes' rings in full), and each
    // node's exact limit mask over that level's vertices.
    std::unique_ptr<LocalStep> limitStep;
    std::unique_ptr<LocalRows> limitMasks;
};

// The shapes met by one factory's trees, each kept once. One thread at a time.
class LocalShapes {
public:
    // Steps keep `rings` rings around the followed child, limit steps `limitRings` around the
    // face's children.
    LocalShapes(const Options& options, int rings, int limitRings, Sharpen sharpen);
    ~LocalShapes();

    // Base face's cut (cutBase's), and into `columns` the base vertex of each of its vertices;
    // faces cut alike share a shape, recognized before the cut's topology is built.
    LocalShape& cut(const Topology& base, int face, WalkScratch& baseScratch, std::vector<int>& columns);
    // The shape's step towards `child`, and its patch.
    const LocalStep& step(LocalShape& shape, int child);
    const LocalShape& classify(LocalShape& shape);
    // The face's next level, cut around all its children: its nodes and their limit masks.
    const LocalStep& limitStep(LocalShape& shape);
    const LocalRows& limitMasks(LocalShape& shape);
    int size() const { return int(shapes_.size()); }

private:
    LocalShape& intern(const Topology& level, const PatchCut& cut, int face, WalkScratch& scratch);
    // One level down towards `child`, or (wholeFace) around all the face's children.
    std::unique_ptr<LocalStep> makeStep(const LocalShape& shape, int child, bool wholeFace);

    Options options_;
    int rings_, limitRings_;
    Sharpen sharpen_;
    bool linear_;
    WalkScratch scratch_;  // for cuts of local levels
    std::unordered_map<std::string, std::unique_ptr<LocalShape>> shapes_;
    std::string key_;
    struct Work;  // the cut, its raw arrays and the refined level, reused
    std::unique_ptr<Work> work_;
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
