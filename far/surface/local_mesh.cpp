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

// The cut as a topology of its own with the level's own edges (a face list would join the two
// children of a collapsed edge, which link the same two vertices), sharpness as cutPatch reads it
// (boundary edges without theirs, so that the rim's boundaries never come back as creases inside
// a later cut), then the boundary rules of a base mesh.
Topology cutKeepingEdges(const Topology& t, const PatchCut& cut, const Options& options, WalkScratch& scratch) {
    Topology m;
    m.numVertices = int(cut.source.size());
    m.faceVerts = cut.corners;
    StampedMarks& localEdge = scratch.labels;  // level edge -> cut edge; cutPatch is done with it
    localEdge.clear(t.numEdges());
    std::vector<float> edgeSharpness;
    auto edgeOf = [&](int e, int from, int to) {
        if (localEdge.marked(e)) return localEdge.value(e);
        const int id = m.numEdges();
        localEdge.mark(e, id);
        m.edgeVerts.insert(m.edgeVerts.end(), {from, to});
        const bool crease = isSharp(t.edgeSharpness[std::size_t(e)]) && !(t.edgeFlags[std::size_t(e)] & kEdgeBoundary);
        edgeSharpness.push_back(crease ? t.edgeSharpness[std::size_t(e)] : 0.0f);
        return id;
    };
    int corner = 0;
    for (std::size_t i = 0; i < cut.faceSource.size(); ++i) {
        const int f = cut.faceSource[i], n = t.faceSize(f), first = corner;
        m.faceOffsets.push_back(first + n);
        const IndexSpan verts = t.verticesOfFace(f), edges = t.edgesOfFace(f);
        for (int k = 0; k < n; ++k, ++corner) {
            const int e = edges[k], here = cut.corners[std::size_t(first + k)],
                      next = cut.corners[std::size_t(first + (k + 1) % n)];
            const bool forward = t.edgeVerts[2 * std::size_t(e)] == verts[k];
            m.faceEdges.push_back(edgeOf(e, forward ? here : next, forward ? next : here));
        }
    }
    completeTopologyFromEdges(m);
    m.edgeSharpness = edgeSharpness;
    for (int v = 0; v < m.numVertices; ++v) {
        const float s = t.vertSharpness[std::size_t(cut.source[std::size_t(v)])];
        m.vertSharpness[std::size_t(v)] = isSharp(s) ? s : 0.0f;
    }
    for (std::size_t i = 0; i < cut.faceSource.size(); ++i) m.faceHole[i] = t.faceHole[std::size_t(cut.faceSource[i])];
    applyBoundaryRules(m, options);
    return m;
}

LocalMesh meshOfCut(const Topology& level, const PatchCut& cut, int face, const Options& options, Sharpen sharpen,
                    WalkScratch& scratch) {
    LocalMesh m;
    m.topology = cutKeepingEdges(level, cut, cutOptions(options), scratch);
    applySharpen(m.topology, sharpen);
    m.face = positionOf(cut.faceSource, face);
    return m;
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

LocalMesh cutBase(const Topology& base, int face, int rings, const Options& options, WalkScratch& scratch,
                  std::vector<int>& columns, Sharpen sharpen) {
    PatchCut cut;
    cutPatch(base, base.verticesOfFace(face), rings, scratch, cut);
    LocalMesh m = meshOfCut(base, cut, face, options, sharpen, scratch);
    const int n = int(cut.source.size());
    columns = cut.source;
    m.numColumns = n;
    m.rowOffsets.resize(std::size_t(n) + 1);
    m.rowColumns.resize(std::size_t(n));
    m.rowWeights.assign(std::size_t(n), 1.0);
    for (int v = 0; v < n; ++v) {
        m.rowOffsets[std::size_t(v) + 1] = v + 1;
        m.rowColumns[std::size_t(v)] = v;
    }
    return m;
}

LocalMesh refineTowards(const LocalMesh& mesh, int child, int rings, const Options& options, WalkScratch& scratch,
                        std::vector<int>* nodes, Sharpen sharpen) {
    const Topology& p = mesh.topology;
    const ChildNumbering num = numberChildren(p, rulesOf(options.scheme).triangleSplit());
    const Topology c = refineTopology(p, num, options.creaseMethod, TopologyDetail::Full);
    int childFace = child;
    for (int f = 0; f < mesh.face; ++f) childFace += num.splitsInFour(p.faceSize(f)) ? 4 : p.faceSize(f);

    PatchCut cut;
    cutPatch(c, c.verticesOfFace(childFace), rings, scratch, cut);
    LocalMesh out = meshOfCut(c, cut, childFace, options, sharpen, scratch);

    std::vector<std::uint8_t> wanted(std::size_t(c.numVertices), 0);
    for (int v : cut.source) wanted[v] = 1;
    const StencilTableD table = buildLevelStencils<StencilTableD>(p, num, options, nullptr, &wanted);
    out.numColumns = mesh.numColumns;
    RowAccumulator sum(mesh.numColumns);
    for (std::size_t i = 0; i < cut.source.size(); ++i) {
        const int v = cut.source[i], first = table.offsets[v];
        for (int k = first; k < first + table.sizes[v]; ++k) sum.add(table.weights[k], mesh.row(table.indices[k]));
        sum.take([&](int column, double weight) {
            out.rowColumns.push_back(column);
            out.rowWeights.push_back(weight);
        });
        out.rowOffsets.push_back(int(out.rowColumns.size()));
    }

    if (nodes) {
        const IndexSpan corners = p.verticesOfFace(mesh.face), edges = p.edgesOfFace(mesh.face);
        auto local = [&](int childVertex) { return positionOf(cut.source, childVertex); };
        auto vertexPoint = [&](int i) { return local(num.vertexPoint(corners[i])); };
        auto edgePoint = [&](int i) { return local(num.edgePoint(edges[i])); };
        if (corners.size() == 4)
            *nodes = {vertexPoint(0), edgePoint(0), vertexPoint(1), edgePoint(3), local(num.facePoint[mesh.face]),
                      edgePoint(1),   vertexPoint(3), edgePoint(2), vertexPoint(2)};
        else if (corners.size() == 3 && num.splitsInFour(3))
            *nodes = {vertexPoint(0), vertexPoint(1), vertexPoint(2), edgePoint(0), edgePoint(1), edgePoint(2)};
        else
            throw std::logic_error("local mesh: nodes of a face that is neither a quad nor a triangle split in four");
    }
    return out;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
