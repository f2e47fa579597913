// LimitTableUpdate (docs/edits.md, "Limit tables"): the limit masks near a changed tag, the rows
// over the control vertices that read a changed stencil of any level, composed again directly.
#include <quadtri/far/limit_table_update.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include <quadtri/far/refiner.h>

#include "far/edit/composed_rows.h"
#include "far/edit/stencil_splice.h"
#include "far/edit/tag_changes.h"
#include "far/internal/stencil_table_double.h"
#include "far/limit/limit_eigen.h"
#include "far/limit/limit_ring.h"
#include "far/limit/limit_table.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {

using namespace internal;

struct LimitTableUpdate::State {
    const Refiner& refiner;
    int level;
    Sources sources;
    RingStarts starts;
    LimitMaskCache cache;
    LimitPoolMarks marks;
    LimitStencilTable masks;  // Sources::Control: level L's limit masks, for who reads what
    LimitPoolMarks maskMarks;

    State(const Refiner& r, int L, Sources s) : refiner(r), level(L), sources(s), starts(r.level(0)) {}

    // Level L's vertices whose limit masks can read a changed tag of level L.
    std::vector<int> masksNear(const EditedLevel& edited) const {
        const Topology& t = refiner.level(level);
        std::vector<int> seeds = edited.vertices;
        for (int e : edited.edges)
            seeds.push_back(t.edgeVerts[2 * std::size_t(e)]), seeds.push_back(t.edgeVerts[2 * std::size_t(e) + 1]);
        for (int f : edited.faces)
            for (int v : t.verticesOfFace(f)) seeds.push_back(v);
        sortUnique(seeds);
        if (seeds.empty()) return {};
        const int rings = rulesOf(refiner.options().scheme).surfaceLimitRings();
        return verticesOf(t, widen(t, facesAt(t, seeds), rings));
    }
};

LimitTableUpdate::LimitTableUpdate(const Refiner& refiner, int level, Sources sources) {
    if (level < 0 || level > refiner.maxLevel())
        throw std::logic_error("LimitTableUpdate: level " + std::to_string(level) + " outside the refined 0.." +
                               std::to_string(refiner.maxLevel()));
    refiner.level(level);  // std::logic_error for a level built with its faces only
    if (sources == Sources::Control)
        for (int l = 1; l <= level; ++l) refiner.levelStencils(l);  // std::logic_error without them
    state_ = std::make_unique<State>(refiner, level, level == 0 ? Sources::Level : sources);
    const TriangleSplit split = rulesOf(refiner.options().scheme).triangleSplit();
    for (int l = 1; l <= level; ++l) {
        const Topology& parent = refiner.level(l - 1);
        state_->starts.descend(parent, numberChildren(parent, split), refiner.level(l).numVertices);
    }
    if (state_->sources == Sources::Control) state_->masks = refiner.limitStencils(level);
}

LimitTableUpdate::~LimitTableUpdate() = default;
LimitTableUpdate::LimitTableUpdate(LimitTableUpdate&&) noexcept = default;
LimitTableUpdate& LimitTableUpdate::operator=(LimitTableUpdate&&) noexcept = default;

LimitTableChange LimitTableUpdate::update(const EditReport& report, LimitStencilTable& table) {
    State& s = *state_;
    const int N = s.level;
    if (int(report.levels.size()) <= N)
        throw std::invalid_argument("LimitTableUpdate: the report covers levels 0.." +
                                    std::to_string(int(report.levels.size()) - 1) + ", the table is of level " +
                                    std::to_string(N));
    const Topology& t = s.refiner.level(N);
    const Options& options = s.refiner.options();
    const std::vector<int> near = s.masksNear(report.levels[std::size_t(N)]);
    if (s.sources == Sources::Level) {
        if (near.empty()) return {};
        const LimitStencilTable fresh = toFloatTable(buildLimitStencilsOf(t, options, &s.starts, near, s.cache));
        LimitTableChange change;
        change.stencils = spliceLimitStencils(table, near, fresh, s.marks, &change.poolsLaidOut);
        return change;
    }

    std::vector<int> rows;
    if (!near.empty()) {
        const LimitStencilTable fresh = toFloatTable(buildLimitStencilsOf(t, options, &s.starts, near, s.cache));
        rows = spliceLimitStencils(s.masks, near, fresh, s.maskMarks);
    }
    // The masks that read a vertex whose stencil over the control vertices changed.
    const std::vector<std::uint8_t> changed = composedChanges(s.refiner, N, report);
    std::vector<int> changedList;
    for (int v = 0; v < int(changed.size()); ++v)
        if (changed[std::size_t(v)]) changedList.push_back(v);
    if (!changedList.empty()) {
        const int rings = rulesOf(options.scheme).surfaceLimitRings();
        for (int v : verticesOf(t, widen(t, facesAt(t, changedList), rings))) {
            const int* sources = s.masks.sourcesOf(v);
            for (int k = 0; k < s.masks.size(v); ++k)
                if (changed[std::size_t(sources[k])]) {
                    rows.push_back(v);
                    break;
                }
        }
    }
    sortUnique(rows);
    if (rows.empty()) return {};

    // Their masks over level L, then composed with level L's stencils over the control vertices.
    LimitStencilTableD limit = buildLimitStencilsOf(t, options, &s.starts, rows, s.cache);
    std::vector<int> sources = limit.indices;
    sortUnique(sources);
    const StencilTableD inner = composedRows(s.refiner, N, sources);
    for (int& i : limit.indices) i = int(std::lower_bound(sources.begin(), sources.end(), i) - sources.begin());
    limit.numSourceVertices = int(sources.size());
    const LimitStencilTable fresh = composeLimitStencilsToFloat(limit, inner);
    LimitTableChange change;
    change.stencils = spliceLimitStencils(table, rows, fresh, s.marks, &change.poolsLaidOut);
    return change;
}

}  // namespace v0
}  // namespace quadtri
