// A face-varying channel's value mesh, its value tags and their refinement (docs/face_varying.md).
#include "far/fvar/fvar_channel.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include "far/schemes/crease.h"
#include "far/topology/face_loops.h"
#include "far/topology/level_estimate.h"
#include "far/limit/limit_ring.h"
#include "far/tables/level_stencils.h"
#include "far/schemes/scheme.h"
#include "far/internal/stencil_table_double.h"
#include "far/topology/topology_builder.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

bool isSemiSharpKind(FVarKind k) {
    return k == FVarKind::SemiSharp || k == FVarKind::Dependent || k == FVarKind::Released;
}

bool linearBoundaries(FVarLinearInterpolation i) {
    return i == FVarLinearInterpolation::Boundaries || i == FVarLinearInterpolation::All;
}

// Position of edge e among vertex v's edges.
int edgeIndexAt(const Topology& t, int v, int e) {
    const IndexSpan edges = t.edgesOfVertex(v);
    int i = 0;
    while (edges[i] != e) ++i;
    return i;
}

// `table` over the value-vertices of level 0 re-expressed over the channel's own values: entries
// of value-vertices that carry the same value merge.
StencilTableD overControlValues(const StencilTableD& table, const std::vector<int>& valueOf, int numValues) {
    StencilTableD out;
    out.numSourceVertices = numValues;
    for (std::size_t s = 0; s < table.sizes.size(); ++s) {
        const int first = int(out.indices.size());
        for (int k = table.offsets[s]; k < table.offsets[s] + table.sizes[s]; ++k) {
            const int value = valueOf[std::size_t(table.indices[std::size_t(k)])];
            int j = first;
            while (j < int(out.indices.size()) && out.indices[std::size_t(j)] != value) ++j;
            if (j == int(out.indices.size())) {
                out.indices.push_back(value);
                out.weights.push_back(0.0);
            }
            out.weights[std::size_t(j)] += table.weights[std::size_t(k)];
        }
        out.offsets.push_back(first);
        out.sizes.push_back(int(out.indices.size()) - first);
    }
    return out;
}

// The sibling of each of vertex v's corners (`corners`, in the order of its faces) as OpenSubdiv numbers them: a
// face with the value of the face before it shares its sibling, any other value is looked up
// among those met so far, except that the third distinct value met is compared with the first
// only, so that at a vertex whose faces alternate A B A B the second B run becomes a sibling of
// its own. Returns the number of siblings.
int numberSiblings(const std::vector<int>& cornerValues, const std::vector<int>& corners, std::vector<int>& siblings,
                   std::vector<int>& unique) {
    const int n = int(corners.size());
    siblings.assign(std::size_t(n), 0);
    unique.clear();
    int previous = -1;
    for (int i = 0; i < n; ++i) {
        const int value = cornerValues[std::size_t(corners[std::size_t(i)])];
        if (i > 0 && value == previous) {
            siblings[std::size_t(i)] = siblings[std::size_t(i) - 1];
        } else if (unique.size() <= 1 || (unique.size() == 2 && unique[0] != value)) {
            siblings[std::size_t(i)] = int(unique.size());
            unique.push_back(value);
        } else {
            const auto found = std::find(unique.begin(), unique.end(), value);
            siblings[std::size_t(i)] = int(found - unique.begin());
            if (found == unique.end()) unique.push_back(value);
        }
        previous = value;
    }
    return int(unique.size());
}

}  // namespace

FVarChannelRefinement::FVarChannelRefinement(const TopologyDescriptor& desc, int channel, const Topology& mesh,
                                             const Options& options) {
    const FVarChannel& c = desc.fvarChannels[channel];
    numControlValues_ = c.numValues;
    // The channel's faces are the mesh's level-0 faces: the loops the descriptor's faces walk
    // around (face_loops.h), each corner with the value of the input corner it comes from.
    FaceLoopSplitter splitter(desc.numVertices, rulesOf(options.scheme).collapsedEdges());
    std::vector<int> faceVerts, sizes, corners;
    controlValues_.reserve(std::size_t(mesh.numFaceVertices()));
    const int* verts = desc.faceVertIndices;
    const int* valueIndices = c.valueIndices;
    for (int f = 0; f < desc.numFaces; ++f) {
        const int n = desc.numVertsPerFace[f];
        corners.clear();
        splitter.split(verts, n, faceVerts, sizes, &corners);
        for (int k : corners) controlValues_.push_back(valueIndices[k]);
        verts += n;
        valueIndices += n;
    }
    if (options.leftHanded) {  // as the mesh stores its faces: the first corner kept, the rest reversed
        for (int f = 0; f < mesh.numFaces(); ++f)
            std::reverse(controlValues_.begin() + mesh.faceOffsets[f] + 1, controlValues_.begin() + mesh.faceOffsets[f + 1]);
    }

    // Value-vertices: each mesh vertex's values, numbered as OpenSubdiv numbers a vertex's
    // "siblings" (vertex by vertex, each in the order its faces come around it).
    Level level;
    Topology& values = level.values;
    values.faceOffsets = mesh.faceOffsets;
    values.faceVerts.assign(std::size_t(mesh.numFaceVertices()), -1);
    VertexRing ring;
    std::vector<int> ringCorners, siblings, unique;
    for (int v = 0; v < mesh.numVertices; ++v) {
        if (mesh.vertexFaceCount(v) == 0) continue;
        orderVertexRing(mesh, v, -1, ring);
        // A face with a collapsed edge is in the ring once per corner at v: each time, its first
        // corner at v not yet taken (marked -2 until numbered).
        ringCorners.clear();
        for (int f : ring.faces) {
            int k = mesh.faceOffsets[f];
            while (mesh.faceVerts[std::size_t(k)] != v || values.faceVerts[std::size_t(k)] != -1) ++k;
            values.faceVerts[std::size_t(k)] = -2;
            ringCorners.push_back(k);
        }
        const int count = numberSiblings(controlValues_, ringCorners, siblings, unique);
        for (std::size_t i = 0; i < ringCorners.size(); ++i)
            values.faceVerts[std::size_t(ringCorners[i])] = values.numVertices + siblings[i];
        values.numVertices += count;
    }
    const int nc = mesh.numFaceVertices();
    completeTopology(values);
    level.meshVertex.resize(std::size_t(values.numVertices));
    controlValueOf_.resize(std::size_t(values.numVertices));
    for (int k = 0; k < nc; ++k) {
        level.meshVertex[std::size_t(values.faceVerts[std::size_t(k)])] = mesh.faceVerts[std::size_t(k)];
        controlValueOf_[std::size_t(values.faceVerts[std::size_t(k)])] = controlValues_[std::size_t(k)];
    }
    level.meshEdge.resize(std::size_t(values.numEdges()));
    for (int k = 0; k < nc; ++k) level.meshEdge[std::size_t(values.faceEdges[std::size_t(k)])] = mesh.faceEdges[std::size_t(k)];
    levels_.push_back(std::move(level));
    restart(mesh, options);
}

void FVarChannelRefinement::restart(const Topology& mesh, const Options& options) {
    levels_.resize(1);
    tables_.clear();
    Level& level = levels_[0];
    Topology& values = level.values;
    values.faceHole = mesh.faceHole;
    // A seam, a boundary or a non-manifold edge of the value mesh is infinitely sharp; every other
    // edge has its mesh edge's sharpness.
    for (int e = 0; e < values.numEdges(); ++e)
        values.edgeSharpness[std::size_t(e)] = (values.edgeFlags[std::size_t(e)] & (kEdgeBoundary | kEdgeNonManifold))
                                                   ? kInfiniteSharpness
                                                   : mesh.edgeSharpness[std::size_t(level.meshEdge[std::size_t(e)])];
    for (int p = 0; p < values.numVertices; ++p)
        values.vertSharpness[std::size_t(p)] = mesh.vertSharpness[std::size_t(level.meshVertex[std::size_t(p)])];
    tagLevel0(mesh, options);
    sharpen(levels_[0], options);
}

// OpenSubdiv's analysis of the channel's level 0 (docs/face_varying.md, "Which values are
// sharp"): which mesh edges are split, which vertices' values do not match their vertex, and the
// kind of each of those values from its span of faces.
void FVarChannelRefinement::tagLevel0(const Topology& mesh, const Options& options) {
    using I = FVarLinearInterpolation;
    const I option = options.fvarLinearInterpolation;
    const bool linear = linearBoundaries(option);
    const bool dependent = option == I::CornersPlus1 || option == I::CornersPlus2;
    const bool fvarCornersSharp = option != I::None;
    const bool smoothCornersSharp = options.boundary != BoundaryInterpolation::EdgeAndCorner && fvarCornersSharp;
    const bool sharpenBothIfOneCorner = option == I::CornersPlus2;
    const bool sharpenDarts = sharpenBothIfOneCorner || linear;

    Level& level = levels_[0];
    const Topology& values = level.values;
    // Per mesh edge end (2e: at edgeVerts[2e]): whether its faces disagree on the value there.
    const int ne = mesh.numEdges();
    std::vector<int> valueAt(2 * std::size_t(ne), -1);
    std::vector<uint8_t> splitAt(2 * std::size_t(ne), 0);
    for (int f = 0; f < mesh.numFaces(); ++f) {
        const int b = mesh.faceOffsets[f], n = mesh.faceSize(f);
        for (int i = 0; i < n; ++i) {
            const int e = mesh.faceEdges[std::size_t(b + i)];
            const int from = values.faceVerts[std::size_t(b + i)], to = values.faceVerts[std::size_t(b + (i + 1) % n)];
            const bool forward = mesh.edgeVerts[2 * std::size_t(e)] == mesh.faceVerts[std::size_t(b + i)];
            const int ends[2] = {forward ? from : to, forward ? to : from};
            for (int end = 0; end < 2; ++end) {
                int& seen = valueAt[2 * std::size_t(e) + end];
                if (seen < 0) seen = ends[end];
                else if (seen != ends[end]) splitAt[2 * std::size_t(e) + end] = 1;
            }
        }
    }
    // Vertices in order, as OpenSubdiv visits them: a boundary vertex not yet known to mismatch
    // makes its boundary edges linear under linear boundaries (an edge split only at its far end
    // is known there once that end has been visited).
    const int nv = mesh.numVertices;
    std::vector<int> valuesAt(std::size_t(nv), 0);
    for (int p = 0; p < values.numVertices; ++p) ++valuesAt[std::size_t(level.meshVertex[std::size_t(p)])];
    std::vector<uint8_t> mismatch(std::size_t(nv), 0), linearEdge(std::size_t(ne), 0);
    for (int v = 0; v < nv; ++v) {
        for (int e : mesh.edgesOfVertex(v)) {
            if (!splitAt[2 * std::size_t(e) + (mesh.edgeVerts[2 * std::size_t(e)] == v ? 0 : 1)]) continue;
            mismatch[std::size_t(mesh.edgeVerts[2 * std::size_t(e)])] = 1;
            mismatch[std::size_t(mesh.edgeVerts[2 * std::size_t(e) + 1])] = 1;
        }
        const int nf = mesh.vertexFaceCount(v);
        if ((mesh.vertFlags[std::size_t(v)] & kVertexBoundary) && !mismatch[std::size_t(v)]) {
            if (linear && nf > 0) {
                mismatch[std::size_t(v)] = 1;
                for (int e : mesh.edgesOfVertex(v))
                    if (mesh.edgeFlags[std::size_t(e)] & kEdgeBoundary) linearEdge[std::size_t(e)] = 1;
            } else if (nf == 1 && smoothCornersSharp) {
                mismatch[std::size_t(v)] = 1;
            }
        }
        // Faces meeting only at a non-manifold vertex may disagree on its value with no split edge.
        if ((mesh.vertFlags[std::size_t(v)] & kVertexNonManifold) && valuesAt[std::size_t(v)] > 1) mismatch[std::size_t(v)] = 1;
    }
    level.edgeTags.resize(std::size_t(values.numEdges()));
    for (int e = 0; e < values.numEdges(); ++e) {
        const int m = level.meshEdge[std::size_t(e)];
        level.edgeTags[std::size_t(e)] = uint8_t((splitAt[2 * std::size_t(m)] || splitAt[2 * std::size_t(m) + 1] ? kSplit : 0) |
                                                 (linearEdge[std::size_t(m)] ? kLinear : 0));
    }

    // The values of a mismatched vertex, contiguous in value-vertex order, each with its span: the
    // faces it covers and the sharpness of the edges inside them.
    struct Span {
        bool disjoint = false;  // not one fan with its seams on both sides (OpenSubdiv: non-manifold)
        int size = 0;
        int infSharp = 0, semiSharp = 0;
    };
    level.kind.assign(std::size_t(values.numVertices), FVarKind::Match);
    level.partner.assign(std::size_t(values.numVertices), -1);
    for (int first = 0; first < values.numVertices;) {
        const int v = level.meshVertex[std::size_t(first)];
        int last = first;
        while (last < values.numVertices && level.meshVertex[std::size_t(last)] == v) ++last;
        const int count = last - first;
        if (!mismatch[std::size_t(v)]) {
            first = last;
            continue;
        }
        const uint8_t flags = mesh.vertFlags[std::size_t(v)];
        const float vs = mesh.vertSharpness[std::size_t(v)];
        std::vector<Span> spans(static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i) {
            const int p = first + i;
            Span& s = spans[std::size_t(i)];
            s.disjoint = (flags & kVertexNonManifold) || (values.vertFlags[std::size_t(p)] & kVertexNonManifold);
            s.size = values.vertexFaceCount(p);
            for (int e : values.edgesOfVertex(p)) {
                if (values.edgeFaceCount(e) != 2) continue;
                const float es = mesh.edgeSharpness[std::size_t(level.meshEdge[std::size_t(e)])];
                s.infSharp += isInfinite(es) ? 1 : 0;
                s.semiSharp += isSemiSharp(es) ? 1 : 0;
            }
        }
        bool allSharp = linear || isInfinite(vs) || (flags & kVertexNonManifold) || (dependent && count > 2) ||
                        (sharpenDarts && count == 1 && !(flags & kVertexBoundary));
        bool dependentPair = false;
        if (!allSharp && dependent && count == 2) {
            const Span &a = spans[0], &b = spans[1];
            allSharp = a.infSharp || b.infSharp || a.disjoint || b.disjoint ||
                       (sharpenBothIfOneCorner && (a.size == 1 || b.size == 1));
            dependentPair = (a.semiSharp > 0) != (b.semiSharp > 0);
        }
        for (int i = 0; i < count; ++i) {
            const int p = first + i;
            const Span& s = spans[std::size_t(i)];
            FVarKind& kind = level.kind[std::size_t(p)];
            if (s.disjoint || allSharp || s.infSharp > 0 || (s.size == 1 && fvarCornersSharp)) {
                kind = FVarKind::Corner;
            } else if (s.semiSharp > 0 || isSemiSharp(vs)) {
                kind = FVarKind::SemiSharp;
            } else if (dependentPair) {
                kind = FVarKind::Dependent;
                level.partner[std::size_t(p)] = first + (1 - i);
            } else {
                kind = FVarKind::Crease;
            }
        }
        first = last;
    }
}

// The value mesh's sharpness from the kinds: corners infinitely sharp, creases not at all, the
// rest as the mesh has it (a dependent value's is set while refining); everything sharp, edges
// too, when the channel is linear throughout.
void FVarChannelRefinement::sharpen(Level& level, const Options& options) const {
    Topology& values = level.values;
    if (options.fvarLinearInterpolation == FVarLinearInterpolation::All) {
        std::fill(values.edgeSharpness.begin(), values.edgeSharpness.end(), kInfiniteSharpness);
        std::fill(values.vertSharpness.begin(), values.vertSharpness.end(), kInfiniteSharpness);
        return;
    }
    for (int p = 0; p < values.numVertices; ++p) {
        const FVarKind k = level.kind[std::size_t(p)];
        if (k == FVarKind::Corner) values.vertSharpness[std::size_t(p)] = kInfiniteSharpness;
        if (k == FVarKind::Crease || k == FVarKind::Released) values.vertSharpness[std::size_t(p)] = 0.0f;
    }
}

// The kinds of the child values, as OpenSubdiv propagates its value tags: face points match;
// an edge point of a split (or linear) edge is a crease (a corner under linear boundaries); a
// vertex point inherits its parent's kind, a semi-sharp one relaxing to a crease once the
// sharpness at its vertex (within its span for its own) has decayed.
std::vector<FVarKind> FVarChannelRefinement::childKinds(const Level& parent, const Topology& meshParent,
                                                        const ChildNumbering& num, const Options& options) const {
    const Topology& values = parent.values;
    const int numChildren = num.numFacePoints + values.numEdges() + values.numVertices;
    std::vector<FVarKind> kinds(std::size_t(numChildren), FVarKind::Match);
    const FVarKind splitKind = linearBoundaries(options.fvarLinearInterpolation) ? FVarKind::Corner : FVarKind::Crease;
    for (int e = 0; e < values.numEdges(); ++e)
        if (parent.edgeTags[std::size_t(e)] & (kSplit | kLinear)) kinds[std::size_t(num.edgePoint(e))] = splitKind;
    std::vector<float> childSharpness;
    for (int p = 0; p < values.numVertices; ++p) {
        FVarKind& kind = kinds[std::size_t(num.vertexPoint(p))];
        kind = parent.kind[std::size_t(p)];
        if (!isSemiSharpKind(kind)) continue;
        const int v = parent.meshVertex[std::size_t(p)];
        const IndexSpan edges = meshParent.edgesOfVertex(v);
        bool semiSharpAtVertex = isSemiSharp(meshParent.vertSharpness[std::size_t(v)]);
        for (int e : edges) semiSharpAtVertex = semiSharpAtVertex || isSemiSharp(meshParent.edgeSharpness[std::size_t(e)]);
        if (!semiSharpAtVertex || isSharp(decrementSharpness(meshParent.vertSharpness[std::size_t(v)]))) continue;
        childSharpness.resize(std::size_t(edges.size()));
        childEdgeSharpnessAtVertex(meshParent, v, options.creaseMethod, childSharpness.data());
        if (std::none_of(childSharpness.begin(), childSharpness.end(), isSemiSharp)) {
            kind = FVarKind::Crease;
            continue;
        }
        if (kind == FVarKind::Dependent) continue;
        bool stillSemiSharp = false;
        for (int e : values.edgesOfVertex(p))
            if (values.edgeFaceCount(e) == 2)
                stillSemiSharp = stillSemiSharp ||
                                 isSemiSharp(childSharpness[std::size_t(edgeIndexAt(meshParent, v, parent.meshEdge[std::size_t(e)]))]);
        if (!stillSemiSharp) kind = FVarKind::Crease;
    }
    for (int p = 0; p < values.numVertices; ++p) {
        FVarKind& kind = kinds[std::size_t(num.vertexPoint(p))];
        if (kind == FVarKind::Dependent &&
            !isSemiSharpKind(kinds[std::size_t(num.vertexPoint(parent.partner[std::size_t(p)]))]))
            kind = FVarKind::Released;
    }
    return kinds;
}

// Per value-vertex edge (parallel to vertEdges): the sharpness its child takes at that end, the
// mesh's own (Chaikin reads the mesh vertex's edges), infinite on the value mesh's boundaries.
std::vector<float> FVarChannelRefinement::meshChildEdgeSharpness(const Level& parent, const Topology& meshParent,
                                                                 const Options& options) const {
    const Topology& values = parent.values;
    std::vector<float> out(values.vertEdges.size());
    std::vector<float> meshChild;
    for (int p = 0; p < values.numVertices; ++p) {
        const int v = parent.meshVertex[std::size_t(p)];
        meshChild.resize(std::size_t(meshParent.vertexEdgeCount(v)));
        childEdgeSharpnessAtVertex(meshParent, v, options.creaseMethod, meshChild.data());
        const IndexSpan edges = values.edgesOfVertex(p);
        for (int i = 0; i < edges.size(); ++i) {
            const int e = edges[i];
            const bool seam = values.edgeFlags[std::size_t(e)] & (kEdgeBoundary | kEdgeNonManifold);
            out[std::size_t(values.vertEdgeOffsets[p] + i)] =
                seam ? decrementSharpness(values.edgeSharpness[std::size_t(e)])
                     : meshChild[std::size_t(edgeIndexAt(meshParent, v, parent.meshEdge[std::size_t(e)]))];
        }
    }
    return out;
}

void FVarChannelRefinement::refine(const Topology& meshParent, const Topology& meshChild, const Options& options) {
    Level& parent = levels_.back();
    Topology& values = parent.values;
    if (parent.meshEdge.empty()) {  // the mesh level was faces only when this level was made
        parent.meshEdge.resize(std::size_t(values.numEdges()));
        for (int k = 0; k < values.numFaceVertices(); ++k)
            parent.meshEdge[std::size_t(values.faceEdges[std::size_t(k)])] = meshParent.faceEdges[std::size_t(k)];
    }
    const ChildNumbering num = numberChildren(values, rulesOf(options.scheme).triangleSplit());
    Level child;
    child.kind = childKinds(parent, meshParent, num, options);
    // A dependent value stays a corner while its child is semi-sharp; when the child becomes a
    // crease, the blend takes its weight from the other value's span.
    if (options.fvarLinearInterpolation != FVarLinearInterpolation::All) {
        std::vector<float> pe, ce, childSharpness;
        for (int p = 0; p < values.numVertices; ++p) {
            if (parent.kind[std::size_t(p)] != FVarKind::Dependent) continue;
            float s = kInfiniteSharpness;
            if (child.kind[std::size_t(num.vertexPoint(p))] == FVarKind::Crease) {
                const int v = parent.meshVertex[std::size_t(p)], q = parent.partner[std::size_t(p)];
                childSharpness.resize(std::size_t(meshParent.vertexEdgeCount(v)));
                childEdgeSharpnessAtVertex(meshParent, v, options.creaseMethod, childSharpness.data());
                pe.clear();
                ce.clear();
                for (int e : values.edgesOfVertex(q)) {
                    if (values.edgeFaceCount(e) != 2) continue;
                    const int m = parent.meshEdge[std::size_t(e)];
                    pe.push_back(meshParent.edgeSharpness[std::size_t(m)]);
                    ce.push_back(childSharpness[std::size_t(edgeIndexAt(meshParent, v, m))]);
                }
                const float pv = meshParent.vertSharpness[std::size_t(v)];
                s = transitionWeight(pv, decrementSharpness(pv), int(pe.size()), pe.data(), ce.data());
            }
            values.vertSharpness[std::size_t(p)] = s;
        }
    }
    // Chaikin decay reads every semi-sharp edge at a vertex: the value mesh's edges decay as the
    // mesh's do, not as a value-vertex's own span alone would.
    std::vector<float> childSharpness;
    if (options.creaseMethod == CreaseMethod::Chaikin) childSharpness = meshChildEdgeSharpness(parent, meshParent, options);
    const std::vector<float>* override = childSharpness.empty() ? nullptr : &childSharpness;
    if (tables_.empty()) {
        tables_.push_back(toFloatTable(overControlValues(buildLevelStencils<StencilTableD>(values, num, options, override),
                                                         controlValueOf_, numControlValues_)));
    } else {
        tables_.push_back(buildLevelStencils<StencilTable>(values, num, options, override));
    }
    child.values = refineTopology(values, num, options.creaseMethod, TopologyDetail::Full);
    for (int p = 0; p < values.numVertices && override; ++p) {
        const IndexSpan edges = values.edgesOfVertex(p);
        for (int i = 0; i < edges.size(); ++i) {
            const int e = edges[i];
            child.values.edgeSharpness[2 * std::size_t(e) + (values.edgeVerts[2 * std::size_t(e)] == p ? 0 : 1)] =
                childSharpness[std::size_t(values.vertEdgeOffsets[p] + i)];
        }
    }
    const Topology& cv = child.values;
    child.meshVertex.resize(std::size_t(cv.numVertices));
    for (int k = 0; k < cv.numFaceVertices(); ++k)
        child.meshVertex[std::size_t(cv.faceVerts[std::size_t(k)])] = meshChild.faceVerts[std::size_t(k)];
    if (!meshChild.faceEdges.empty()) {
        child.meshEdge.resize(std::size_t(cv.numEdges()));
        for (int k = 0; k < cv.numFaceVertices(); ++k)
            child.meshEdge[std::size_t(cv.faceEdges[std::size_t(k)])] = meshChild.faceEdges[std::size_t(k)];
    }
    child.partner.assign(std::size_t(cv.numVertices), -1);
    for (int p = 0; p < values.numVertices; ++p)
        if (parent.partner[std::size_t(p)] >= 0)
            child.partner[std::size_t(num.vertexPoint(p))] = num.vertexPoint(parent.partner[std::size_t(p)]);
    child.edgeTags.assign(std::size_t(cv.numEdges()), 0);
    for (int e = 0; e < values.numEdges(); ++e) {
        child.edgeTags[2 * std::size_t(e)] = parent.edgeTags[std::size_t(e)];
        child.edgeTags[2 * std::size_t(e) + 1] = parent.edgeTags[std::size_t(e)];
    }
    sharpen(child, options);
    levels_.push_back(std::move(child));
}

IndexSpan FVarChannelRefinement::valuesOfFace(int L, int f) const {
    if (L == 0) {
        const Topology& t = levels_[0].values;
        return {controlValues_.data() + t.faceOffsets[std::size_t(f)], controlValues_.data() + t.faceOffsets[std::size_t(f) + 1]};
    }
    return levels_.at(std::size_t(L)).values.verticesOfFace(f);
}

IndexSpan FVarChannelRefinement::valuesOfLevel(int L) const {
    const std::vector<int>& corners = L == 0 ? controlValues_ : levels_.at(std::size_t(L)).values.faceVerts;
    return {corners.data(), corners.data() + corners.size()};
}

std::size_t FVarChannelRefinement::bytes() const {
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    std::size_t total = bytes(controlValues_) + bytes(controlValueOf_);
    for (const Level& l : levels_)
        total += bytesOf(l.values) + bytes(l.meshVertex) + bytes(l.meshEdge) + bytes(l.kind) + bytes(l.partner) +
                 bytes(l.edgeTags);
    for (const StencilTable& t : tables_) total += t.bytes();
    return total;
}

std::size_t FVarChannelRefinement::estimateNextLevelBytes(const SchemeRules& rules) const {
    return estimateLevelBytes(levels_.back().values, rules);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
