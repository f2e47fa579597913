// Connectivity of one refinement level, as flat index arrays (structure of arrays).
#pragma once

#include <cstdint>
#include <vector>

#include <quadtri/export.h>
#include <quadtri/far/options.h>

namespace quadtri {
inline namespace v0 {

// A run of indices inside one of Topology's arrays (a face's corners, a vertex's edges): two
// pointers, so that hot loops read it as they would the raw offsets.
class IndexSpan {
public:
    IndexSpan(const int* first, const int* last) : first_(first), last_(last) {}
    const int* begin() const { return first_; }
    const int* end() const { return last_; }
    int size() const { return int(last_ - first_); }
    int operator[](int i) const { return first_[i]; }

private:
    const int* first_;
    const int* last_;
};

enum EdgeFlag : uint8_t {
    kEdgeBoundary = 1,     // exactly one incident face
    kEdgeNonManifold = 2,  // more than two faces, or two faces that traverse it the same way
    kEdgeSeam = 4,         // one triangle and one quad (or n-gon) on its two sides
};

enum VertexFlag : uint8_t {
    kVertexBoundary = 1,     // on a boundary edge
    kVertexNonManifold = 2,  // on a non-manifold edge, or its faces form more than one fan
    kVertexSeam = 4,         // on at least one seam edge
    kVertexCorner = 8,       // topological corner: one face, two edges
};

struct Topology {
    int numVertices = 0;

    // Faces: vertices of face f are faceVerts[faceOffsets[f] .. faceOffsets[f+1]).
    // faceEdges is parallel to faceVerts: entry i is the edge from faceVerts[i] to the next corner.
    std::vector<int> faceOffsets{0};
    std::vector<int> faceVerts;
    std::vector<int> faceEdges;
    std::vector<uint8_t> faceHole;

    // Edges: endpoints edgeVerts[2e], edgeVerts[2e+1]; incident faces in CSR form.
    std::vector<int> edgeVerts;
    std::vector<int> edgeFaceOffsets{0};
    std::vector<int> edgeFaces;
    std::vector<float> edgeSharpness;
    std::vector<uint8_t> edgeFlags;

    // Vertices: incident faces and edges in CSR form (unordered).
    std::vector<int> vertFaceOffsets{0};
    std::vector<int> vertFaces;
    std::vector<int> vertEdgeOffsets{0};
    std::vector<int> vertEdges;
    std::vector<float> vertSharpness;
    std::vector<uint8_t> vertFlags;

    int numFaces() const { return int(faceOffsets.size()) - 1; }
    int numEdges() const { return int(edgeVerts.size() / 2); }
    int faceSize(int f) const { return faceOffsets[f + 1] - faceOffsets[f]; }
    int edgeFaceCount(int e) const { return edgeFaceOffsets[e + 1] - edgeFaceOffsets[e]; }
    int vertexEdgeCount(int v) const { return vertEdgeOffsets[v + 1] - vertEdgeOffsets[v]; }
    int vertexFaceCount(int v) const { return vertFaceOffsets[v + 1] - vertFaceOffsets[v]; }
    // The other endpoint of edge e seen from vertex v.
    int otherVertex(int e, int v) const { return edgeVerts[2 * e] == v ? edgeVerts[2 * e + 1] : edgeVerts[2 * e]; }
    int numFaceVertices() const { return int(faceVerts.size()); }

    // Incidences as spans: a face's corners and its edges (entry i from corner i to i + 1), an
    // edge's faces, a vertex's faces and edges.
    IndexSpan verticesOfFace(int f) const { return span(faceVerts, faceOffsets, f); }
    IndexSpan edgesOfFace(int f) const { return span(faceEdges, faceOffsets, f); }
    IndexSpan facesOfEdge(int e) const { return span(edgeFaces, edgeFaceOffsets, e); }
    IndexSpan facesOfVertex(int v) const { return span(vertFaces, vertFaceOffsets, v); }
    IndexSpan edgesOfVertex(int v) const { return span(vertEdges, vertEdgeOffsets, v); }
    // Position of vertex v (edge e) among face f's corners (edges); f must hold it, as a valid
    // face holds each once.
    int cornerOfVertex(int f, int v) const { return positionIn(verticesOfFace(f), v); }
    int cornerOfEdge(int f, int e) const { return positionIn(edgesOfFace(f), e); }
    // Face f's edge from corner i to corner i + 1, i taken cyclically (i in [-n, 2n)).
    int edgeOfCorner(int f, int i) const {
        const int n = faceSize(f);
        return faceEdges[faceOffsets[f] + (i < 0 ? i + n : i >= n ? i - n : i)];
    }

private:
    static IndexSpan span(const std::vector<int>& list, const std::vector<int>& offsets, int i) {
        return {list.data() + offsets[i], list.data() + offsets[i + 1]};
    }
    static int positionIn(IndexSpan s, int x) {
        int i = 0;
        while (s[i] != x) ++i;
        return i;
    }
};

// How much of a child level to build. A level that is not refined further needs only its faces
// (to draw or write them); its edges, incidences, flags and sharpness are several times the cost.
enum class TopologyDetail {
    Full,       // faces, edges, incidences, flags and sharpness
    FacesOnly,  // numVertices, faceOffsets, faceVerts and faceHole only: Refiner::faces reads it, Refiner::level refuses it
};

// Bytes of a topology's arrays.
QUADTRI_API std::size_t bytesOf(const Topology& topology);

// Per-vertex face-type counts: incident quad-like faces (4 or more corners) and triangles.
struct VertexFaceCounts {
    int quads = 0;
    int triangles = 0;
};
QUADTRI_API VertexFaceCounts countVertexFaces(const Topology& topology, int vertex);

// Edge joining vertices a and b, or -1.
QUADTRI_API int findEdge(const Topology& topology, int a, int b);

}  // namespace v0
}  // namespace quadtri
