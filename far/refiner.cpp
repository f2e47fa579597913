#include <quadtri/far/refiner.h>

#include <stdexcept>
#include <string>

#include <tbb/parallel_invoke.h>

#include "far/internal/level_estimate.h"
#include "far/internal/refine_topology.h"
#include "far/internal/rules.h"
#include "far/internal/scheme.h"
#include "far/internal/stencil_table_double.h"
#include "far/internal/topology_builder.h"

namespace quadtri {
inline namespace v0 {

Refiner::Refiner(const TopologyDescriptor& desc, const Options& options) : options_(options) {
    levels_.push_back(buildBaseTopology(desc, options, &warnings_));
    detail_.push_back(TopologyDetail::Full);
}

const Topology& Refiner::level(int L) const {
    const Topology& topology = levels_.at(L);
    if (detail_[L] == TopologyDetail::FacesOnly)
        throw std::logic_error("level " + std::to_string(L) + " holds its faces only: read them with faces(" +
                               std::to_string(L) + "), or refine with refineUniform(" + std::to_string(L) +
                               ", TopologyDetail::Full) for its edges and incidences");
    return topology;
}

std::size_t Refiner::estimateLevelBytes(int L) const {
    return quadtri::estimateLevelBytes(levels_.at(L - 1), rulesOf(options_.scheme));
}

std::size_t Refiner::bytes() const {
    std::size_t total = 0;
    for (const Topology& t : levels_) total += bytesOf(t);
    for (const StencilTable& t : levelTables_) total += t.bytes();
    return total;
}

namespace {

// Bytes of a float table converted to a double one (toDoubleTable).
std::size_t doubleBytes(const StencilTable& t) {
    return std::size_t(2 * t.numStencils()) * sizeof(int) + t.numEntries() * (sizeof(int) + sizeof(double));
}

}  // namespace

void Refiner::completeLevel(int L) {
    if (detail_[L] == TopologyDetail::Full) return;
    const Topology& parent = levels_[L - 1];
    levels_[L] = refineTopology(parent, numberChildren(parent, rulesOf(options_.scheme).triangleSplit()),
                                options_.creaseMethod, TopologyDetail::Full);
    detail_[L] = TopologyDetail::Full;
}

void Refiner::refineUniform(int maxLevel, TopologyDetail lastLevel) {
    if (maxLevel < 0) throw TopologyError("refinement level " + std::to_string(maxLevel) + " is negative");
    while (this->maxLevel() < maxLevel) {
        const int L = this->maxLevel() + 1;
        completeLevel(L - 1);  // within the budget level L - 1 was built under
        const std::size_t estimate = estimateLevelBytes(L), held = bytes();
        if (held > options_.memoryBudgetBytes || estimate > options_.memoryBudgetBytes - held)
            throw MemoryBudgetError("level " + std::to_string(L), held + estimate, held, options_.memoryBudgetBytes);
        const Topology& parent = levels_.back();
        const ChildNumbering numbering = numberChildren(parent, rulesOf(options_.scheme).triangleSplit());
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
    const std::size_t budget = options_.memoryBudgetBytes, held = bytes();
    std::size_t used = 0;  // bytes of the double tables alive at this point
    auto refuse = [&](std::size_t needed) {
        return MemoryBudgetError("the factorized stencils of level " + std::to_string(L), needed, held, budget);
    };
    auto reserve = [&](std::size_t more) {
        if (held > budget || used > budget - held || more > budget - held - used) throw refuse(held + used + more);
        used += more;
    };
    reserve(doubleBytes(levelTables_[0]));
    StencilTableD composed = toDoubleTable(levelTables_[0]);
    for (int l = 2; l <= L; ++l) {
        reserve(doubleBytes(levelTables_[l - 1]));
        const StencilTableD outer = toDoubleTable(levelTables_[l - 1]);
        try {
            StencilTableD next = composeStencils(outer, composed, budget - held - used);
            used -= doubleBytes(levelTables_[l - 1]);
            used += bytesOf(next) - bytesOf(composed);
            composed = std::move(next);
        } catch (const std::length_error&) {
            throw refuse(budget + 1);  // composition stopped at the budget: more, by how much is unknown
        }
    }
    // The float table (an index per entry, two ints per stencil, a weight pool of at most one
    // float per entry) and a 3-float output per stencil, while the double table still lives.
    const std::size_t n = composed.sizes.size(), entries = composed.indices.size();
    reserve(entries * (sizeof(int) + sizeof(float)) + n * (2 * sizeof(int) + 3 * sizeof(float)));
    return toFloatTable(composed);
}

}  // namespace v0
}  // namespace quadtri
