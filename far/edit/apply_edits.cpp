// Refiner::applyEdits (docs/edits.md): level by level, the tags passed on from the level above,
// and the per-level table's stencils near a changed tag recomputed and spliced in.
#include <quadtri/far/refiner.h>
#include <quadtri/far/tag_edits.h>

#include "far/edit/stencil_splice.h"
#include "far/edit/tag_changes.h"
#include "far/fvar/fvar_channel.h"
#include "far/schemes/scheme.h"
#include "far/tables/level_stencils.h"

namespace quadtri {
inline namespace v0 {

using namespace internal;

void TagEdits::setCrease(int a, int b, float sharpness) {
    creaseVertexPairs.push_back(a);
    creaseVertexPairs.push_back(b);
    creaseWeights.push_back(sharpness);
}

void TagEdits::setCorner(int vertex, float sharpness) {
    cornerVertices.push_back(vertex);
    cornerWeights.push_back(sharpness);
}

void TagEdits::setHole(int face, bool hole) {
    holeFaces.push_back(face);
    holeFlags.push_back(hole ? 1 : 0);
}

void TagEdits::clear() { *this = TagEdits(); }

namespace {

void report(const ChangedTags& changed, EditedLevel& level) {
    level.edges = changed.edges;
    level.vertices = changed.vertices;
    level.faces = changed.faces;
}

}  // namespace

EditReport Refiner::applyEdits(const TagEdits& edits) {
    checkEdits(levels_[0], edits);
    EditReport out;
    out.levels.resize(std::size_t(maxLevel()) + 1);
    ChangedTags changed = applyToLevel0(levels_[0], edits, options_, givenHoles_);
    report(changed, out.levels[0]);
    const SchemeRules& rules = rulesOf(options_.scheme);
    poolMarks_.resize(levelTables_.size(), 0);
    for (int L = 1; L <= maxLevel(); ++L) {
        if (changed.edges.empty() && changed.vertices.empty() && changed.faces.empty()) break;
        const Topology& parent = levels_[std::size_t(L) - 1];
        const ChildNumbering numbering = numberChildren(parent, rules.triangleSplit());
        std::optional<StencilTable>& table = levelTables_[std::size_t(L) - 1];
        EditedLevel& level = out.levels[std::size_t(L)];
        if (table && changed.sharpness() && rules.usesSharpness()) {
            // The children that can read a changed tag, and the faces their masks read.
            const std::vector<int> region = facesNear(parent, changed, rules.surfaceRings());
            const std::vector<int> children = childrenOf(parent, numbering, region);
            const std::vector<int> read = widen(parent, region, rules.surfaceRings());
            const StencilTable fresh = buildChildStencils<StencilTable>(parent, numbering, options_, children, read);
            std::size_t& mark = poolMarks_[std::size_t(L) - 1];
            if (mark == 0) mark = table->weights.size();
            Splice splice = spliceStencils(*table, children, fresh, mark);
            level.recomputedStencils = int(children.size());
            level.stencils = std::move(splice.changed);
            level.tableResized = splice.resized;
            level.poolLaidOut = splice.poolLaidOut;
        }
        changed = passOn(parent, numbering, changed, options_.creaseMethod, levels_[std::size_t(L)]);
        report(changed, level);
    }
    if (!fvar_.empty() && out.changed()) {
        for (const auto& c : fvar_) {
            c->restart(levels_[0], options_);
            for (int L = 1; L <= maxLevel(); ++L)
                c->refine(levels_[std::size_t(L) - 1], levels_[std::size_t(L)], options_);
        }
        out.faceVaryingRebuilt = true;
    }
    return out;
}

}  // namespace v0
}  // namespace quadtri
