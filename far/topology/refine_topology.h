// Uniform refinement of one level's topology: triangles split in 4 (or into 3 quads, as the
// scheme says), quads and n-gons into quads around their centroid. Child sharpness decays from the parent (docs/schemes/creases.md,
// §2).
#pragma once

#include <vector>

#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

// How a triangle of the parent level is split (SchemeRules::triangleSplit). Quads and n-gons
// always become quads around a face point.
enum class TriangleSplit {
    FourTriangles,  // three corner triangles and the middle one; no face point
    ThreeQuads,     // three quads around a face point, as n-gons are (Catmull-Clark)
};

// Where the children of a parent level's components land in the child level's vertex list:
// face points first (of every face that is split around one), then edge points, then vertex
// points.
struct ChildNumbering {
    std::vector<int> facePoint;  // per parent face, -1 for a triangle split in four
    int numFacePoints = 0;
    int numEdges = 0;
    TriangleSplit triangleSplit = TriangleSplit::FourTriangles;
    int edgePoint(int e) const { return numFacePoints + e; }
    int vertexPoint(int v) const { return numFacePoints + numEdges + v; }
    // Whether a face of this many corners splits into four triangles (else into quads around a
    // face point).
    bool splitsInFour(int faceSize) const { return faceSize == 3 && triangleSplit == TriangleSplit::FourTriangles; }
};

ChildNumbering numberChildren(const Topology& parent, TriangleSplit split = TriangleSplit::FourTriangles);

// The child level, split as `numbering` says: faces (children of hole faces stay holes) and,
// with TopologyDetail::Full, connectivity and sharpness.
Topology refineTopology(const Topology& parent, const ChildNumbering& numbering, CreaseMethod creaseMethod,
                        TopologyDetail detail = TopologyDetail::Full);

// The sharpness vertex v passes on: its vertex point's, and that of the halves of its edges at
// its end (docs/schemes/creases.md, §2). `scratch` is any vector, reused between calls.
void inheritSharpnessAt(const Topology& parent, const ChildNumbering& numbering, CreaseMethod creaseMethod, int v,
                        Topology& child, std::vector<float>& scratch);

// The first child face of each parent face, and their total last: a face split in four has 4,
// any other face one per corner.
std::vector<int> firstChildFaces(const Topology& parent, const ChildNumbering& numbering);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
