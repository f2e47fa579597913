// Building level 0 from the descriptor: validation, edges, incidences and flags.
#pragma once

#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

// Checks the descriptor (throws TopologyError naming the face or vertex) and builds level 0:
// edges, incidences, sharpness, boundary / non-manifold / seam flags, holes (including the
// faces that BoundaryInterpolation::None turns into holes). What is accepted with a change (a
// crease on a pair that is not an edge is ignored, as OpenSubdiv does) is appended to `warnings`;
// `givenHoles` gets the holes the descriptor asks for, per face of level 0.
Topology buildBaseTopology(const TopologyDescriptor& desc, const Options& options,
                           std::vector<TopologyDiagnostic>* warnings = nullptr,
                           std::vector<uint8_t>* givenHoles = nullptr);

// Throws TopologyError for malformed input; called by buildBaseTopology before anything else.
void validateDescriptor(const TopologyDescriptor& desc);

// Fills edges, incidences and flags of a topology whose numVertices, faceOffsets and faceVerts
// are set. Sharpness arrays are sized and zeroed. Used for level 0; refined levels know their
// edges and flags by construction (refine_topology.cpp).
void completeTopology(Topology& topology);

// Fills the edge-face, vertex-face and vertex-edge incidences from faceVerts, faceEdges and
// edgeVerts.
void buildIncidences(Topology& topology);

// completeTopology for a topology whose edges are given (faceEdges, edgeVerts): incidences and
// flags; sharpness arrays sized and zeroed. For a piece cut from a refined level, whose edges a
// face list cannot say (a collapsed edge's two children join the same two vertices).
void completeTopologyFromEdges(Topology& topology);

// What buildBaseTopology makes of boundaries once creases, corners and holes are set: boundary
// and non-manifold edges infinitely sharp, corners under EdgeAndCorner, non-manifold and isolated
// vertices, and the holes of BoundaryInterpolation::None.
void applyBoundaryRules(Topology& topology, const Options& options);
// The same rules item by item, for a tag `given` to one of level 0's items (an edit): the edge's
// and the vertex's sharpness, and whether the face is a hole (read after the sharpness).
float ruledEdgeSharpness(const Topology& topology, int edge, float given);
float ruledVertexSharpness(const Topology& topology, int vertex, const Options& options, float given);
bool ruledHole(const Topology& topology, int face, const Options& options, bool given);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
