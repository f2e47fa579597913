// LimitTableUpdate (docs/edits.md, "Limit tables"): the limit masks near a changed tag, the rows
// over the control vertices that read a changed stencil of any level, composed again directly.
#include <quadtri/far/limit_table_update.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include <quadtri/far/refiner.h>

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

namespace {

void sortUnique(std::vector<int>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

std::vector<int> facesAt(const Topology& t, const std::vector<int>& vertices) {
    std::vector<int> faces;
    for (int v : vertices)
        for (int f : t.facesOfVertex(v)) faces.push_back(f);
    sortUnique(faces);
    return faces;
}

std::vector<int> verticesOf(const Topology& t, const std::vector<int>& faces) {
    std::vector<int> vertices;
    for (int f : faces)
        for (int v : t.verticesOfFace(f)) vertices.push_back(v);
    sortUnique(vertices);
    return vertices;
}

// Rows `rows` of a float table as a double one, each index mapped through `indexOf`.
template <class IndexOf>
StencilTableD rowsOf(const StencilTable& table, const std::vector<int>& rows, int numSources, IndexOf indexOf) {
    StencilTableD out;
    out.numSourceVertices = numSources;
    for (int r : rows) {
        out.offsets.push_back(int(out.indices.size()));
        out.sizes.push_back(table.size(r));
        const float* w = table.weightsOf(r);
        for (int k = 0; k < table.size(r); ++k) {
            out.indices.push_back(indexOf(table.indices[std::size_t(table.offsets[r] + k)]));
            out.weights.push_back(double(w[k]));
        }
    }
    return out;
}

// The stencils of level L's `vertices` (sorted) over the control vertices, composed in double as
// the Refiner composes them (level by level, each level's float table read as double).
StencilTableD composedRows(const Refiner& refiner, int L, const std::vector<int>& vertices) {
    const StencilTable& table = refiner.levelStencils(L);
    if (L == 1) return rowsOf(table, vertices, table.numSourceVertices, [](int s) { return s; });
    std::vector<int> sources;
    for (int r : vertices)
        sources.insert(sources.end(), table.indices.begin() + table.offsets[r],
                       table.indices.begin() + table.offsets[r + 1]);
    sortUnique(sources);
    const StencilTableD inner = composedRows(refiner, L - 1, sources);
    const StencilTableD outer = rowsOf(table, vertices, int(sources.size()), [&](int s) {
        return int(std::lower_bound(sources.begin(), sources.end(), s) - sources.begin());
    });
    return composeStencils(outer, inner);
}

}  // namespace

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

    // Per level l = 1..L, whether each vertex's stencil over the control vertices changed: its
    // own stencil did, or it reads a vertex of level l - 1 whose did.
    std::vector<std::uint8_t> composedChanges(const EditReport& report) const {
        const SchemeRules& rules = rulesOf(refiner.options().scheme);
        std::vector<std::uint8_t> changed;
        std::vector<int> list;
        for (int l = 1; l <= level; ++l) {
            const Topology& parent = refiner.level(l - 1);
            const StencilTable& table = refiner.levelStencils(l);
            std::vector<std::uint8_t> next(std::size_t(table.numStencils()), 0);
            std::vector<int> nextList = report.levels[std::size_t(l)].stencils;
            for (int c : nextList) next[std::size_t(c)] = 1;
            if (!list.empty()) {
                // Readers of a changed parent: children of the faces within the masks' reach.
                const ChildNumbering numbering = numberChildren(parent, rules.triangleSplit());
                const std::vector<int> candidates =
                    childrenOf(parent, numbering, widen(parent, facesAt(parent, list), rules.surfaceRings()));
                for (int c : candidates) {
                    if (next[std::size_t(c)]) continue;
                    for (int k = table.offsets[c]; k < table.offsets[c + 1]; ++k)
                        if (changed[std::size_t(table.indices[std::size_t(k)])]) {
                            next[std::size_t(c)] = 1;
                            nextList.push_back(c);
                            break;
                        }
                }
            }
            changed.swap(next);
            list.swap(nextList);
        }
        return changed;
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
    const std::vector<std::uint8_t> changed = s.composedChanges(report);
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
