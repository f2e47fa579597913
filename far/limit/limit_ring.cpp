// A vertex's neighbourhood in rotational order, and where that order starts (docs/limit.md,
// "Ring order"): the limit masks of creases and corners depend on the start, so it is chosen as
// OpenSubdiv chooses it, level by level.
#include "far/limit/limit_ring.h"

#include <algorithm>

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// Face f's edge leaving (entering) its corner c. Topology stores faces counter-clockwise
// (left-handed input reversed), so this is the winding that makes the outside.
int leavingEdge(const Topology& t, int f, int c) { return t.edgeOfCorner(f, c); }
int enteringEdge(const Topology& t, int f, int c) { return t.edgeOfCorner(f, c - 1); }

void fillIncidenceOrder(const Topology& t, int v, VertexRing& ring) {
    ring.manifold = false;
    for (int f : t.facesOfVertex(v)) ring.faces.push_back(f);
    for (int e : t.edgesOfVertex(v)) ring.edges.push_back(e);
}

// Walks from `start` across each face's entering edge; false if the fan does not close up as a
// manifold vertex's does.
bool walk(const Topology& t, int v, int start, VertexRing& ring) {
    const int numFaces = t.vertexFaceCount(v);
    int f = start;
    ring.edges.push_back(leavingEdge(t, f, t.cornerOfVertex(f, v)));
    while (true) {
        ring.faces.push_back(f);
        const int e = enteringEdge(t, f, t.cornerOfVertex(f, v));
        if (e == ring.edges[0]) return !ring.boundary && int(ring.faces.size()) == numFaces;
        ring.edges.push_back(e);
        const IndexSpan faces = t.facesOfEdge(e);
        if (faces.size() == 1) return ring.boundary && int(ring.faces.size()) == numFaces;
        if (faces.size() != 2 || int(ring.faces.size()) >= numFaces) return false;
        f = faces[0] == f ? faces[1] : faces[0];
    }
}

}  // namespace

void orderVertexRing(const Topology& t, int v, int startFace, VertexRing& ring) {
    ring.vertex = v;
    ring.manifold = true;
    ring.boundary = (t.vertFlags[v] & kVertexBoundary) != 0;
    ring.faces.clear();
    ring.edges.clear();
    ring.neighbours.clear();
    ring.opposite.clear();
    ring.edgeSharpness.clear();
    if (t.vertexFaceCount(v) > 0) {
        const IndexSpan faces = t.facesOfVertex(v);
        int start = std::find(faces.begin(), faces.end(), startFace) != faces.end() ? startFace : faces[0];
        if (ring.boundary) {  // the face whose leaving edge is a boundary edge
            for (int f : t.facesOfVertex(v))
                if (t.edgeFaceCount(leavingEdge(t, f, t.cornerOfVertex(f, v))) == 1) start = f;
        }
        if ((t.vertFlags[v] & kVertexNonManifold) || !walk(t, v, start, ring)) {
            ring.faces.clear();
            ring.edges.clear();
            fillIncidenceOrder(t, v, ring);
        }
    }
    for (int e : ring.edges) {
        ring.neighbours.push_back(t.otherVertex(e, v));
        ring.edgeSharpness.push_back(t.edgeSharpness[e]);
    }
    for (int f : ring.faces) {
        const int n = t.faceSize(f), c = t.cornerOfVertex(f, v);
        ring.opposite.push_back(t.verticesOfFace(f)[(c + 2) % n]);
    }
}

VertexRule limitRule(const Topology& t, const VertexRing& ring) {
    int sharp = 0;
    for (float s : ring.edgeSharpness) sharp += isSharp(s) ? 1 : 0;
    return vertexRule(t.vertSharpness[ring.vertex], sharp);
}

RingStarts::RingStarts(const Topology& level0) {
    vertexStart_.assign(level0.numVertices, -1);
    edgeFirst_.assign(level0.numEdges(), -1);
    for (int v = 0; v < level0.numVertices; ++v)
        if (level0.vertexFaceCount(v) > 0) vertexStart_[v] = level0.facesOfVertex(v)[0];
    for (int e = 0; e < level0.numEdges(); ++e)
        if (level0.edgeFaceCount(e) > 0) edgeFirst_[e] = level0.facesOfEdge(e)[0];
}

// The propagation mirrors how OpenSubdiv lists a child's faces: a face point starts at the
// child of corner 0, an edge point at the child (of the edge's first face) at the corner after
// the edge, a vertex point at the child of its parent's first face; a child edge's first face
// is the child of its parent edge's first face at its end, or, inside a face, the child at
// corner j (quads) or the corner triangle beside it (triangles split in four).
void RingStarts::descend(const Topology& parent, const ChildNumbering& numbering, int childVertices) {
    const int nf = parent.numFaces(), ne = parent.numEdges();
    std::vector<int> firstChildFace(std::size_t(nf) + 1, 0), firstInterior(std::size_t(nf) + 1, 2 * ne);
    for (int f = 0; f < nf; ++f) {
        const int n = parent.faceSize(f);
        firstChildFace[f + 1] = firstChildFace[f] + (numbering.splitsInFour(n) ? 4 : n);
        firstInterior[f + 1] = firstInterior[f] + n;
    }
    std::vector<int> vertexStart(childVertices, -1), edgeFirst(firstInterior[nf], -1);
    for (int f = 0; f < nf; ++f) {
        const int n = parent.faceSize(f);
        if (numbering.facePoint[f] >= 0) vertexStart[numbering.facePoint[f]] = firstChildFace[f];
        for (int j = 0; j < n; ++j)
            edgeFirst[firstInterior[f] + j] = firstChildFace[f] + (numbering.splitsInFour(n) ? (j + 1) % 3 : j);
    }
    for (int e = 0; e < ne; ++e) {
        const int f = edgeFirst_[e];
        if (f < 0) continue;
        const int n = parent.faceSize(f), c = parent.cornerOfEdge(f, e);
        vertexStart[numbering.edgePoint(e)] = firstChildFace[f] + (c + 1) % n;
        // The half at each end is the child at that end's corner: c or c + 1 (a face may hold a
        // vertex twice, beside a collapsed edge, so the corner is read from the edge's place).
        const bool collapsed = parent.edgeVerts[2 * e] == parent.edgeVerts[2 * e + 1];
        for (int k = 0; k < 2; ++k) {
            const bool atNext = collapsed ? k == 1 : parent.verticesOfFace(f)[c] != parent.edgeVerts[2 * e + k];
            edgeFirst[2 * e + k] = firstChildFace[f] + (c + (atNext ? 1 : 0)) % n;
        }
    }
    for (int v = 0; v < parent.numVertices; ++v) {
        const int f = vertexStart_[v];
        if (f >= 0) vertexStart[numbering.vertexPoint(v)] = firstChildFace[f] + parent.cornerOfVertex(f, v);
    }
    vertexStart_ = std::move(vertexStart);
    edgeFirst_ = std::move(edgeFirst);
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
