// The local subdivision matrix of a vertex configuration (docs/limit_eigen.md): the faces around
// a vertex in order, which of its edges are sharp, whether its fan is open and whether it is a
// corner. The matrix is read off the scheme's own level masks on a small mesh built with that
// configuration, so that the limit and the refinement never disagree.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "far/limit/limit_scratch.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// What the local subdivision matrix of a vertex depends on once its neighbourhood has settled
// into regular sectors (docs/limit_eigen.md, "Configurations").
struct VertexConfiguration {
    Scheme scheme = Scheme::SchaeferWarren;
    BoundaryInterpolation boundary = BoundaryInterpolation::EdgeOnly;
    std::vector<uint8_t> faceSizes;  // 3 or 4, counter-clockwise from the start face
    // Ray i is the edge leaving the vertex along the first side of face i; an open fan has one
    // more ray (the last face's second side). Boundary rays are sharp by being boundaries.
    std::vector<uint8_t> sharpRays;
    bool open = false;    // a boundary vertex: the fan does not close
    bool corner = false;  // the vertex itself is sharp

    int numRays() const { return int(faceSizes.size()) + (open ? 1 : 0); }
    // One string per configuration (the cache key).
    std::string key() const;
};

// A vertex of a level read as a configuration: its faces and rays counter-clockwise from the
// start face chosen so that equal configurations start alike.
struct VertexFan {
    VertexConfiguration configuration;
    std::vector<int> faces;  // counter-clockwise, faces[0] the start face
    std::vector<int> rays;   // edges, as VertexConfiguration::sharpRays
};

// The fan of `vertex`, or nullopt where no configuration describes it: a non-manifold vertex, a
// hole or a face other than a triangle or quad around it, a triangle under a scheme that splits
// triangles into quads, a scheme other than the quad/triangle ones and the pure schemes on their
// own faces.
std::optional<VertexFan> fanOf(const Topology& topology, int vertex, const Options& options);

// The vertices of `rings` face rings around `vertex` (ring 1: the corners of its faces; ring
// j + 1: the corners of every face touching ring j), labelled by an oriented walk over the faces
// of one ring more, from `startFace` (docs/limit_eigen.md, "Ring-relative order"): two meshes
// that agree on those faces give their vertices the same labels. `signature` lists what the walk
// saw (face sizes, labels of corners, edge sharpness classes and face counts), equal exactly when
// they agree on them.
struct Neighbourhood {
    std::vector<int> vertices;  // the first `rings` rings, in label order; vertices[0] is `vertex`
    std::vector<int> signature;
};
Neighbourhood gatherNeighbourhood(const Topology& topology, int vertex, int startFace, int rings);
// The same into `out` (its arrays reused), in `scratch`'s working space: for the limit build's
// vertex after vertex. With `expected`, the walk stops at the first face where the signature
// departs from it, and returns false: the neighbourhood is not that one (`out` is then partial).
bool gatherNeighbourhood(const Topology& topology, int vertex, int startFace, int rings, WalkScratch& scratch,
                         Neighbourhood& out, const std::vector<int>* expected = nullptr);

// The local subdivision matrix S over the smallest ring neighbourhood N its masks keep closed:
// row i is the child (one level down) of N's element i, in ring-relative order, over N.
struct LocalMatrix {
    int rings = 0;              // N is this many face rings
    int size = 0;               // |N|
    std::vector<double> S;      // size x size, row-major
    std::vector<double> layout; // 2 per element: N laid out in the plane, sectors counter-clockwise
    std::vector<int> signature; // gatherNeighbourhood's, on the configuration mesh
};

// S of a configuration, growing N one ring at a time (up to kMaxLocalRings) until no child row
// reads outside it; nullopt if none is closed.
constexpr int kMaxLocalRings = 4;
std::optional<LocalMatrix> buildLocalMatrix(const VertexConfiguration& configuration, const Options& options);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
