// FaceTree (far/surface/face_tree.h): a point walks down from the face to the leaf that holds it,
// refining the neighbourhood of each sub-face it enters for the first time.
#include "far/surface/face_tree.h"

#include <algorithm>

#include "far/limit/limit_mask.h"
#include "far/limit/limit_ring.h"
#include "far/limit/limit_table.h"
#include "far/schemes/scheme.h"
#include "far/surface/patch_basis.h"
#include "far/surface/regular_patch.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// The point in the followed sub-face's own (s, t), and d(s, t)/d(u, v) back to the base face.
struct Where {
    double s = 0, t = 0;
    double k[2][2] = {{1, 0}, {0, 1}};  // k[0]: ds/du, ds/dv; k[1]: dt/du, dt/dv

    // (s, t) <- a (s, t) + b, kept inside the domain against rounding.
    void map(const double a[2][2], double b0, double b1, bool triangle) {
        const double s1 = a[0][0] * s + a[0][1] * t + b0, t1 = a[1][0] * s + a[1][1] * t + b1;
        s = std::clamp(s1, 0.0, 1.0);
        t = std::clamp(t1, 0.0, 1.0);
        if (triangle && s + t > 1) {
            const double over = s + t;
            s /= over;
            t /= over;
        }
        double k1[2][2];
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) k1[i][j] = a[i][0] * k[0][j] + a[i][1] * k[1][j];
        std::copy(&k1[0][0], &k1[0][0] + 4, &k[0][0]);
    }
};

// The child of a quad (or triangle split in four) that holds the point, the point moved into it
// (children as refine_topology.cpp numbers them: corner i's first, a triangle's middle last).
int descend(bool quad, Where& w) {
    if (quad) {
        static constexpr double kA[4][2][2] = {
            {{2, 0}, {0, 2}}, {{0, 2}, {-2, 0}}, {{-2, 0}, {0, -2}}, {{0, -2}, {2, 0}}};
        static constexpr double kB[4][2] = {{0, 0}, {0, 2}, {2, 2}, {2, 0}};
        const int child = w.s < 0.5 ? (w.t < 0.5 ? 0 : 3) : (w.t < 0.5 ? 1 : 2);
        w.map(kA[child], kB[child][0], kB[child][1], false);
        return child;
    }
    static constexpr double kA[4][2][2] = {
        {{2, 0}, {0, 2}}, {{0, 2}, {-2, -2}}, {{-2, -2}, {2, 0}}, {{2, 2}, {-2, 0}}};
    static constexpr double kB[4][2] = {{0, 0}, {0, 2}, {2, 0}, {-1, 1}};
    const int child = w.s + w.t <= 0.5 ? 0 : w.s >= 0.5 ? 1 : w.t >= 0.5 ? 2 : 3;
    w.map(kA[child], kB[child][0], kB[child][1], true);
    return child;
}

// The sub-face of an n-gon's (u, v), checked to hold it, and the point in it.
int enterSubFace(const FaceParameterization& p, double u, double v, Where& w) {
    const int i = p.subFaceAt(u, v);
    static constexpr double kTwice[2][2] = {{2, 0}, {0, 2}};
    w.s = u;
    w.t = v;
    w.map(kTwice, -2.0 * (i % p.gridWidth), -2.0 * (i / p.gridWidth), false);
    return i;
}

FaceTree::Leaf leafOf(PatchKind kind) {
    switch (kind) {
    case PatchKind::BSpline: return FaceTree::Leaf::BSpline;
    case PatchKind::BoxSpline: return FaceTree::Leaf::BoxSpline;
    case PatchKind::Bilinear: return FaceTree::Leaf::Bilinear;
    case PatchKind::Linear: return FaceTree::Leaf::Linear;
    default: return FaceTree::Leaf::None;
    }
}

}  // namespace

FaceTree::FaceTree(Leaf kind, const FaceParameterization& param) : param_(param), regular_(true) {
    static constexpr int kPoints[] = {0, 16, 12, 4, 3};
    numColumns_ = kPoints[int(kind)];
    Node root;
    root.classified = true;
    root.leaf = kind;
    root.quad = kind == Leaf::BSpline || kind == Leaf::Bilinear;
    nodes_.push_back(std::move(root));
    for (int i = 0; i < numColumns_; ++i) {
        rowSlots_.push_back(i);
        rows_.columns.push_back(i);
        rows_.weights.push_back(1.0);
        rows_.offsets.push_back(i + 1);
        leafColumns_.push_back(i);
    }
    nodes_[0].numColumns = numColumns_;
    p_.assign(std::size_t(numColumns_), 0.0);
    ds_ = dt_ = p_;
}

FaceTree::FaceTree(LocalShapes& shapes, LocalShape& root, const LimitSurfaceOptions& surfaceOptions,
                   const FaceParameterization& param)
    : shapes_(&shapes), surfaceOptions_(surfaceOptions), param_(param) {
    numColumns_ = root.topology.numVertices;
    Node node;
    node.shape = &root;
    node.rows = std::make_unique<LocalRows>();
    LocalRows& rows = *node.rows;
    for (int v = 0; v < numColumns_; ++v) {
        rows.columns.push_back(v);
        rows.weights.push_back(1.0);
        rows.offsets.push_back(v + 1);
    }
    nodes_.push_back(std::move(node));
    p_.assign(std::size_t(numColumns_), 0.0);
    ds_ = dt_ = p_;
    sum_.resize(numColumns_);
    marked_.assign(std::size_t(numColumns_), 0);
}

FaceTree::~FaceTree() = default;

int FaceTree::child(int node, int which, int depth) {
    const int slot = children_[std::size_t(nodes_[std::size_t(node)].firstChild + which)];
    if (slot >= 0) return slot;
    const LocalStep& step = shapes_->step(*nodes_[std::size_t(node)].shape, which);
    const int id = int(nodes_.size());
    children_[std::size_t(nodes_[std::size_t(node)].firstChild + which)] = id;
    nodes_.emplace_back();
    nodes_.back().shape = step.child;
    classify(id, depth, nodes_[std::size_t(node)].rows.get(), &step);
    Node& parent = nodes_[std::size_t(node)];
    if (++parent.numBuilt == parent.numChildren) parent.rows.reset();
    return id;
}

void FaceTree::classify(int id, int depth, const LocalRows* parentRows, const LocalStep* step) {
    Node& node = nodes_[std::size_t(id)];
    LocalShape& shape = *node.shape;
    shapes_->classify(shape);
    node.classified = true;
    node.quad = shape.topology.faceSize(shape.face) == 4;
    node.firstRow = rows_.size();
    // Vertex v's row, appended to `out`.
    auto rowOf = [&](int v, LocalRows& out) {
        if (step) {
            const int first = step->offsets[std::size_t(v)];
            composeRow(step->indices.data() + first, step->weights.data() + first,
                       step->offsets[std::size_t(v) + 1] - first, *parentRows, sum_, out);
        } else {
            const SparseRow row = node.rows->row(v);
            out.columns.insert(out.columns.end(), row.columns, row.columns + row.size);
            out.weights.insert(out.weights.end(), row.weights, row.weights + row.size);
            out.offsets.push_back(int(out.columns.size()));
        }
    };

    if (shape.patch != PatchKind::None) {
        node.leaf = leafOf(shape.patch);
        for (int p : shape.points) rowOf(p, rows_);
        gatherColumns(node, int(shape.points.size()));
        node.rows.reset();
        return;
    }
    if (step) {
        node.rows = std::make_unique<LocalRows>();
        // About the parent's entries: grown by doubling, the rows would be copied over and over.
        node.rows->offsets.reserve(std::size_t(shape.topology.numVertices) + 1);
        node.rows->columns.reserve(parentRows->columns.size() + parentRows->columns.size() / 2);
        node.rows->weights.reserve(node.rows->columns.capacity());
        for (int v = 0; v < shape.topology.numVertices; ++v) rowOf(v, *node.rows);
    }
    if (depth < surfaceOptions_.maxDepth) {
        node.numChildren = 4;
        node.firstChild = int(children_.size());
        children_.insert(children_.end(), 4, -1);
        return;
    }
    // The quadratic through the exact limit points of the sub-face's next level: the rows of the
    // next level's vertices the masks read, then the masks' sums of them.
    const LocalRows& masks = shapes_->limitMasks(shape);
    const LocalStep& next = shapes_->limitStep(shape);
    nextRow_.assign(std::size_t(next.child->topology.numVertices), -1);
    next_ = LocalRows();
    for (int v : masks.columns) {
        if (nextRow_[std::size_t(v)] >= 0) continue;
        nextRow_[std::size_t(v)] = next_.size();
        const int first = next.offsets[std::size_t(v)];
        composeRow(next.indices.data() + first, next.weights.data() + first, next.offsets[std::size_t(v) + 1] - first,
                   *node.rows, sum_, next_);
    }
    for (int n = 0; n < masks.size(); ++n) {
        for (int k = masks.offsets[std::size_t(n)]; k < masks.offsets[std::size_t(n) + 1]; ++k)
            sum_.add(masks.weights[std::size_t(k)], next_.row(nextRow_[std::size_t(masks.columns[std::size_t(k)])]));
        sum_.take([&](int column, double weight) {
            rows_.columns.push_back(column);
            rows_.weights.push_back(weight);
        });
        rows_.offsets.push_back(int(rows_.columns.size()));
    }
    node.leaf = node.quad ? Leaf::QuadraticQuad : Leaf::QuadraticTriangle;
    gatherColumns(node, masks.size());
    node.rows.reset();
}

void FaceTree::gatherColumns(Node& leaf, int points) {
    leaf.firstColumn = int(leafColumns_.size());
    for (int k = rowBegin(leaf.firstRow); k < rowBegin(leaf.firstRow + points); ++k) {
        const int j = rows_.columns[std::size_t(k)];
        if (!marked_[std::size_t(j)]) {
            marked_[std::size_t(j)] = 1;
            leafColumns_.push_back(j);
        }
    }
    std::sort(leafColumns_.begin() + leaf.firstColumn, leafColumns_.end());
    leaf.numColumns = int(leafColumns_.size()) - leaf.firstColumn;
    for (auto j = leafColumns_.begin() + leaf.firstColumn; j != leafColumns_.end(); ++j) marked_[std::size_t(*j)] = 0;
    // Each row entry's place among the leaf's columns.
    slot_.resize(std::size_t(numColumns_));
    for (int s = 0; s < leaf.numColumns; ++s) slot_[std::size_t(leafColumns_[std::size_t(leaf.firstColumn + s)])] = s;
    rowSlots_.resize(rows_.columns.size());
    for (int k = rowBegin(leaf.firstRow); k < rowBegin(leaf.firstRow + points); ++k)
        rowSlots_[std::size_t(k)] = slot_[std::size_t(rows_.columns[std::size_t(k)])];
}

void FaceTree::locate(double u, double v, Located& out) {
    Where w;
    w.s = u;
    w.t = v;
    int node = 0, depth = 0;
    if (param_.type == FaceParameterization::Type::QuadSubFaces) {
        Node& root = nodes_[0];
        if (root.numChildren == 0) {
            root.classified = true;
            root.numChildren = param_.faceSize;
            root.firstChild = int(children_.size());
            children_.insert(children_.end(), std::size_t(param_.faceSize), -1);
        }
        node = child(0, enterSubFace(param_, u, v, w), 1);
        depth = 1;
    } else if (!nodes_[0].classified) {
        classify(0, 0, nullptr, nullptr);
    }
    for (; nodes_[std::size_t(node)].leaf == Leaf::None; ++depth)
        node = child(node, descend(nodes_[std::size_t(node)].quad, w), depth + 1);

    const Node& leaf = nodes_[std::size_t(node)];
    out.firstRow = leaf.firstRow;
    out.firstColumn = leaf.firstColumn;
    out.numColumns = leaf.numColumns;
    double* const p = out.wP;
    double* const ds = out.wDs;
    double* const dt = out.wDt;
    switch (leaf.leaf) {
    case Leaf::BSpline: bSplineWeights(w.s, w.t, p, ds, dt), out.count = 16; break;
    case Leaf::BoxSpline: boxSplineWeights(w.s, w.t, p, ds, dt), out.count = 12; break;
    case Leaf::Bilinear: bilinearWeights(w.s, w.t, p, ds, dt), out.count = 4; break;
    case Leaf::Linear: linearWeights(w.s, w.t, p, ds, dt), out.count = 3; break;
    case Leaf::QuadraticQuad: quadraticQuadWeights(w.s, w.t, p, ds, dt), out.count = 9; break;
    default: quadraticTriangleWeights(w.s, w.t, p, ds, dt), out.count = 6; break;
    }
    std::copy(&w.k[0][0], &w.k[0][0] + 4, &out.k[0][0]);
}

void FaceTree::stencil(double u, double v, const int* columns, LimitPointStencil& out) {
    Located at;
    locate(u, v, at);
    out.indices.clear();
    out.position.clear();
    out.du.clear();
    out.dv.clear();
    // Derivatives back to (u, v); columns the point does not read left out.
    visitWeights(at, [&](int j, double p, double ds, double dt) {
        if (p == 0.0 && ds == 0.0 && dt == 0.0) return;
        out.indices.push_back(columns[std::size_t(j)]);
        out.position.push_back(p);
        out.du.push_back(ds * at.k[0][0] + dt * at.k[1][0]);
        out.dv.push_back(ds * at.k[0][1] + dt * at.k[1][1]);
    });
}

FaceTrees::FaceTrees(const Topology& base, const Options& options, const LimitSurfaceOptions& surfaceOptions,
                     Sharpen sharpen, WalkScratch& baseScratch)
    : base_(base), options_(options), surfaceOptions_(surfaceOptions), sharpen_(sharpen),
      quadDomain_(FaceParameterization::of(options.scheme, 4)),
      triangleDomain_(FaceParameterization::of(options.scheme, 3)),
      linear_(sharpen == Sharpen::All && rulesOf(options.scheme).surfacePatches().sharpIsLinear),
      shapes_(options, surfaceOptions.rings > 0 ? surfaceOptions.rings : rulesOf(options.scheme).surfaceRings(),
              surfaceOptions.rings > 0 ? surfaceOptions.rings : rulesOf(options.scheme).surfaceLimitRings(), sharpen),
      scratch_(baseScratch) {}

FaceTrees::~FaceTrees() = default;

FaceTree& FaceTrees::treeOf(int face, std::vector<int>& columns) {
    const int size = base_.faceSize(face);
    const FaceParameterization param =
        size == 4 ? quadDomain_ : size == 3 ? triangleDomain_ : FaceParameterization::of(options_.scheme, size);
    if (param.type != FaceParameterization::Type::QuadSubFaces) {
        // A regular face (most of a mesh) is its own patch: no neighbourhood to cut.
        FaceTree::Leaf kind = FaceTree::Leaf::None;
        if (linear_) {
            const IndexSpan corners = base_.verticesOfFace(face);
            columns.assign(corners.begin(), corners.end());
            kind = corners.size() == 4 ? FaceTree::Leaf::Bilinear : FaceTree::Leaf::Linear;
            for (std::size_t i = 0; i < columns.size(); ++i)
                for (std::size_t j = 0; j < i; ++j)
                    if (columns[i] == columns[j]) kind = FaceTree::Leaf::None;
        } else {
            kind = leafOf(patches_ ? patches_->of(face, columns) : regularPatch(base_, face, options_, columns));
        }
        if (kind != FaceTree::Leaf::None) {
            std::unique_ptr<FaceTree>& tree = regular_[int(kind) - 1];
            if (!tree) tree = std::make_unique<FaceTree>(kind, param);
            return *tree;
        }
    }
    LocalShape& shape = shapes_.cut(base_, face, scratch_, columns);
    std::unique_ptr<FaceTree>& tree = trees_[&shape];
    if (!tree) tree = std::make_unique<FaceTree>(shapes_, shape, surfaceOptions_, param);
    return *tree;
}

void FaceTrees::keepRings() {
    if (!patches_) patches_ = std::make_unique<RegularPatches>(base_, options_);
}

const FaceTrees::Kept& FaceTrees::keptTreeOf(int face) {
    if (kept_.empty()) {
        kept_.resize(std::size_t(base_.numFaces()));
        keepRings();
    }
    Kept& k = kept_[std::size_t(face)];
    if (k.tree) return k;
    k.tree = &treeOf(face, columns_);
    const int n = int(columns_.size());
    if (keptUsed_ + n > keptCapacity_) {
        keptCapacity_ = std::max(n, 16 * 1024);
        keptBlocks_.emplace_back(new int[std::size_t(keptCapacity_)]);
        keptUsed_ = 0;
    }
    int* kept = keptBlocks_.back().get() + keptUsed_;
    std::copy(columns_.begin(), columns_.end(), kept);
    keptUsed_ += n;
    k.columns = kept;
    k.numColumns = n;
    return k;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
