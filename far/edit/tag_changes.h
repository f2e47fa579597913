// Which tags an edit changes, level by level, and which children's masks can read them
// (docs/edits.md, "The region").
#pragma once

#include <cstdint>
#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/tag_edits.h>
#include <quadtri/far/topology.h>
#include "far/topology/refine_topology.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// Items of one level whose tags changed, each list sorted.
struct ChangedTags {
    std::vector<int> edges, vertices, faces;
    bool sharpness() const { return !edges.empty() || !vertices.empty(); }
};

// Throws TopologyError naming the first item of `edits` that level 0 cannot take (a pair that is
// not an edge, a vertex or face out of range, a sharpness that is negative or not a number).
void checkEdits(const Topology& level0, const TagEdits& edits);

// Sets the edits' tags on level 0 under the boundary rules (topology_builder.h), `givenHoles`
// (the holes asked for, per face) with them; returns what changed.
ChangedTags applyToLevel0(Topology& level0, const TagEdits& edits, const Options& options,
                          std::vector<std::uint8_t>& givenHoles);

// Passes the parent's changes on to the child level (its sharpness where it has any, its holes):
// returns the child's changes.
ChangedTags passOn(const Topology& parent, const ChildNumbering& numbering, const ChangedTags& changed,
                   CreaseMethod creaseMethod, Topology& child);

// `v` sorted, each value once.
void sortUnique(std::vector<int>& v);
// The faces at `vertices`, and the vertices of `faces`, sorted.
std::vector<int> facesAt(const Topology& level, const std::vector<int>& vertices);
std::vector<int> verticesOf(const Topology& level, const std::vector<int>& faces);

// The faces within `rings` face rings of a changed edge or vertex (ring 0: the faces at their
// vertices), sorted. With the scheme's SchemeRules::surfaceRings(), the faces whose children's
// masks can read a changed tag: a face's children read nothing beyond that many rings of it.
std::vector<int> facesNear(const Topology& parent, const ChangedTags& changed, int rings);
// `faces` (sorted) and every face within `rings` rings of them, sorted.
std::vector<int> widen(const Topology& parent, const std::vector<int>& faces, int rings);
// The children of `faces` (their face points, edge points and vertex points), sorted.
std::vector<int> childrenOf(const Topology& parent, const ChildNumbering& numbering, const std::vector<int>& faces);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
