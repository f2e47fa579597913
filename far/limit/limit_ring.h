// Ordering a vertex's neighbourhood for its limit masks (docs/limit.md, "Ring order").
#pragma once

#include <vector>

#include "far/schemes/crease.h"
#include "far/limit/limit_mask.h"
#include "far/topology/refine_topology.h"
#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

// Fills `ring` for vertex v of a level with full topology. An interior manifold vertex's ring
// starts at `startFace` (one of its faces; -1: its lowest-numbered face), a boundary one at the
// face whose leaving edge is a boundary edge.
void orderVertexRing(const Topology& level, int v, int startFace, VertexRing& ring);

// The rule a limit mask follows at a vertex of the level asked for: from the level's own
// sharpness, a semi-sharp vertex or edge counting as sharp, as OpenSubdiv's Limit does
// (docs/limit.md, "Semi-sharp features").
VertexRule limitRule(const Topology& level, const VertexRing& ring);

// Where each vertex's ring starts, level by level as OpenSubdiv lists a child's faces: at level
// 0 its lowest-numbered face; below, inherited from the parent component. Also tracks each
// edge's first face, which the edge points of the next level inherit.
class RingStarts {
public:
    explicit RingStarts(const Topology& level0);
    // From `parent`'s starts to those of its children (`childVertices` of them).
    void descend(const Topology& parent, const ChildNumbering& numbering, int childVertices);
    int startFace(int v) const { return vertexStart_[v]; }

private:
    std::vector<int> vertexStart_;  // per vertex of the current level, -1 without faces
    std::vector<int> edgeFirst_;    // per edge of the current level
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
