#include "far/refine_topology.h"

#include "far/crease.h"

namespace quadtri {

ChildNumbering numberChildren(const Topology& parent) {
    ChildNumbering n;
    n.facePoint.assign(parent.numFaces(), -1);
    for (int f = 0; f < parent.numFaces(); ++f)
        if (parent.faceSize(f) != 3) n.facePoint[f] = n.numFacePoints++;
    n.numEdges = parent.numEdges();
    return n;
}

namespace {

// Builds the child level straight from the parent: its faces, edges, flags and sharpness are all
// known by construction, so no edge search or fan walk is needed.
//   child edges: 2e and 2e+1 are the halves of parent edge e at edgeVerts[2e] and [2e+1]; then
//                each parent face's interior edges: quad-like face j -> (edge point j, centre),
//                triangle j -> (edge point j, edge point j+1) of the middle triangle.
//   child faces: a quad-like face's n quads (corner order), a triangle's 3 corners then middle.
class ChildBuilder {
public:
    ChildBuilder(const Topology& parent, const ChildNumbering& numbering, Topology& child)
        : p_(parent), num_(numbering), c_(child), firstInterior_(parent.numFaces() + 1) {
        firstInterior_[0] = 2 * p_.numEdges();
        for (int f = 0; f < p_.numFaces(); ++f) firstInterior_[f + 1] = firstInterior_[f] + p_.faceSize(f);
    }

    void build() {
        c_.numVertices = num_.numFacePoints + p_.numEdges() + p_.numVertices;
        faces();
        edges();
        buildIncidences(c_);
        flags();
    }

private:
    int half(int e, int v) const { return 2 * e + (p_.edgeVerts[2 * e] == v ? 0 : 1); }
    int interior(int f, int j) const {
        const int n = p_.faceSize(f);
        return firstInterior_[f] + (j + n) % n;
    }

    void corner(int vertex, int edge) {
        c_.faceVerts.push_back(vertex);
        c_.faceEdges.push_back(edge);
    }

    void faces() {
        std::size_t childFaces = 0, childCorners = 0;
        for (int f = 0; f < p_.numFaces(); ++f) {
            const std::size_t n = p_.faceSize(f);
            childFaces += n == 3 ? 4 : n;
            childCorners += n == 3 ? 12 : 4 * n;
        }
        c_.faceOffsets.assign(1, 0);
        c_.faceOffsets.reserve(childFaces + 1);
        c_.faceVerts.reserve(childCorners);
        c_.faceEdges.reserve(childCorners);
        c_.faceHole.reserve(childFaces);
        for (int f = 0; f < p_.numFaces(); ++f) {
            const int b = p_.faceOffsets[f], n = p_.faceSize(f);
            for (int i = 0; i < n; ++i) {  // corner i's child keeps the parent's orientation
                const int v = p_.faceVerts[b + i], e = p_.faceEdges[b + i], prev = p_.faceEdges[b + (i + n - 1) % n];
                corner(num_.vertexPoint(v), half(e, v));
                if (n == 3) {
                    corner(num_.edgePoint(e), interior(f, i - 1));
                } else {
                    corner(num_.edgePoint(e), interior(f, i));
                    corner(num_.facePoint[f], interior(f, i - 1));
                }
                corner(num_.edgePoint(prev), half(prev, v));
                close(f);
            }
            if (n == 3) {
                for (int i = 0; i < 3; ++i) corner(num_.edgePoint(p_.faceEdges[b + i]), interior(f, i));
                close(f);
            }
        }
    }

    void close(int parentFace) {
        c_.faceOffsets.push_back(int(c_.faceVerts.size()));
        c_.faceHole.push_back(p_.faceHole[parentFace]);
    }

    void edges() {
        c_.edgeVerts.resize(2 * std::size_t(firstInterior_.back()));
        for (int e = 0; e < p_.numEdges(); ++e) {
            const int ep = num_.edgePoint(e);
            c_.edgeVerts[4 * e + 0] = num_.vertexPoint(p_.edgeVerts[2 * e]);
            c_.edgeVerts[4 * e + 1] = ep;
            c_.edgeVerts[4 * e + 2] = ep;
            c_.edgeVerts[4 * e + 3] = num_.vertexPoint(p_.edgeVerts[2 * e + 1]);
        }
        for (int f = 0; f < p_.numFaces(); ++f) {
            const int b = p_.faceOffsets[f], n = p_.faceSize(f);
            for (int j = 0; j < n; ++j) {
                const int k = interior(f, j);
                c_.edgeVerts[2 * k] = num_.edgePoint(p_.faceEdges[b + j]);
                c_.edgeVerts[2 * k + 1] = n == 3 ? num_.edgePoint(p_.faceEdges[b + (j + 1) % 3]) : num_.facePoint[f];
            }
        }
    }

    // Halves of a parent edge keep its boundary / non-manifold / seam flags; interior edges have
    // two faces of one parent: none. Vertex points keep their parent's flags, edge points take
    // their edge's, face points none.
    void flags() {
        c_.edgeFlags.assign(c_.numEdges(), 0);
        for (int e = 0; e < p_.numEdges(); ++e) c_.edgeFlags[2 * e] = c_.edgeFlags[2 * e + 1] = p_.edgeFlags[e];
        c_.vertFlags.assign(c_.numVertices, 0);
        for (int e = 0; e < p_.numEdges(); ++e) {
            const uint8_t f = p_.edgeFlags[e];
            c_.vertFlags[num_.edgePoint(e)] = (f & kEdgeBoundary ? kVertexBoundary : 0) |
                                              (f & kEdgeNonManifold ? kVertexNonManifold : 0) |
                                              (f & kEdgeSeam ? kVertexSeam : 0);
        }
        for (int v = 0; v < p_.numVertices; ++v) c_.vertFlags[num_.vertexPoint(v)] = p_.vertFlags[v];
        c_.edgeSharpness.assign(c_.numEdges(), 0.0f);
        c_.vertSharpness.assign(c_.numVertices, 0.0f);
    }

    const Topology& p_;
    const ChildNumbering& num_;
    Topology& c_;
    std::vector<int> firstInterior_;  // first interior child edge of each parent face
};

// Halves of parent edges inherit decayed sharpness (Chaikin per end); interior edges are smooth.
// Vertex points inherit uniformly decayed vertex sharpness.
void inheritSharpness(const Topology& p, const ChildNumbering& num, CreaseMethod method, Topology& c) {
    std::vector<float> childSharpness;
    for (int v = 0; v < p.numVertices; ++v) {
        c.vertSharpness[num.vertexPoint(v)] = decrementSharpness(p.vertSharpness[v]);
        const int n = p.vertexEdgeCount(v);
        childSharpness.resize(n);
        childEdgeSharpnessAtVertex(p, v, method, childSharpness.data());
        for (int i = 0; i < n; ++i) {
            const int e = p.vertEdges[p.vertEdgeOffsets[v] + i];
            c.edgeSharpness[2 * e + (p.edgeVerts[2 * e] == v ? 0 : 1)] = childSharpness[i];
        }
    }
}

}  // namespace

Topology refineTopology(const Topology& parent, const ChildNumbering& numbering, CreaseMethod creaseMethod) {
    Topology child;
    ChildBuilder(parent, numbering, child).build();
    inheritSharpness(parent, numbering, creaseMethod, child);
    return child;
}

}  // namespace quadtri
