// Local refinement towards a point (far/surface/local_mesh.h): the cut and its refinement are the
// limit code's (far/limit/limit_deeper.h), around a face instead of a vertex; the rows carry each
// local vertex's weights over the base neighbourhood, composed level by level in double.
#include "far/surface/local_mesh.h"

#include <algorithm>
#include <stdexcept>

#include "far/schemes/scheme.h"
#include "far/tables/level_stencils.h"
#include "far/schemes/crease.h"
#include "far/topology/refine_topology.h"
#include "far/topology/topology_builder.h"
#include "far/limit/limit_mask.h"
#include "far/limit/limit_ring.h"
#include "far/limit/limit_table.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// The cut's faces are the level's, already oriented counter-clockwise: rebuilt as they are.
Options cutOptions(const Options& options) {
    Options o = options;
    o.leftHanded = false;
    return o;
}

int positionOf(const std::vector<int>& list, int x) {
    const auto it = std::find(list.begin(), list.end(), x);
    if (it == list.end()) throw std::logic_error("local mesh: a kept item is missing from its cut");
    return int(it - list.begin());
}

// The cut's rim looks like a boundary and is sharpened with it: harmless, since the rim's
// vertices are wrong already and a sharp vertex reaches no further than a smooth one.
void applySharpen(Topology& t, Sharpen sharpen) {
    if (sharpen == Sharpen::None) return;
    for (int v = 0; v < t.numVertices; ++v)
        if (sharpen == Sharpen::All || (t.vertFlags[std::size_t(v)] & kVertexBoundary))
            t.vertSharpness[std::size_t(v)] = kInfiniteSharpness;
    if (sharpen == Sharpen::All) std::fill(t.edgeSharpness.begin(), t.edgeSharpness.end(), kInfiniteSharpness);
}

// What a cut's topology is built from: the cut's faces with the level's own edges (a face list
// would join the two children of a collapsed edge, which link the same two vertices), sharpness
// as cutPatch reads it (boundary edges without theirs, so that the rim's boundaries never come
// back as creases inside a later cut). Two cuts with equal raw arrays have one shape.
struct RawCut {
    int face = -1;
    int numVertices = 0;
    std::vector<int> sizes, corners, faceEdges, edgeVerts;
    std::vector<float> edgeSharpness, vertSharpness;
    std::vector<unsigned char> holes;
};

void rawCutOf(const Topology& t, const PatchCut& cut, int face, WalkScratch& scratch, RawCut& raw) {
    raw.face = positionOf(cut.faceSource, face);
    raw.numVertices = int(cut.source.size());
    raw.sizes = cut.sizes;
    raw.corners = cut.corners;
    raw.faceEdges.clear();
    raw.edgeVerts.clear();
    raw.edgeSharpness.clear();
    raw.holes.clear();
    StampedMarks& localEdge = scratch.labels;  // level edge -> cut edge; cutPatch is done with it
    localEdge.clear(t.numEdges());
    auto edgeOf = [&](int e, int from, int to) {
        if (localEdge.marked(e)) return localEdge.value(e);
        const int id = int(raw.edgeSharpness.size());
        localEdge.mark(e, id);
        raw.edgeVerts.insert(raw.edgeVerts.end(), {from, to});
        const bool crease = isSharp(t.edgeSharpness[std::size_t(e)]) && !(t.edgeFlags[std::size_t(e)] & kEdgeBoundary);
        raw.edgeSharpness.push_back(crease ? t.edgeSharpness[std::size_t(e)] : 0.0f);
        return id;
    };
    int corner = 0;
    for (std::size_t i = 0; i < cut.faceSource.size(); ++i) {
        const int f = cut.faceSource[i], n = t.faceSize(f), first = corner;
        const IndexSpan verts = t.verticesOfFace(f), edges = t.edgesOfFace(f);
        for (int k = 0; k < n; ++k, ++corner) {
            const int e = edges[k], here = cut.corners[std::size_t(first + k)],
                      next = cut.corners[std::size_t(first + (k + 1) % n)];
            const bool forward = t.edgeVerts[2 * std::size_t(e)] == verts[k];
            raw.faceEdges.push_back(edgeOf(e, forward ? here : next, forward ? next : here));
        }
        raw.holes.push_back(t.faceHole[std::size_t(f)]);
    }
    raw.vertSharpness.resize(cut.source.size());
    for (std::size_t v = 0; v < cut.source.size(); ++v) {
        const float s = t.vertSharpness[std::size_t(cut.source[v])];
        raw.vertSharpness[v] = isSharp(s) ? s : 0.0f;
    }
}

template <class T>
void append(std::string& key, const std::vector<T>& items) {
    const std::size_t n = items.size();
    key.append(reinterpret_cast<const char*>(&n), sizeof n);
    key.append(reinterpret_cast<const char*>(items.data()), n * sizeof(T));
}

void keyOf(const RawCut& raw, std::string& key) {
    key.assign(reinterpret_cast<const char*>(&raw.face), sizeof raw.face);
    append(key, raw.sizes);
    append(key, raw.corners);
    append(key, raw.faceEdges);
    append(key, raw.edgeVerts);
    append(key, raw.edgeSharpness);
    append(key, raw.vertSharpness);
    append(key, raw.holes);
}

// The raw cut as a topology of its own, with the boundary rules of a base mesh.
Topology topologyOf(const RawCut& raw, const Options& options, Sharpen sharpen) {
    Topology m;
    m.numVertices = raw.numVertices;
    m.faceVerts = raw.corners;
    int corners = 0;
    for (int n : raw.sizes) m.faceOffsets.push_back(corners += n);
    m.faceEdges = raw.faceEdges;
    m.edgeVerts = raw.edgeVerts;
    completeTopologyFromEdges(m);
    m.edgeSharpness = raw.edgeSharpness;
    std::copy(raw.vertSharpness.begin(), raw.vertSharpness.end(), m.vertSharpness.begin());
    std::copy(raw.holes.begin(), raw.holes.end(), m.faceHole.begin());
    applyBoundaryRules(m, cutOptions(options));
    applySharpen(m, sharpen);
    return m;
}

// A level refined from a local topology and the child's neighbourhood cut from it.
struct RefinedCut {
    ChildNumbering num;
    Topology level;
    int childFace = -1;
    PatchCut cut;
};

// The cut is `rings` rings around the child face, or with `wholeFace` around all the face's
// children (whose vertices' limit masks read their own rings: limitMasks).
void refineAndCut(const Topology& p, int face, int child, int rings, const Options& options, WalkScratch& scratch,
                  RefinedCut& r, bool wholeFace = false) {
    r.num = numberChildren(p, rulesOf(options.scheme).triangleSplit());
    r.level = refineTopology(p, r.num, options.creaseMethod, TopologyDetail::Full);
    r.childFace = child;
    for (int f = 0; f < face; ++f) r.childFace += r.num.splitsInFour(p.faceSize(f)) ? 4 : p.faceSize(f);
    if (!wholeFace) return cutPatch(r.level, r.level.verticesOfFace(r.childFace), rings, scratch, r.cut);
    std::vector<int> seeds;
    const int children = r.num.splitsInFour(p.faceSize(face)) ? 4 : p.faceSize(face);
    for (int c = r.childFace - child; c < r.childFace - child + children; ++c)
        for (int v : r.level.verticesOfFace(c))
            if (std::find(seeds.begin(), seeds.end(), v) == seeds.end()) seeds.push_back(v);
    cutPatch(r.level, IndexSpan(seeds.data(), seeds.data() + seeds.size()), rings, scratch, r.cut);
}

// Each kept child vertex's stencil over p's vertices, in the table's order; the nodes towards
// child 0 of a quad or a triangle split in four.
void fillStep(const Topology& p, int face, const RefinedCut& r, const Options& options, LocalStep& step) {
    std::vector<std::uint8_t> wanted(std::size_t(r.level.numVertices), 0);
    for (int v : r.cut.source) wanted[std::size_t(v)] = 1;
    const StencilTableD table = buildLevelStencils<StencilTableD>(p, r.num, options, nullptr, &wanted);
    for (int v : r.cut.source) {
        const int first = table.offsets[std::size_t(v)], size = table.sizes[std::size_t(v)];
        step.indices.insert(step.indices.end(), table.indices.begin() + first, table.indices.begin() + first + size);
        step.weights.insert(step.weights.end(), table.weights.begin() + first, table.weights.begin() + first + size);
        step.offsets.push_back(int(step.indices.size()));
    }
    const IndexSpan corners = p.verticesOfFace(face), edges = p.edgesOfFace(face);
    if (corners.size() != 4 && !(corners.size() == 3 && r.num.splitsInFour(3))) return;
    auto local = [&](int childVertex) { return positionOf(r.cut.source, childVertex); };
    auto vertexPoint = [&](int i) { return local(r.num.vertexPoint(corners[i])); };
    auto edgePoint = [&](int i) { return local(r.num.edgePoint(edges[i])); };
    if (corners.size() == 4)
        step.nodes = {vertexPoint(0), edgePoint(0), vertexPoint(1), edgePoint(3), local(r.num.facePoint[face]),
                      edgePoint(1),   vertexPoint(3), edgePoint(2), vertexPoint(2)};
    else
        step.nodes = {vertexPoint(0), vertexPoint(1), vertexPoint(2), edgePoint(0), edgePoint(1), edgePoint(2)};
}

}  // namespace

void RowAccumulator::resize(int numColumns) {
    sum_.assign(std::size_t(numColumns), 0.0);
    seen_.assign(std::size_t(numColumns), 0);
    touched_.clear();
}

void RowAccumulator::add(double weight, const SparseRow& row) {
    for (int k = 0; k < row.size; ++k) {
        const std::size_t j = std::size_t(row.columns[k]);
        if (!seen_[j]) {
            seen_[j] = 1;
            touched_.push_back(int(j));
        }
        sum_[j] += weight * row.weights[k];
    }
}

void composeRow(const int* indices, const double* weights, int count, const LocalRows& rows, RowAccumulator& sum,
                LocalRows& out) {
    for (int k = 0; k < count; ++k) sum.add(weights[k], rows.row(indices[k]));
    sum.take([&](int column, double weight) {
        out.columns.push_back(column);
        out.weights.push_back(weight);
    });
    out.offsets.push_back(int(out.columns.size()));
}

namespace {

void identityRows(int n, LocalRows& rows) {
    rows.offsets.resize(std::size_t(n) + 1);
    rows.columns.resize(std::size_t(n));
    rows.weights.assign(std::size_t(n), 1.0);
    for (int v = 0; v < n; ++v) {
        rows.offsets[std::size_t(v) + 1] = v + 1;
        rows.columns[std::size_t(v)] = v;
    }
}

}  // namespace

LocalMesh cutBase(const Topology& base, int face, int rings, const Options& options, WalkScratch& scratch,
                  std::vector<int>& columns, Sharpen sharpen) {
    PatchCut cut;
    cutPatch(base, base.verticesOfFace(face), rings, scratch, cut);
    RawCut raw;
    rawCutOf(base, cut, face, scratch, raw);
    LocalMesh m;
    m.topology = topologyOf(raw, options, sharpen);
    m.face = raw.face;
    columns = cut.source;
    m.numColumns = int(cut.source.size());
    identityRows(m.numColumns, m.rows);
    return m;
}

LocalMesh refineTowards(const LocalMesh& mesh, int child, int rings, const Options& options, WalkScratch& scratch,
                        std::vector<int>* nodes, Sharpen sharpen) {
    RefinedCut r;
    refineAndCut(mesh.topology, mesh.face, child, rings, options, scratch, r);
    RawCut raw;
    rawCutOf(r.level, r.cut, r.childFace, scratch, raw);
    LocalMesh out;
    out.topology = topologyOf(raw, options, sharpen);
    out.face = raw.face;
    out.numColumns = mesh.numColumns;
    LocalStep step;
    fillStep(mesh.topology, mesh.face, r, options, step);
    RowAccumulator sum(mesh.numColumns);
    for (int v = 0; v < int(r.cut.source.size()); ++v) {
        const int first = step.offsets[std::size_t(v)];
        composeRow(step.indices.data() + first, step.weights.data() + first, step.offsets[std::size_t(v) + 1] - first,
                   mesh.rows, sum, out.rows);
    }
    if (nodes) {
        if (step.nodes.empty())
            throw std::logic_error("local mesh: nodes of a face that is neither a quad nor a triangle split in four");
        *nodes = step.nodes;
    }
    return out;
}

struct LocalShapes::Work {
    RawCut raw;
    PatchCut cut;
    RefinedCut refined;
};

LocalShapes::LocalShapes(const Options& options, int rings, int limitRings, Sharpen sharpen)
    : options_(options), rings_(rings), limitRings_(limitRings), sharpen_(sharpen),
      linear_(sharpen == Sharpen::All && rulesOf(options.scheme).surfacePatches().sharpIsLinear),
      work_(std::make_unique<Work>()) {}

LocalShapes::~LocalShapes() = default;

LocalShape& LocalShapes::intern(const Topology& level, const PatchCut& cut, int face, WalkScratch& scratch) {
    rawCutOf(level, cut, face, scratch, work_->raw);
    keyOf(work_->raw, key_);
    std::unique_ptr<LocalShape>& shape = shapes_[key_];
    if (!shape) {
        shape = std::make_unique<LocalShape>();
        shape->topology = topologyOf(work_->raw, options_, sharpen_);
        shape->face = work_->raw.face;
    }
    return *shape;
}

LocalShape& LocalShapes::cut(const Topology& base, int face, WalkScratch& baseScratch, std::vector<int>& columns) {
    cutPatch(base, base.verticesOfFace(face), rings_, baseScratch, work_->cut);
    LocalShape& shape = intern(base, work_->cut, face, baseScratch);
    columns = work_->cut.source;
    return shape;
}

const LocalStep& LocalShapes::step(LocalShape& shape, int child) {
    if (std::size_t(child) >= shape.steps.size()) shape.steps.resize(std::size_t(child) + 1);
    std::unique_ptr<LocalStep>& step = shape.steps[std::size_t(child)];
    if (!step) step = makeStep(shape, child, false);
    return *step;
}

std::unique_ptr<LocalStep> LocalShapes::makeStep(const LocalShape& shape, int child, bool wholeFace) {
    refineAndCut(shape.topology, shape.face, child, wholeFace ? limitRings_ : rings_, options_, scratch_,
                 work_->refined, wholeFace);
    auto made = std::make_unique<LocalStep>();
    made->child = &intern(work_->refined.level, work_->refined.cut, work_->refined.childFace, scratch_);
    fillStep(shape.topology, shape.face, work_->refined, options_, *made);
    return made;
}

const LocalShape& LocalShapes::classify(LocalShape& shape) {
    if (shape.classified) return shape;
    shape.classified = true;
    if (linear_) {
        // Under Sharpen::All a face is its corners' bilinear (linear) patch.
        const IndexSpan corners = shape.topology.verticesOfFace(shape.face);
        shape.points.assign(corners.begin(), corners.end());
        shape.patch = corners.size() == 4 ? PatchKind::Bilinear : PatchKind::Linear;
    } else {
        shape.patch = regularPatch(shape.topology, shape.face, options_, shape.points);
    }
    return shape;
}

const LocalStep& LocalShapes::limitStep(LocalShape& shape) {
    if (!shape.limitStep) shape.limitStep = makeStep(shape, 0, true);
    return *shape.limitStep;
}

const LocalRows& LocalShapes::limitMasks(LocalShape& shape) {
    if (shape.limitMasks) return *shape.limitMasks;
    const LocalStep& next = limitStep(shape);
    if (next.nodes.empty())
        throw std::logic_error("local mesh: nodes of a face that is neither a quad nor a triangle split in four");
    const Topology& t = next.child->topology;
    const SchemeRules& rules = rulesOf(options_.scheme);
    auto masks = std::make_unique<LocalRows>();
    VertexRing ring;
    LimitMask limit;
    LimitMaskCache cache;
    for (int vertex : next.nodes) {
        orderVertexRing(t, vertex, -1, ring);
        limit.clear();
        rules.limitMask(LimitVertex{t, options_, ring, limitRule(t, ring)}, cache, limit);
        for (int k = 0; k < limit.size(); ++k) {
            masks->columns.push_back(limit.indices[std::size_t(k)]);
            masks->weights.push_back(limit.position[std::size_t(k)]);
        }
        masks->offsets.push_back(int(masks->columns.size()));
    }
    shape.limitMasks = std::move(masks);
    return *shape.limitMasks;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
