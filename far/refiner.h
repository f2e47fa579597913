// The public face of the analyzer: validate a mesh, refine its topology uniformly, and emit the
// stencil tables of every level (per level) or of one level from the control vertices (factorized).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <quadtri/export.h>
#include <quadtri/far/level_faces.h>
#include <quadtri/far/level_patch_table.h>
#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/options.h>
#include <quadtri/far/stencil_table.h>
#include <quadtri/far/tag_edits.h>
#include <quadtri/far/topology.h>

namespace quadtri {
inline namespace v0 {

namespace internal {
class FVarChannelRefinement;  // far/fvar/fvar_channel.h
}

// Whether refineUniform builds the per-level stencil table of each level it refines
// (levelStencils). A caller that reads only tables over the control vertices (factorizedStencils,
// factorizedLimitStencils) asks for None: those compose from the regular faces' templates and
// make, for the call alone, the rows of the per-level tables that a stencil reads
// (docs/factorized_templates.md, "Per-level tables only where a row is read"). OpenSubdiv's
// StencilTableFactory likewise builds a factorized table without the per-level ones.
enum class LevelTables {
    Build,  // every refined level keeps its table: levelStencils(L) for any L
    None,   // the levels refined by this call keep none (face-varying channels still keep theirs)
};

class QUADTRI_API Refiner {
public:
    // Validates the descriptor (TopologyError on bad input) and builds level 0, with its
    // face-varying channels.
    Refiner(const TopologyDescriptor& desc, const Options& options);
    ~Refiner();
    Refiner(Refiner&&) noexcept;
    Refiner& operator=(Refiner&&) noexcept;

    // Refines to `maxLevel` (>= 0), building the topology and per-level stencil table of every
    // level not yet built. Throws TopologyError, before allocating, if what the Refiner holds
    // (bytes()) plus a level's estimated topology, tables and output exceed
    // options.memoryBudgetBytes; the levels built before stay usable. The last level holds only its faces
    // unless `lastLevel` asks for Full (as OpenSubdiv's fullTopologyInLastLevel); refining
    // further, or asking again with Full, completes it. With LevelTables::None the levels it
    // refines get no per-level table; asking again with Build (the default) builds the tables
    // that levels 1..maxLevel lack, each within the budget as a level is.
    void refineUniform(int maxLevel, TopologyDetail lastLevel = TopologyDetail::FacesOnly,
                       LevelTables tables = LevelTables::Build);

    int maxLevel() const { return int(levels_.size()) - 1; }
    // What the descriptor had that was accepted with a change, each naming its item (a crease on
    // a pair that is not an edge: ignored). Empty for clean input.
    const std::vector<TopologyDiagnostic>& warnings() const { return warnings_; }
    const Options& options() const { return options_; }

    // The faces of level 0 .. maxLevel(), whatever detail the level was built with.
    // Vertex order of level L >= 1: the face points of level L-1's faces that get one (every
    // face but the triangles the scheme splits in four), in face order, then one point per edge
    // (edge order), then one point per vertex (vertex order).
    LevelFaces faces(int L) const { return LevelFaces(levels_.at(L)); }

    // How much of level L was built: every level but the last is Full; the last one is what
    // refineUniform's `lastLevel` asked for.
    TopologyDetail detail(int L) const { return detail_.at(L); }

    // The full topology of level L (edges, incidences, flags, sharpness). Throws std::logic_error
    // for a level built with its faces only: read those with faces(L), or refine with
    // refineUniform(L, TopologyDetail::Full).
    const Topology& level(int L) const;

    // Stencils of level L >= 1 over the vertices of level L-1, one per vertex of level L. Throws
    // std::out_of_range for a level not refined, std::logic_error for one refined with
    // LevelTables::None (refineUniform(L) builds its table).
    const StencilTable& levelStencils(int L) const;
    // Whether level L (1 <= L <= maxLevel()) has its per-level table.
    bool hasLevelStencils(int L) const { return levelTables_.at(std::size_t(L) - 1).has_value(); }

    // Stencils of level L >= 1 over the control (level 0) vertices: the per-level tables
    // composed, accumulated in double precision. Throws TopologyError when composing them, with
    // what the Refiner holds, would pass options.memoryBudgetBytes (counting the double tables
    // being composed, the float table and a 3-float output for it), before that allocation.
    StencilTable factorizedStencils(int L) const;

    // Varying stencils of level L >= 1 over the vertices of level L-1: the same children, in the
    // same order, as levelStencils(L), each a linear interpolation of its parents (a face point is
    // its face's centroid, an edge point its edge's midpoint, a vertex point its vertex), for
    // per-vertex data that should follow the refined mesh without being smoothed (colours,
    // weights; OpenSubdiv's PrimvarRefiner::InterpolateVarying). Built on each call, in linear
    // time; docs/varying.md. Throws TopologyError for a level out of range.
    StencilTable varyingStencils(int L) const;
    // The same over the control (level 0) vertices, composed in double; the budget is kept as in
    // factorizedStencils.
    StencilTable factorizedVaryingStencils(int L) const;

    // Limit stencils of level L's vertices (0 <= L <= maxLevel()) over level L's vertices: apply
    // them to what the per-level tables (or the control data, at L = 0) produced. One stencil per
    // vertex of level L, in its vertex order: the limit position and two tangents
    // (LimitStencilTable, docs/limit.md). A level built with its faces only is completed for the
    // call and let go after it (the Refiner itself does not change; its bytes are counted in the
    // budget). Throws TopologyError for a level out of range, MemoryBudgetError when the table
    // and a 3-float output for it, with what the Refiner holds, would pass the budget.
    LimitStencilTable limitStencils(int L) const;

    // The same stencils over the control (level 0) vertices: limitStencils(L) composed with the
    // per-level tables, in double precision, rounded once. The budget is kept as in
    // factorizedStencils (the double tables being composed, the float table, a 3-float output).
    LimitStencilTable factorizedLimitStencils(int L) const;

    // Face-varying channels (TopologyDescriptor::fvarChannels), refined with the mesh by
    // refineUniform under Options::fvarLinearInterpolation (docs/face_varying.md). A channel's
    // values at level 0 are its own; at level L >= 1 they are the values its per-level tables
    // produce. Level L's faces are faces(L)'s, corner for corner: fvarValuesOfFace(c, L, f)[k] is
    // the value at faces(L).verticesOfFace(f)[k].
    int numFVarChannels() const { return int(fvar_.size()); }
    int numFVarValues(int channel, int L) const;
    IndexSpan fvarValuesOfFace(int channel, int L, int face) const;
    // Every corner's value at level L, in faces(L).vertices() order (an index buffer).
    IndexSpan fvarValues(int channel, int L) const;
    // Level L's values (L >= 1) over level L - 1's; level 1's over the channel's own values.
    // Evaluate them like levelStencils, with the channel's width (2 floats for UVs).
    const StencilTable& fvarLevelStencils(int channel, int L) const;
    // Level L's values over the channel's own: the per-level tables composed in double, the
    // memory budget kept as in factorizedStencils.
    StencilTable fvarFactorizedStencils(int channel, int L) const;

    // Limit stencils of channel c's values of level L (0 <= L <= maxLevel()) over level L's values
    // (the channel's own at L = 0): one stencil per value, in value order, the limit UV and two
    // tangents, as limitStencils gives them for positions (docs/face_varying.md, "Limit UVs").
    // The limit UVs are OpenSubdiv's LimitFaceVarying: a value that matches its vertex takes the
    // vertex's limit mask, any other the corner or the crease (seam) mask its value tag says.
    // Throws TopologyError for a channel or level out of range, MemoryBudgetError as
    // limitStencils does.
    LimitStencilTable fvarLimitStencils(int channel, int L) const;
    // The same over the channel's own values: fvarLimitStencils(c, L) composed with the channel's
    // per-level tables in double, the budget kept as in factorizedLimitStencils.
    LimitStencilTable fvarFactorizedLimitStencils(int channel, int L) const;

    // Level L's limit positions and normals from the regular patches of level K (0 <= K < L <=
    // maxLevel(), levels K+1 .. L with their per-level tables): apply it to level K's data with
    // an evaluator's EvalLevelPatches (docs/patches.md). Throws TopologyError for levels out of
    // range or without their tables.
    LevelPatchTable levelPatches(int L, int K) const;

    // Sets the sharpness of level-0 edges and vertices and the holes `edits` asks for, and
    // updates in place what the Refiner holds: every level's tags, and in each per-level table
    // the stencils within the scheme's reach of a changed tag, recomputed and put back where
    // they differ (docs/edits.md). Everything else it holds stays as it is, bit for bit; what it
    // holds then equals a Refiner built from the edited descriptor, stencil for stencil (a
    // table's weight pool may be laid out otherwise). Face-varying channels are refined again
    // from level 0. The report lists what changed, level by level, for tables built from this
    // Refiner (limit, factorized, patches) and their device copies. Throws TopologyError naming
    // the edit (its index among the creases, corners or holes) that level 0 cannot take, before
    // anything changes: a pair that is not an edge, an item out of range, a sharpness that is
    // negative or not a number.
    EditReport applyEdits(const TagEdits& edits);

    // Estimated bytes of topology, per-level table and 3-float output for refining level L-1 to L
    // (a looser bound while level L-1 holds its faces only).
    std::size_t estimateLevelBytes(int L) const;

    // Bytes the Refiner holds: every level's topology and per-level table (those built), with its
    // channels'.
    std::size_t bytes() const;

private:
    friend class LimitSurface;  // reads the face-varying channels' value meshes

    void checkRefinedLevel(const char* what, int L) const;  // TopologyError unless 1 <= L <= maxLevel()
    void completeLevel(int L);  // rebuilds a faces-only level in full
    void completeTable(int L);  // builds level L's per-level table where it has none, within the budget
    void checkLimitLevel(const char* what, int L) const;  // TopologyError unless 0 <= L <= maxLevel()
    const internal::FVarChannelRefinement& channel(int c) const;

    Options options_;
    std::vector<TopologyDiagnostic> warnings_;
    std::vector<Topology> levels_;
    std::vector<TopologyDetail> detail_;  // per level
    std::vector<std::optional<StencilTable>> levelTables_;  // per level 1..maxLevel(); none with LevelTables::None
    std::vector<std::unique_ptr<internal::FVarChannelRefinement>> fvar_;
    std::vector<std::uint8_t> givenHoles_;  // per face of level 0: a hole asked for (applyEdits)
    std::vector<std::size_t> poolMarks_;    // per level table: its pool's size when laid out (applyEdits)
};

}  // namespace v0
}  // namespace quadtri
