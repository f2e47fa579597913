#include "far/edit/composed_rows.h"

#include <algorithm>

#include "far/edit/tag_changes.h"
#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

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

}  // namespace

std::vector<std::uint8_t> composedChanges(const Refiner& refiner, int level, const EditReport& report) {
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

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
