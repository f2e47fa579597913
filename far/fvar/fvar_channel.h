// One face-varying channel refined with its mesh (docs/face_varying.md). The channel is read as
// a mesh of its own, the value mesh: the mesh's faces with every corner's vertex replaced by the
// pair (mesh vertex, value), so that where neighbouring faces disagree on a value the value mesh
// has a boundary (a seam). It is refined with the mesh's scheme and rules, level by level; its
// faces are the mesh's faces in the same order, so level L's corners line up with the mesh's.
// Which value-vertices are sharp (kept linear) follows OpenSubdiv's value tags under
// Options::fvarLinearInterpolation; their kind is tracked per level.
#pragma once

#include <cstdint>
#include <vector>

#include <quadtri/far/options.h>
#include <quadtri/far/stencil_table.h>
#include <quadtri/far/topology.h>
#include "far/limit/limit_table.h"
#include "far/topology/refine_topology.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

class SchemeRules;

// How a value-vertex is interpolated (OpenSubdiv's value tags, docs/face_varying.md).
enum class FVarKind : uint8_t {
    Match,        // the value's topology is the vertex's: the mesh's own rule
    Corner,       // kept where it is (infinitely sharp)
    Crease,       // a smooth boundary of the channel: the crease rule along its seam
    SemiSharp,    // a corner until the sharpness inside its faces has decayed (the value mesh's own rule)
    Dependent,    // a corner for as long as the other value of its vertex is semi-sharp
    Released,     // a dependent value whose other value became a crease: a crease from now on
};

class FVarChannelRefinement {
public:
    // Level 0 of `channel` over the mesh's level 0 (`mesh`, built from `desc` under `options`).
    // A face that repeats a vertex is the mesh's loops (face_loops.h), with the values of the
    // input corners its kept corners come from.
    FVarChannelRefinement(const TopologyDescriptor& desc, int channel, const Topology& mesh, const Options& options);

    // Level L = maxLevel() + 1 from level L - 1: `meshParent` is the mesh's level L - 1 (full
    // topology), `meshChild` its level L (faces at least).
    void refine(const Topology& meshParent, const Topology& meshChild, const Options& options);

    // Level 0 again, its tags read anew from the mesh's level 0 (`mesh`, edited since): the
    // levels refined are let go (Refiner::applyEdits refines them again).
    void restart(const Topology& mesh, const Options& options);

    int maxLevel() const { return int(levels_.size()) - 1; }
    // Values of level L: the channel's own at L = 0, the value mesh's vertices after.
    int numValues(int L) const { return L == 0 ? numControlValues_ : levels_.at(L).values.numVertices; }
    // Face f's value per corner at level L (the channel's value indices at L = 0).
    IndexSpan valuesOfFace(int L, int f) const;
    // Every corner's value at level L, in faces(L)'s corner order.
    IndexSpan valuesOfLevel(int L) const;
    // Level L's values over level L - 1's (L >= 1; level 1 over the channel's own values).
    const StencilTable& levelStencils(int L) const { return tables_.at(L - 1); }
    std::size_t bytes() const;
    // Bytes of level L's value mesh (what limitMesh copies).
    std::size_t valueMeshBytes(int L) const { return bytesOf(levels_.at(L).values); }

    // Limit stencils (far/fvar/fvar_limit.cpp, docs/face_varying.md "Limit UVs"). limitMesh(L) is level
    // L's value mesh with the sharpness OpenSubdiv's limit reads from the value tags: every value
    // kept as a corner there (corners, semi-sharp and dependent values) infinitely sharp, creases
    // not sharp. limitStencils builds the value mesh's limit masks on it, one stencil per value of
    // level L, over level L's values (the channel's own at L = 0).
    Topology limitMesh(int L, const Options& options) const;
    LimitStencilTableD limitStencils(int L, const Topology& limitMesh, const Options& options) const;

    // Level 0's value mesh with the sharpness LimitSurface's local refinement starts from
    // (docs/surface.md, "Face-varying values"): as refinement reads it, a dependent value kept as
    // a corner. valueOfVertex()[p] is the channel's value at its vertex p.
    Topology surfaceMesh() const;
    const std::vector<int>& valueOfVertex() const { return controlValueOf_; }

    // What refining the last level once more would allocate at least (SchemeRules'
    // estimate over the value mesh).
    std::size_t estimateNextLevelBytes(const SchemeRules& rules) const;

private:
    struct Level {
        Topology values;               // the value mesh
        std::vector<int> meshVertex;   // per value-vertex
        std::vector<int> meshEdge;     // per value-edge
        std::vector<FVarKind> kind;    // per value-vertex
        std::vector<int> partner;      // per value-vertex: the other value of a Dependent one, else -1
        std::vector<uint8_t> edgeTags; // per value-edge: kSplit, kLinear
    };
    static constexpr uint8_t kSplit = 1;   // the mesh edge's faces disagree on a value at an end
    static constexpr uint8_t kLinear = 2;  // a boundary edge kept linear (FVarLinearInterpolation::Boundaries)

    void tagLevel0(const Topology& mesh, const Options& options);
    void sharpen(Level& level, const Options& options) const;
    std::vector<float> meshChildEdgeSharpness(const Level& parent, const Topology& meshParent, const Options& options) const;
    std::vector<FVarKind> childKinds(const Level& parent, const Topology& meshParent, const ChildNumbering& num,
                                     const Options& options) const;

    int numControlValues_ = 0;
    std::vector<int> controlValues_;     // per corner of level 0: the channel's value index
    std::vector<int> controlValueOf_;    // per value-vertex of level 0: its value index
    std::vector<Level> levels_;
    std::vector<StencilTable> tables_;
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
