// Uniform refinement of one level's topology: triangles split in 4, quads and n-gons into
// quads around their centroid. Child sharpness decays from the parent (docs/schemes/creases.md,
// §2).
#pragma once

#include <vector>

#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {

// Where the children of a parent level's components land in the child level's vertex list:
// face points of non-triangle faces first, then edge points, then vertex points.
struct ChildNumbering {
    std::vector<int> facePoint;  // per parent face, -1 for triangles
    int numFacePoints = 0;
    int numEdges = 0;
    int edgePoint(int e) const { return numFacePoints + e; }
    int vertexPoint(int v) const { return numFacePoints + numEdges + v; }
};

ChildNumbering numberChildren(const Topology& parent);

// The child level: faces (children of hole faces stay holes) and, with TopologyDetail::Full,
// connectivity and sharpness.
Topology refineTopology(const Topology& parent, const ChildNumbering& numbering, CreaseMethod creaseMethod,
                        TopologyDetail detail = TopologyDetail::Full);

}  // namespace v0
}  // namespace quadtri
