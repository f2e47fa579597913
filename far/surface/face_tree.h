// One base face's surface as a tree of sub-faces, grown as points ask for it (docs/surface.md,
// "Faces' trees"): each node is a sub-face of the face's local refinement; a node that is a
// regular patch, or lies at the maximum depth, is a leaf whose points are kept as weights over
// the base neighbourhood, so that every later point in it costs one basis evaluation.
#pragma once

#include <memory>
#include <unordered_map>
#include <vector>

#include <quadtri/far/limit_surface.h>
#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "far/limit/limit_scratch.h"
#include "far/surface/local_mesh.h"
#include "far/surface/regular_patch.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// The tree of one neighbourhood shape, over columns of its own: the cut's vertices, or a regular
// face's points in patch order. A leaf's points are rows of weights over the columns.
class FaceTree {
public:
    enum class Leaf : signed char { None, BSpline, BoxSpline, Bilinear, Linear, QuadraticQuad, QuadraticTriangle };

    // A regular face: one leaf over its points.
    FaceTree(Leaf kind, const FaceParameterization& param);
    // Any other face: the cut around it, refined as points ask, through the steps of `shapes`
    // (which outlives the tree).
    FaceTree(LocalShapes& shapes, LocalShape& root, const LimitSurfaceOptions& surfaceOptions,
             const FaceParameterization& param);
    ~FaceTree();

    const FaceParameterization& parameterization() const { return param_; }
    // A regular face's tree (one leaf over its points in the basis's order, at the face's own
    // (u, v)): its basis; else Leaf::None.
    Leaf regularBasis() const { return regular_ ? nodes_[0].leaf : Leaf::None; }
    int numColumns() const { return numColumns_; }

    // Where (u, v) (checked by the caller to lie in the face's domain) falls: its leaf's rows
    // (points) and their basis weights; d(s, t)/d(u, v) takes the leaf's derivatives to the face's.
    struct Located {
        int firstRow = 0, count = 0;
        int firstColumn = 0, numColumns = 0;  // the columns the rows read, increasing
        double wP[16], wDs[16], wDt[16];
        double k[2][2];  // k[0]: ds/du, ds/dv; k[1]: dt/du, dt/dv
    };
    void locate(double u, double v, Located& out);

    // The weights of (u, v) over columns[j] for the tree's column j, derivatives along the face's
    // u and v.
    void stencil(double u, double v, const int* columns, LimitPointStencil& out);

    // Row r's weights over the columns: columns rowColumn(k), weights rowWeight(k) for k in
    // [rowBegin(r), rowBegin(r + 1)).
    int rowBegin(int r) const { return rows_.offsets[std::size_t(r)]; }
    int rowColumn(int k) const { return rows_.columns[std::size_t(k)]; }
    double rowWeight(int k) const { return rows_.weights[std::size_t(k)]; }
    // A leaf row entry's column as its place among the leaf's columns (Located::firstColumn ..),
    // and those columns.
    int rowSlot(int k) const { return rowSlots_[std::size_t(k)]; }
    int leafColumn(int i) const { return leafColumns_[std::size_t(i)]; }

private:
    struct Node {
        LocalShape* shape = nullptr;
        std::unique_ptr<LocalRows> rows;  // its shape's vertices', while it has children to make
        int firstChild = -1;              // into children_, numChildren slots
        int numChildren = 0, numBuilt = 0;
        int firstRow = 0;                 // a leaf's points: rows firstRow .. firstRow + points
        int firstColumn = 0, numColumns = 0;  // a leaf's: the columns its rows read, in leafColumns_
        Leaf leaf = Leaf::None;
        bool classified = false;
        bool quad = true;
    };

    // The located point's weights per column the leaf reads, as visit(column, p, ds, dt) by
    // increasing column (ds, dt along the leaf's s and t; Located::k takes them to the face's).
    template <class Visit>
    void visitWeights(const Located& at, Visit&& visit) {
        for (int i = 0; i < at.count; ++i) {
            const int row = at.firstRow + i;
            for (int k = rows_.offsets[std::size_t(row)]; k < rows_.offsets[std::size_t(row) + 1]; ++k) {
                const std::size_t j = std::size_t(rows_.columns[std::size_t(k)]);
                const double x = rows_.weights[std::size_t(k)];
                p_[j] += at.wP[i] * x;
                ds_[j] += at.wDs[i] * x;
                dt_[j] += at.wDt[i] * x;
            }
        }
        for (int c = at.firstColumn; c < at.firstColumn + at.numColumns; ++c) {
            const std::size_t j = std::size_t(leafColumns_[std::size_t(c)]);
            visit(int(j), p_[j], ds_[j], dt_[j]);
            p_[j] = ds_[j] = dt_[j] = 0.0;
        }
    }

    // Child `which` of `node`, made and classified at `depth` when first asked.
    int child(int node, int which, int depth);
    // Made a leaf (its points' rows) or given its vertices' rows: from its parent's rows through
    // `step`, or (the root) from its own.
    void classify(int node, int depth, const LocalRows* parentRows, const LocalStep* step);
    void gatherColumns(Node& leaf, int points);  // the columns of the leaf's rows, once

    LocalShapes* shapes_ = nullptr;
    LimitSurfaceOptions surfaceOptions_;
    FaceParameterization param_;
    bool regular_ = false;
    int numColumns_ = 0;
    std::vector<Node> nodes_;
    std::vector<int> children_;
    LocalRows rows_;  // the leaves' points
    std::vector<int> leafColumns_;
    std::vector<int> rowSlots_;  // per row entry of a leaf: rowSlot
    std::vector<int> slot_;      // per column, while gathering
    std::vector<unsigned char> marked_;  // per column, while gathering
    std::vector<double> p_, ds_, dt_;  // per column
    RowAccumulator sum_;
    LocalRows next_;            // at the maximum depth: rows of the next level's vertices the limit masks read
    std::vector<int> nextRow_;  // per vertex of that level: its row in next_, or -1
};

// The trees of a topology's faces, one per neighbourhood shape: faces whose cuts have the same
// topology and sharpness share one (a tree depends on nothing else), as Bfr's factory caches its
// irregular patches. One thread at a time, with the trees it gave.
class FaceTrees {
public:
    // `baseScratch`, sized for `base` (kept by the caller: sizing it is linear in the mesh), is
    // used by every treeOf.
    FaceTrees(const Topology& base, const Options& options, const LimitSurfaceOptions& surfaceOptions, Sharpen sharpen,
              WalkScratch& baseScratch);
    ~FaceTrees();

    // Face f's tree, and into `columns` the base vertex of each of its columns.
    FaceTree& treeOf(int face, std::vector<int>& columns);
    // The same, kept for the next call with this face (a FaceSurfaceFactory meets a face again
    // each time its points are asked for): the columns stay where they are while this lives.
    struct Kept {
        FaceTree* tree = nullptr;
        const int* columns = nullptr;
        int numColumns = 0;
    };
    const Kept& keptTreeOf(int face);
    // From now on each vertex's ring is ordered once for all the regular faces around it (for
    // many faces: it takes memory in the mesh's size); keptTreeOf does it first.
    void keepRings();
    int numShapes() const { return int(trees_.size()); }

private:
    const Topology& base_;
    Options options_;
    LimitSurfaceOptions surfaceOptions_;
    Sharpen sharpen_;
    FaceParameterization quadDomain_, triangleDomain_;  // the scheme's, looked up once
    bool linear_;
    LocalShapes shapes_;
    std::unordered_map<const LocalShape*, std::unique_ptr<FaceTree>> trees_;  // by the face's cut
    std::unique_ptr<FaceTree> regular_[4];  // by Leaf - 1: BSpline, BoxSpline, Bilinear, Linear
    std::unique_ptr<RegularPatches> patches_;  // after keepRings
    WalkScratch& scratch_;
    std::vector<Kept> kept_;  // per face, filled by keptTreeOf
    // The kept columns, in blocks that never move (a block's worth of faces per allocation).
    std::vector<std::unique_ptr<int[]>> keptBlocks_;
    int keptUsed_ = 0, keptCapacity_ = 0;
    std::vector<int> columns_;  // keptTreeOf's scratch for treeOf
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
