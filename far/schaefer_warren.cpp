#include "far/internal/schaefer_warren.h"

#include "far/internal/rules.h"
#include "far/internal/unzip.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {

UnzippedLevel::UnzippedLevel(const Topology& t)
    : triangleCopies(unzipStencils(t, Piece::Triangle)),
      quadCopies(unzipStencils(t, Piece::Quad)),
      faceTouches(t.numFaces(), 0) {
    for (int f = 0; f < t.numFaces(); ++f)
        for (int c = t.faceOffsets[f]; c < t.faceOffsets[f + 1]; ++c)
            if (quadCopies.sizes[t.faceVerts[c]] > 1) faceTouches[f] = 1;
}

SchaeferWarrenMasks::SchaeferWarrenMasks(const Topology& topology, const UnzippedLevel& unzipped,
                                         SparseAccumulator& accumulator)
    : t_(topology), u_(unzipped), acc_(accumulator) {}

bool SchaeferWarrenMasks::touchesEdge(int e) const {
    for (int k = t_.edgeFaceOffsets[e]; k < t_.edgeFaceOffsets[e + 1]; ++k)
        if (u_.faceTouches[t_.edgeFaces[k]]) return true;
    return false;
}

bool SchaeferWarrenMasks::touchesVertex(int v) const {
    for (int k = t_.vertFaceOffsets[v]; k < t_.vertFaceOffsets[v + 1]; ++k)
        if (u_.faceTouches[t_.vertFaces[k]]) return true;
    return false;
}

void SchaeferWarrenMasks::addCopy(int v, bool quad, double scale) {
    const StencilTableD& copies = quad ? u_.quadCopies : u_.triangleCopies;
    for (int k = copies.offsets[v]; k < copies.offsets[v] + copies.sizes[v]; ++k)
        acc_.add(copies.indices[k], scale * copies.weights[k]);
}

void SchaeferWarrenMasks::addPoint(Point p, bool quad, double scale) {
    switch (p.kind) {
    case Point::Vertex: addCopy(p.index, quad, scale); break;
    case Point::Edge:
        addCopy(t_.edgeVerts[2 * p.index], quad, 0.5 * scale);
        addCopy(t_.edgeVerts[2 * p.index + 1], quad, 0.5 * scale);
        break;
    case Point::Face: {  // only quads and n-gons have centres
        const int b = t_.faceOffsets[p.index], n = t_.faceSize(p.index);
        for (int i = 0; i < n; ++i) addCopy(t_.faceVerts[b + i], true, scale / n);
        break;
    }
    }
}

void SchaeferWarrenMasks::addCentroid(const Point* c, int count, double scale) {
    if (count == 4) {
        for (int i = 0; i < 4; ++i) addPoint(c[i], true, 0.25 * scale);
    } else {
        addPoint(c[0], false, 0.25 * scale);
        addPoint(c[1], false, 0.375 * scale);
        addPoint(c[2], false, 0.375 * scale);
    }
}

int SchaeferWarrenMasks::cornerOfEdge(int f, int e) const {
    int i = 0;
    while (t_.faceEdges[t_.faceOffsets[f] + i] != e) ++i;
    return i;
}

int SchaeferWarrenMasks::cornerOfVertex(int f, int v) const {
    int i = 0;
    while (t_.faceVerts[t_.faceOffsets[f] + i] != v) ++i;
    return i;
}

int SchaeferWarrenMasks::edgeAt(int f, int corner) const {
    const int n = t_.faceSize(f);
    return t_.faceEdges[t_.faceOffsets[f] + (corner % n + n) % n];
}

// The n child quads around the centre, each weighing ½ (s = n/2).
void SchaeferWarrenMasks::facePoint(int f, double scale) {
    const int n = t_.faceSize(f);
    const Point centre{Point::Face, f};
    for (int i = 0; i < n; ++i) {
        const Point quad[4] = {centre, {Point::Edge, edgeAt(f, i - 1)},
                               {Point::Vertex, t_.faceVerts[t_.faceOffsets[f] + i]}, {Point::Edge, edgeAt(f, i)}};
        addCentroid(quad, 4, scale / n);
    }
}

// Each quad-like face gives two child quads (½ each), each triangle three child triangles (⅓
// each): s = number of faces. Next to an n-gon the child quad's corner diagonal to the midpoint
// is replaced by the n-gon's centre, which gives Catmull-Clark's edge rule there.
void SchaeferWarrenMasks::edgePoint(int e, double scale) {
    const double s = t_.edgeFaceCount(e);
    const Point mid{Point::Edge, e};
    for (int k = t_.edgeFaceOffsets[e]; k < t_.edgeFaceOffsets[e + 1]; ++k) {
        const int f = t_.edgeFaces[k], n = t_.faceSize(f), i = cornerOfEdge(f, e), b = t_.faceOffsets[f];
        const Point here{Point::Vertex, t_.faceVerts[b + i]}, next{Point::Vertex, t_.faceVerts[b + (i + 1) % n]};
        const Point prevEdge{Point::Edge, edgeAt(f, i - 1)}, nextEdge{Point::Edge, edgeAt(f, i + 1)};
        if (n == 3) {
            const Point a[3] = {mid, here, prevEdge}, c[3] = {mid, next, nextEdge}, centre[3] = {mid, nextEdge, prevEdge};
            for (const Point* tri : {a, c, centre}) addCentroid(tri, 3, scale / (3 * s));
        } else {
            const Point centre{Point::Face, f};
            const Point a[4] = {mid, here, n == 4 ? prevEdge : centre, centre};
            const Point c[4] = {mid, next, n == 4 ? nextEdge : centre, centre};
            addCentroid(a, 4, scale / (2 * s));
            addCentroid(c, 4, scale / (2 * s));
        }
    }
}

// avg over the child faces at v, then v2 = v0 + (1 + η) 2sα (avg − v0) with α = 1/(1 + nE/2 + nQ/4).
void SchaeferWarrenMasks::vertexPoint(int v, double scale) {
    const VertexFaceCounts counts = countVertexFaces(t_, v);
    const int nE = t_.vertexEdgeCount(v);
    const double s = 0.5 * counts.quads + counts.triangles / 3.0;
    const double alpha = 1.0 / (1.0 + 0.5 * nE + 0.25 * counts.quads);
    const double k = (1.0 + stamLoopEta(nE, counts.quads, counts.triangles)) * 2.0 * s * alpha;
    const Point vertex{Point::Vertex, v};
    for (int j = t_.vertFaceOffsets[v]; j < t_.vertFaceOffsets[v + 1]; ++j) {
        const int f = t_.vertFaces[j], i = cornerOfVertex(f, v);
        const Point next{Point::Edge, edgeAt(f, i)}, prev{Point::Edge, edgeAt(f, i - 1)};
        if (t_.faceSize(f) == 3) {
            const Point tri[3] = {vertex, next, prev};
            addCentroid(tri, 3, scale * k / (3 * s));
        } else {
            const Point quad[4] = {vertex, next, {Point::Face, f}, prev};
            addCentroid(quad, 4, scale * k / (2 * s));
        }
    }
    acc_.add(v, scale * (1.0 - k));
}

}  // namespace v0
}  // namespace quadtri
