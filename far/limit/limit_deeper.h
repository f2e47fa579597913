// Local refinement for limit masks (docs/limit_eigen.md, "Vertices that have not settled"): a
// patch of faces around a vertex refined one level by the scheme's own masks, so that a vertex
// still near another irregularity can be followed to a level where its neighbourhood is its
// configuration's, and its masks there brought back.
#pragma once

#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "far/limit/limit_scratch.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// The faces within kPatchRings face rings of `vertex`, in the patch's own vertex numbering: what
// refining it depends on, all of it, so that two cuts with equal keys refine alike, bit for bit.
struct PatchCut {
    std::vector<int> source;      // per patch vertex: the vertex of the level it was cut from
    std::vector<int> faceSource;  // per patch face: the face of the level it was cut from
    std::vector<int> sizes, corners, creasePairs, holes, cornerVerts;
    std::vector<float> creaseWeights, cornerWeights;

    // Every array but `source`, with the options that change the refinement, into `out`.
    void key(const Options& options, std::vector<int>& out) const;
};

// A patch refined one level.
struct PatchStep {
    std::vector<int> source;  // per patch vertex: the vertex of the level it was cut from
    StencilTableD table;      // child vertices over the patch vertices
    Topology child;           // the refined patch, in full
    int descendant = -1;      // the vertex's child in `child`
};

// Wide enough that the masks of the next patch's vertices never read the patch's own rim: they
// reach two rings of the parent at most (Schaefer-Warren's copies, Butterfly's wings).
constexpr int kPatchRings = 6;

// Into `cut` (its arrays reused), in `scratch`'s working space: the faces within `rings` face
// rings of the `seeds` (patch vertices 0, 1, ... in seed order), the first ring's faces first.
// Boundary edges are cut without their sharpness: the cut's rebuild makes every boundary sharp
// again, and a cut of a refined cut would otherwise carry the first cut's rim inside as creases.
void cutPatch(const Topology& level, IndexSpan seeds, int rings, WalkScratch& scratch, PatchCut& cut);
// kPatchRings rings around one vertex.
inline void cutPatch(const Topology& level, int vertex, WalkScratch& scratch, PatchCut& cut) {
    cutPatch(level, IndexSpan(&vertex, &vertex + 1), kPatchRings, scratch, cut);
}
// The cut as the topology of a level of its own: its faces, holes and sharpness, in the cut's
// numbering (what the cut's refinement starts from).
Topology cutTopology(const PatchCut& cut, const Options& options);
PatchStep refineCut(const PatchCut& cut, const Options& options);
PatchStep refinePatch(const Topology& level, int vertex, const Options& options, WalkScratch& scratch);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
