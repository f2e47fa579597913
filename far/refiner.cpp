#include "far/refiner.h"

#include <string>

#include <tbb/parallel_invoke.h>

#include "far/refine_topology.h"
#include "far/rules.h"

namespace quadtri {

Refiner::Refiner(const TopologyDescriptor& desc, const Options& options) : options_(options) {
    levels_.push_back(buildBaseTopology(desc, options, &warnings_));
    detail_.push_back(TopologyDetail::Full);
}

std::size_t Refiner::estimateLevelBytes(int L) const {
    const Topology& p = levels_.at(L - 1);
    std::size_t faces = 0, corners = 0, entries = 0, facePoints = 0;
    for (int f = 0; f < p.numFaces(); ++f) {
        const std::size_t n = p.faceSize(f);
        faces += n == 3 ? 4 : n;
        corners += n == 3 ? 12 : 4 * n;
        facePoints += n == 3 ? 0 : 1;
        // Each face contributes its corners to its face point and to the masks of its edges'
        // and vertices' points.
        entries += n + 2 * n * n;
    }
    // A faces-only level has no edges yet: one per corner bounds them (an open mesh's count).
    const std::size_t parentEdges = p.edgeVerts.empty() ? p.faceVerts.size() : std::size_t(p.numEdges());
    const std::size_t edges = 2 * parentEdges + corners / 4;
    const std::size_t vertices = facePoints + parentEdges + p.numVertices;
    entries += 4 * parentEdges + p.numVertices;
    const std::size_t topologyBytes = corners * 16 + edges * 25 + vertices * 22 + faces * 5;
    // An index per entry and two offsets per stencil (weights are pooled), twice over: the parts
    // built by other threads are copied into the table (buildLevelStencils). Catmark-butterfly's
    // masks are larger than `entries` counts; the factor 2 covers them.
    const std::size_t tableBytes = 2 * (entries * 4 + vertices * 8);
    const std::size_t outputBytes = vertices * 3 * sizeof(float);
    return topologyBytes + tableBytes + outputBytes;
}

void Refiner::completeLevel(int L) {
    if (detail_[L] == TopologyDetail::Full) return;
    const Topology& parent = levels_[L - 1];
    levels_[L] = refineTopology(parent, numberChildren(parent), options_.creaseMethod, TopologyDetail::Full);
    detail_[L] = TopologyDetail::Full;
}

void Refiner::refineUniform(int maxLevel, TopologyDetail lastLevel) {
    if (maxLevel < 0) throw TopologyError("refinement level " + std::to_string(maxLevel) + " is negative");
    while (this->maxLevel() < maxLevel) {
        const int L = this->maxLevel() + 1;
        completeLevel(L - 1);  // within the budget level L - 1 was built under
        const std::size_t estimate = estimateLevelBytes(L);
        if (estimate > options_.memoryBudgetBytes)
            throw TopologyError("level " + std::to_string(L) + " needs an estimated " + std::to_string(estimate) +
                                " bytes of tables and output, over the budget of " +
                                std::to_string(options_.memoryBudgetBytes) + " bytes (Options::memoryBudgetBytes)");
        const Topology& parent = levels_.back();
        const ChildNumbering numbering = numberChildren(parent);
        const TopologyDetail detail = L == maxLevel ? lastLevel : TopologyDetail::Full;
        // Both read only the parent level: build them side by side.
        StencilTable table;
        Topology child;
        tbb::parallel_invoke([&] { table = buildLevelStencils<StencilTable>(parent, numbering, options_); },
                             [&] { child = refineTopology(parent, numbering, options_.creaseMethod, detail); });
        levelTables_.push_back(std::move(table));
        levels_.push_back(std::move(child));
        detail_.push_back(detail);
    }
    if (lastLevel == TopologyDetail::Full) completeLevel(maxLevel);
}

StencilTable Refiner::factorizedStencils(int L) const {
    if (L < 1 || L > maxLevel())
        throw TopologyError("factorized stencils asked for level " + std::to_string(L) + "; refined levels are 1.." +
                            std::to_string(maxLevel()));
    StencilTableD composed = toDoubleTable(levelTables_[0]);
    for (int l = 2; l <= L; ++l) composed = composeStencils(toDoubleTable(levelTables_[l - 1]), composed);
    return toFloatTable(composed);
}

}  // namespace quadtri
