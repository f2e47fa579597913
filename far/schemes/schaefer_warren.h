// Schaefer-Warren's smooth rules (docs/schemes/schaefer_warren.md): unzip the tri/quad network,
// subdivide each piece linearly, then average typed centroids (a quad's centroid from quad copies,
// a triangle's ¼ x + ⅜ (other corners) from triangle copies) weighted by the angle each face spans
// in the ordinary layout (π/2, π/3). Old vertices are corrected as in Stam-Loop with v0 the
// pre-unzip position, so that away from the network the masks equal Stam-Loop's exactly, and
// the masks there are Stam-Loop's (the base class); sharp masks are the shared ones.
#pragma once

#include <cstdint>
#include <vector>

#include "far/schemes/stam_loop.h"
#include "far/internal/stencil_table_double.h"
#include "far/schemes/unzip.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// What every mask of a level reads: each vertex's copies in the unzipped pieces (rows only for
// the vertices that split) and which faces have such a vertex. Built once per level and shared,
// read-only, by the threads building its masks; empty on a level without network edges.
struct UnzippedLevel : SchemeLevel {
    // With `faces`, the copies of their vertices only, and the flags of those faces.
    explicit UnzippedLevel(const Topology& topology, const std::vector<int>* faces = nullptr);

    UnzippedCopies copies;
    std::vector<uint8_t> faceTouches;  // per face: one of its vertices splits (empty where none does)
};

class SchaeferWarrenMasks : public StamLoopMasks {
public:
    SchaeferWarrenMasks(const Topology& topology, const UnzippedLevel& unzipped, SparseAccumulator& accumulator);

    void facePoint(int face, double scale) override;
    void smoothEdgePoint(int edge, double scale) override;  // an edge with two faces
    bool regularFace(int face) const override { return !touchesFace(face); }
    bool regularEdge(int edge) const override { return !touchesEdge(edge); }
    bool regularVertex(int vertex) const override { return !touchesVertex(vertex); }

protected:
    void smoothVertexPoint(int vertex, double scale) override;  // with the η correction

private:
    // Whether a child's mask reads an unzipped copy: only then does it differ from Stam-Loop's
    // (which is cheaper to build), i.e. when a face around it has a vertex on the network.
    bool touchesFace(int face) const { return !u_.faceTouches.empty() && u_.faceTouches[face] != 0; }
    bool touchesEdge(int edge) const;
    bool touchesVertex(int vertex) const;

    // A point of the linearly subdivided mesh: a parent vertex, an edge midpoint or a face centre.
    struct Point {
        enum Kind { Vertex, Edge, Face } kind;
        int index;
    };
    // A mask's copies are gathered first, each (vertex, piece) once with its summed weight, and
    // read from the copy tables by flushCopies at the end of the mask: the child centroids around
    // a child share most of their points (an edge's midpoint is in four of its edge mask's
    // centroids), which read the same rows over and over.
    void addCopy(int vertex, bool quad, double scale);
    void flushCopies();
    void addPoint(Point p, bool quad, double scale);
    // Centroid of a child quad (4 corners) or the triangle centroid ¼ x + ⅜ (b + c) of a child
    // triangle whose first corner x is the vertex being averaged.
    void addCentroid(const Point* corners, int count, double scale);

    const UnzippedLevel& u_;
    struct Copy {
        int vertex;
        bool quad;
        double weight;
    };
    std::vector<Copy> copies_;  // the current mask's, in first-added order
};

const SchemeRules& schaeferWarrenRules();

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
