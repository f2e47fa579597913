#include "far/topology/refine_topology.h"

#include <algorithm>
#include <cstdint>

#include "far/schemes/crease.h"
#include "far/internal/for_each.h"
#include "far/topology/topology_builder.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

ChildNumbering numberChildren(const Topology& parent, TriangleSplit split) {
    ChildNumbering n;
    n.triangleSplit = split;
    n.facePoint.assign(parent.numFaces(), -1);
    for (int f = 0; f < parent.numFaces(); ++f)
        if (!n.splitsInFour(parent.faceSize(f))) n.facePoint[f] = n.numFacePoints++;
    n.numEdges = parent.numEdges();
    return n;
}

namespace {

// Builds the child level straight from the parent: its faces, edges, incidences and flags are
// all known by construction, so no edge search, sort or fan walk is needed, and each array is
// filled in parallel, each child item gathering from its parent's few neighbours.
//   child faces: a face split around a face point gives n quads (corner i's first), a triangle
//                split in four its 3 corners then the middle.
//   child edges: 2e and 2e+1 are the halves of parent edge e at edgeVerts[2e] and [2e+1]; then
//                each parent face's interior edges: split around a face point, j -> (edge point j,
//                centre); split in four, j -> (edge point j, edge point j+1) of the middle triangle.
// Incidence lists come out in ascending order, as the generic builder (completeTopology) makes them.
class ChildBuilder {
public:
    ChildBuilder(const Topology& parent, const ChildNumbering& numbering, Topology& child)
        : p_(parent), num_(numbering), c_(child) {
        const int nf = p_.numFaces();
        firstChildFace_.resize(std::size_t(nf) + 1);
        firstInterior_.resize(std::size_t(nf) + 1);
        firstChildFace_[0] = 0;
        firstInterior_[0] = 2 * p_.numEdges();
        for (int f = 0; f < nf; ++f) {
            const int n = p_.faceSize(f);
            firstChildFace_[f + 1] = firstChildFace_[f] + (inFour(n) ? 4 : n);
            firstInterior_[f + 1] = firstInterior_[f] + n;
        }
    }

    void build(TopologyDetail detail) {
        c_.numVertices = num_.numFacePoints + p_.numEdges() + p_.numVertices;
        if (detail == TopologyDetail::FacesOnly) return faces<false>();
        faces<true>();
        edges();
        edgeFaces();
        vertexFaces();
        vertexEdges();
        flags();
    }

private:
    int half(int e, int v) const { return 2 * e + (p_.edgeVerts[2 * e] == v ? 0 : 1); }
    // A collapsed edge (both ends v; kept only by schemes that read faces as OpenSubdiv does) has
    // two halves between the same two vertices: the corner that leaves it takes the first, the
    // corner that enters it the second (docs/schemes/catmull_clark.md).
    bool collapsed(int e) const { return p_.edgeVerts[2 * e] == p_.edgeVerts[2 * e + 1]; }
    int halfLeaving(int e, int v) const { return collapsed(e) ? 2 * e : half(e, v); }
    int halfEntering(int e, int v) const { return collapsed(e) ? 2 * e + 1 : half(e, v); }
    // The child faces at vertex v's corners, in vertFaces order. A face with a collapsed edge
    // at v is listed twice in a row, once per corner v has in it.
    void fillVertexFaces(int v, int* out) const {
        int last = -1, corner = -1;
        for (int f : p_.facesOfVertex(v)) {
            const IndexSpan corners = p_.verticesOfFace(f);
            corner = f == last ? corner + 1 : 0;
            while (corners[corner] != v) ++corner;
            last = f;
            *out++ = firstChildFace_[f] + corner;
        }
    }
    // The halves of v's edges at v, in vertEdges order; a collapsed edge is listed twice in a
    // row, once per half.
    void fillVertexHalves(int v, int* out) const {
        const IndexSpan edges = p_.edgesOfVertex(v);
        for (int i = 0; i < edges.size(); ++i)
            *out++ = i > 0 && edges[i - 1] == edges[i] ? halfEntering(edges[i], v) : halfLeaving(edges[i], v);
    }
    bool inFour(int faceSize) const { return num_.splitsInFour(faceSize); }
    // Interior edge j of face f, j in [-1, n]: wraps without a division.
    int interior(int f, int j) const {
        const int n = p_.faceSize(f);
        return firstInterior_[f] + (j < 0 ? j + n : j >= n ? j - n : j);
    }

    template <bool WithEdges>
    void faces() {
        const int nf = p_.numFaces(), numChildFaces = firstChildFace_[nf];
        // A face split around a face point makes n quads (4n child corners), a triangle split
        // in four four triangles (12): 4 child corners per parent corner either way.
        c_.faceOffsets.resize(std::size_t(numChildFaces) + 1);
        c_.faceVerts.resize(4 * p_.faceVerts.size());
        c_.faceHole.resize(numChildFaces);
        if (WithEdges) c_.faceEdges.resize(c_.faceVerts.size());
        // Read once: the stores below are ints (and bytes), which the compiler must otherwise
        // assume may change them.
        const int edgeBase = num_.numFacePoints, vertexBase = num_.numFacePoints + p_.numEdges();
        const int* facePoint = num_.facePoint.data();
        const std::uint8_t* parentHoles = p_.faceHole.data();
        std::uint8_t* holes = c_.faceHole.data();  // all 0 as sized: only holes' children are written
        const bool anyHole = std::any_of(p_.faceHole.begin(), p_.faceHole.end(), [](std::uint8_t h) { return h != 0; });
        forEach(nf, [&](int f) {
            const IndexSpan corners = p_.verticesOfFace(f), sides = p_.edgesOfFace(f);
            const int n = corners.size(), first = firstChildFace_[f], next = firstChildFace_[f + 1];
            const bool four = inFour(n);
            int* offsets = c_.faceOffsets.data() + first;
            const int corner = 4 * p_.faceOffsets[f];
            int* verts = c_.faceVerts.data() + corner;
            int* edges = WithEdges ? c_.faceEdges.data() + corner : nullptr;
            // The edge is computed only when kept (a faces-only level skips the lookups).
            auto put = [&](int k, int vertex, auto edge) {
                verts[k] = vertex;
                if constexpr (WithEdges) edges[k] = edge();
            };
            int k = 0;
            for (int i = 0, last = n - 1; i < n; last = i++) {  // corner i's child keeps the parent's orientation
                const int v = corners[i], e = sides[i], prev = sides[last];
                offsets[i] = corner + k;
                put(k++, vertexBase + v, [&] { return halfLeaving(e, v); });
                if (four) {
                    put(k++, edgeBase + e, [&] { return interior(f, last); });
                } else {
                    put(k++, edgeBase + e, [&] { return interior(f, i); });
                    put(k++, facePoint[f], [&] { return interior(f, last); });
                }
                put(k++, edgeBase + prev, [&] { return halfEntering(prev, v); });
            }
            if (four) {
                offsets[3] = corner + k;
                for (int i = 0; i < 3; ++i) put(k++, edgeBase + sides[i], [&] { return interior(f, i); });
            }
            if (anyHole && parentHoles[f])
                for (int i = first; i < next; ++i) holes[i] = parentHoles[f];
        });
        c_.faceOffsets[numChildFaces] = int(c_.faceVerts.size());
    }

    void edges() {
        const int ne = p_.numEdges();
        c_.edgeVerts.resize(2 * std::size_t(firstInterior_.back()));
        forEach(ne, [&](int e) {
            const int ep = num_.edgePoint(e);
            c_.edgeVerts[4 * std::size_t(e) + 0] = num_.vertexPoint(p_.edgeVerts[2 * e]);
            c_.edgeVerts[4 * std::size_t(e) + 1] = ep;
            c_.edgeVerts[4 * std::size_t(e) + 2] = ep;
            c_.edgeVerts[4 * std::size_t(e) + 3] = num_.vertexPoint(p_.edgeVerts[2 * e + 1]);
        });
        forEach(p_.numFaces(), [&](int f) {
            const IndexSpan sides = p_.edgesOfFace(f);
            const int n = sides.size();
            for (int j = 0; j < n; ++j) {
                const std::size_t k = interior(f, j);
                c_.edgeVerts[2 * k] = num_.edgePoint(sides[j]);
                c_.edgeVerts[2 * k + 1] = inFour(n) ? num_.edgePoint(sides[j == 2 ? 0 : j + 1]) : num_.facePoint[f];
            }
        });
    }

    // Halves: one child face per parent face of the edge, the one at the half's end. Interior
    // edges: the two child faces beside them.
    void edgeFaces() {
        const int ne = p_.numEdges(), nf = p_.numFaces(), numChildEdges = c_.numEdges();
        c_.edgeFaceOffsets.resize(std::size_t(numChildEdges) + 1);
        const int interiorBase = 2 * int(p_.edgeFaces.size());
        forEach(ne, [&](int e) {
            const int b = p_.edgeFaceOffsets[e], n = p_.edgeFaceCount(e);
            c_.edgeFaceOffsets[2 * e] = 2 * b;
            c_.edgeFaceOffsets[2 * e + 1] = 2 * b + n;
        });
        forEach(numChildEdges - 2 * ne, [&](int k) { c_.edgeFaceOffsets[2 * ne + k] = interiorBase + 2 * k; });
        c_.edgeFaceOffsets[numChildEdges] = interiorBase + 2 * (numChildEdges - 2 * ne);
        c_.edgeFaces.resize(c_.edgeFaceOffsets[numChildEdges]);
        forEach(ne, [&](int e) {
            int* out = c_.edgeFaces.data() + c_.edgeFaceOffsets[2 * e];
            const int n = p_.edgeFaceCount(e), a = p_.edgeVerts[2 * e];
            for (int i = 0; i < n; ++i) {
                const int f = p_.facesOfEdge(e)[i], fn = p_.faceSize(f), j = p_.cornerOfEdge(f, e);
                // The edge runs from corner j to corner j+1 of f.
                const bool aFirst = p_.verticesOfFace(f)[j] == a;
                const int next = j + 1 == fn ? 0 : j + 1;
                out[i] = firstChildFace_[f] + (aFirst ? j : next);
                out[n + i] = firstChildFace_[f] + (aFirst ? next : j);
            }
        });
        forEach(nf, [&](int f) {
            const int n = p_.faceSize(f), first = firstChildFace_[f];
            for (int j = 0; j < n; ++j) {
                int* out = c_.edgeFaces.data() + c_.edgeFaceOffsets[interior(f, j)];
                // Around a face point: between child faces j and j+1; in four: corner face j+1
                // and the middle.
                const int next = j + 1 == n ? 0 : j + 1;
                const bool four = inFour(n);
                const int x = four ? next : j, y = four ? 3 : next;
                out[0] = first + std::min(x, y);
                out[1] = first + std::max(x, y);
            }
        });
    }

    // Child vertex order: face points, edge points, vertex points (ChildNumbering).
    template <typename Count, typename Fill>
    void incidence(std::vector<int>& offsets, std::vector<int>& list, const Count& count, const Fill& fill) {
        const int nv = c_.numVertices;
        offsets.resize(std::size_t(nv) + 1);
        offsets[0] = 0;
        forEach(nv, [&](int v) { offsets[v + 1] = count(v); });
        for (int v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
        list.resize(offsets[nv]);
        forEach(nv, [&](int v) { fill(v, list.data() + offsets[v]); });
    }

    // Which parent component child vertex v stands for.
    enum class Kind { Face, Edge, Vertex };
    Kind kindOf(int v, int& index) const {
        if (v < num_.numFacePoints) {
            index = faceOfPoint_[v];
            return Kind::Face;
        }
        if (v < num_.numFacePoints + p_.numEdges()) {
            index = v - num_.numFacePoints;
            return Kind::Edge;
        }
        index = v - num_.numFacePoints - p_.numEdges();
        return Kind::Vertex;
    }

    void vertexFaces() {
        faceOfPoint_.resize(num_.numFacePoints);
        for (int f = 0; f < p_.numFaces(); ++f)
            if (num_.facePoint[f] >= 0) faceOfPoint_[num_.facePoint[f]] = f;
        auto count = [&](int v) {
            int i;
            switch (kindOf(v, i)) {
            case Kind::Face: return p_.faceSize(i);
            case Kind::Vertex: return p_.vertexFaceCount(i);
            case Kind::Edge: break;
            }
            int total = 0;
            for (int f : p_.facesOfEdge(i)) total += inFour(p_.faceSize(f)) ? 3 : 2;
            return total;
        };
        auto fill = [&](int v, int* out) {
            int i;
            switch (kindOf(v, i)) {
            case Kind::Face:
                for (int j = 0; j < p_.faceSize(i); ++j) out[j] = firstChildFace_[i] + j;
                return;
            case Kind::Vertex:
                fillVertexFaces(i, out);
                return;
            case Kind::Edge: break;
            }
            // Edge point of edge j of f: corner faces j and j+1, and the middle of a triangle split
            // in four.
            for (int f : p_.facesOfEdge(i)) {
                const int n = p_.faceSize(f), j = p_.cornerOfEdge(f, i), first = firstChildFace_[f];
                const int next = j + 1 == n ? 0 : j + 1;
                *out++ = first + std::min(j, next);
                *out++ = first + std::max(j, next);
                if (inFour(n)) *out++ = first + 3;
            }
        };
        incidence(c_.vertFaceOffsets, c_.vertFaces, count, fill);
    }

    void vertexEdges() {
        auto count = [&](int v) {
            int i;
            switch (kindOf(v, i)) {
            case Kind::Face: return p_.faceSize(i);
            case Kind::Vertex: return p_.vertexEdgeCount(i);
            case Kind::Edge: break;
            }
            int total = 2;
            for (int f : p_.facesOfEdge(i)) total += inFour(p_.faceSize(f)) ? 2 : 1;
            return total;
        };
        auto fill = [&](int v, int* out) {
            int i;
            switch (kindOf(v, i)) {
            case Kind::Face:
                for (int j = 0; j < p_.faceSize(i); ++j) out[j] = firstInterior_[i] + j;
                return;
            case Kind::Vertex:
                fillVertexHalves(i, out);
                return;
            case Kind::Edge: break;
            }
            // Edge point: both halves, then per face the interior edges ending at it (split
            // around a face point, edge j -> interior j; in four, -> interiors j-1 and j).
            *out++ = 2 * i;
            *out++ = 2 * i + 1;
            for (int f : p_.facesOfEdge(i)) {
                const int j = p_.cornerOfEdge(f, i);
                if (!inFour(p_.faceSize(f))) {
                    *out++ = interior(f, j);
                    continue;
                }
                const int a = interior(f, j - 1), b = interior(f, j);
                *out++ = std::min(a, b);
                *out++ = std::max(a, b);
            }
        };
        incidence(c_.vertEdgeOffsets, c_.vertEdges, count, fill);
    }

    // Halves of a parent edge keep its boundary / non-manifold / seam flags; interior edges have
    // two faces of one parent: none. Vertex points keep their parent's flags, edge points take
    // their edge's, face points none. When triangles split into quads every child is a quad, so
    // no seam is left.
    void flags() {
        c_.edgeFlags.assign(c_.numEdges(), 0);
        c_.vertFlags.assign(c_.numVertices, 0);
        const bool seamsStay = num_.triangleSplit == TriangleSplit::FourTriangles;
        const uint8_t edgeKept = seamsStay ? 0xff : uint8_t(~kEdgeSeam);
        const uint8_t vertexKept = seamsStay ? 0xff : uint8_t(~kVertexSeam);
        forEach(p_.numEdges(), [&](int e) {
            const uint8_t f = p_.edgeFlags[e] & edgeKept;
            c_.edgeFlags[2 * e] = c_.edgeFlags[2 * e + 1] = f;
            c_.vertFlags[num_.edgePoint(e)] = (f & kEdgeBoundary ? kVertexBoundary : 0) |
                                              (f & kEdgeNonManifold ? kVertexNonManifold : 0) |
                                              (f & kEdgeSeam ? kVertexSeam : 0);
        });
        forEach(p_.numVertices, [&](int v) { c_.vertFlags[num_.vertexPoint(v)] = p_.vertFlags[v] & vertexKept; });
        c_.edgeSharpness.assign(c_.numEdges(), 0.0f);
        c_.vertSharpness.assign(c_.numVertices, 0.0f);
    }

    const Topology& p_;
    const ChildNumbering& num_;
    Topology& c_;
    std::vector<int> firstChildFace_;  // first child face of each parent face (+ total)
    std::vector<int> firstInterior_;   // first interior child edge of each parent face (+ total)
    std::vector<int> faceOfPoint_;     // parent face of each face point
};

}  // namespace

std::vector<int> firstChildFaces(const Topology& p, const ChildNumbering& num) {
    std::vector<int> first(std::size_t(p.numFaces()) + 1, 0);
    for (int f = 0; f < p.numFaces(); ++f) {
        const int n = p.faceSize(f);
        first[std::size_t(f) + 1] = first[std::size_t(f)] + (num.splitsInFour(n) ? 4 : n);
    }
    return first;
}

void inheritSharpnessAt(const Topology& p, const ChildNumbering& num, CreaseMethod method, int v, Topology& c,
                        std::vector<float>& scratch) {
    c.vertSharpness[num.vertexPoint(v)] = decrementSharpness(p.vertSharpness[v]);
    const int n = p.vertexEdgeCount(v);
    scratch.resize(n);
    childEdgeSharpnessAtVertex(p, v, method, scratch.data());
    const IndexSpan edges = p.edgesOfVertex(v);
    for (int i = 0; i < n; ++i) {
        // A collapsed edge is listed twice in a row: its first half, then its second.
        const int e = edges[i];
        const bool second = p.edgeVerts[2 * e] != v || (i > 0 && edges[i - 1] == e);
        c.edgeSharpness[2 * e + (second ? 1 : 0)] = scratch[i];
    }
}

namespace {

void inheritSharpness(const Topology& p, const ChildNumbering& num, CreaseMethod method, Topology& c) {
    std::vector<float> scratch;
    for (int v = 0; v < p.numVertices; ++v) inheritSharpnessAt(p, num, method, v, c, scratch);
}

}  // namespace

Topology refineTopology(const Topology& parent, const ChildNumbering& numbering, CreaseMethod creaseMethod,
                        TopologyDetail detail) {
    Topology child;
    ChildBuilder(parent, numbering, child).build(detail);
    // A level without sharpness passes none on: the child's arrays are already zero.
    if (detail == TopologyDetail::Full && hasSharpness(parent)) inheritSharpness(parent, numbering, creaseMethod, child);
    return child;
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
