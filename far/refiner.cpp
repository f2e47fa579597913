#include <quadtri/far/refiner.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>


#include "far/fvar/fvar_channel.h"
#include "far/surface/level_patch_builder.h"
#include "far/schemes/scheme.h"
#include "far/tables/level_stencils.h"
#include "far/tables/table_factory.h"
#include "far/topology/level_estimate.h"
#include "far/topology/refine_topology.h"
#include "far/topology/topology_builder.h"
#include "far/internal/parallel.h"

namespace quadtri {
inline namespace v0 {

using namespace internal;

Refiner::Refiner(const TopologyDescriptor& desc, const Options& options) : options_(options) {
    levels_.push_back(buildBaseTopology(desc, options, &warnings_, &givenHoles_));
    detail_.push_back(TopologyDetail::Full);
    for (int c = 0; c < desc.numFVarChannels; ++c)
        fvar_.push_back(std::make_unique<FVarChannelRefinement>(desc, c, levels_[0], options_));
}

Refiner::~Refiner() = default;
Refiner::Refiner(Refiner&&) noexcept = default;
Refiner& Refiner::operator=(Refiner&&) noexcept = default;

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
    for (const std::optional<StencilTable>& t : levelTables_)
        if (t) total += t->bytes();
    for (const auto& c : fvar_) total += c->bytes();
    return total;
}

void Refiner::completeLevel(int L) {
    if (detail_[L] == TopologyDetail::Full) return;
    const Topology& parent = levels_[L - 1];
    levels_[L] = refineTopology(parent, numberChildren(parent, rulesOf(options_.scheme).triangleSplit()),
                                options_.creaseMethod, TopologyDetail::Full);
    detail_[L] = TopologyDetail::Full;
}

const StencilTable& Refiner::levelStencils(int L) const {
    const std::optional<StencilTable>& table = levelTables_.at(std::size_t(L) - 1);
    if (!table)
        throw std::logic_error("level " + std::to_string(L) + " was refined without its per-level table " +
                               "(LevelTables::None): refineUniform(" + std::to_string(L) + ") builds it");
    return *table;
}

void Refiner::completeTable(int L) {
    if (levelTables_[std::size_t(L) - 1]) return;
    const std::size_t estimate = estimateLevelBytes(L), held = bytes();  // the level's bound, its topology included
    if (held > options_.memoryBudgetBytes || estimate > options_.memoryBudgetBytes - held)
        throw MemoryBudgetError("the stencil table of level " + std::to_string(L), held + estimate, held,
                                options_.memoryBudgetBytes);
    const Topology& parent = levels_[std::size_t(L) - 1];  // below the last level: full
    levelTables_[std::size_t(L) - 1] = buildLevelStencils<StencilTable>(
        parent, numberChildren(parent, rulesOf(options_.scheme).triangleSplit()), options_);
}

void Refiner::refineUniform(int maxLevel, TopologyDetail lastLevel, LevelTables tables) {
    if (maxLevel < 0) throw TopologyError("refinement level " + std::to_string(maxLevel) + " is negative");
    while (this->maxLevel() < maxLevel) {
        const int L = this->maxLevel() + 1;
        completeLevel(L - 1);  // within the budget level L - 1 was built under
        std::size_t estimate = estimateLevelBytes(L);
        for (const auto& c : fvar_) estimate += c->estimateNextLevelBytes(rulesOf(options_.scheme));
        const std::size_t held = bytes();
        if (held > options_.memoryBudgetBytes || estimate > options_.memoryBudgetBytes - held)
            throw MemoryBudgetError("level " + std::to_string(L), held + estimate, held, options_.memoryBudgetBytes);
        const Topology& parent = levels_.back();
        const ChildNumbering numbering = numberChildren(parent, rulesOf(options_.scheme).triangleSplit());
        const TopologyDetail detail = L == maxLevel ? lastLevel : TopologyDetail::Full;
        // Both read only the parent level: build them side by side.
        std::optional<StencilTable> table;
        Topology child;
        if (tables == LevelTables::Build)
            parallel::invoke([&] { table = buildLevelStencils<StencilTable>(parent, numbering, options_); },
                                 [&] { child = refineTopology(parent, numbering, options_.creaseMethod, detail); });
        else
            child = refineTopology(parent, numbering, options_.creaseMethod, detail);
        levelTables_.push_back(std::move(table));
        levels_.push_back(std::move(child));
        detail_.push_back(detail);
        for (const auto& c : fvar_) c->refine(levels_[L - 1], levels_[L], options_);
    }
    if (tables == LevelTables::Build)
        for (int L = 1; L <= maxLevel; ++L) completeTable(L);
    if (lastLevel == TopologyDetail::Full) completeLevel(maxLevel);
}

StencilTable Refiner::factorizedStencils(int L) const {
    checkRefinedLevel("factorized stencils", L);
    CompositionBudget budget("the factorized stencils of level " + std::to_string(L), bytes(),
                             options_.memoryBudgetBytes);
    return composePositionTables(*this, L, budget);
}

void Refiner::checkRefinedLevel(const char* what, int L) const {
    if (L < 1 || L > maxLevel())
        throw TopologyError(std::string(what) + " asked for level " + std::to_string(L) + "; refined levels are 1.." +
                            std::to_string(maxLevel()));
}

StencilTable Refiner::varyingStencils(int L) const {
    checkRefinedLevel("varying stencils", L);
    return varyingTable(*this, L);
}

StencilTable Refiner::factorizedVaryingStencils(int L) const {
    checkRefinedLevel("factorized varying stencils", L);
    CompositionBudget budget("the factorized varying stencils of level " + std::to_string(L), bytes(),
                             options_.memoryBudgetBytes);
    return composeVaryingTables(*this, L, budget);
}

const FVarChannelRefinement& Refiner::channel(int c) const {
    if (c < 0 || c >= numFVarChannels())
        throw TopologyError("face-varying channel " + std::to_string(c) + " asked for; the mesh has " +
                            std::to_string(numFVarChannels()));
    return *fvar_[std::size_t(c)];
}

int Refiner::numFVarValues(int c, int L) const {
    if (L < 0 || L > maxLevel())
        throw TopologyError("face-varying values asked for level " + std::to_string(L) + "; refined levels are 0.." +
                            std::to_string(maxLevel()));
    return channel(c).numValues(L);
}

IndexSpan Refiner::fvarValuesOfFace(int c, int L, int face) const {
    const FVarChannelRefinement& ch = channel(c);
    if (L < 0 || L > maxLevel() || face < 0 || face >= levels_[std::size_t(L)].numFaces())
        throw TopologyError("face-varying values asked for face " + std::to_string(face) + " of level " +
                            std::to_string(L));
    return ch.valuesOfFace(L, face);
}

IndexSpan Refiner::fvarValues(int c, int L) const {
    const FVarChannelRefinement& ch = channel(c);
    if (L < 0 || L > maxLevel())
        throw TopologyError("face-varying values asked for level " + std::to_string(L) + "; refined levels are 0.." +
                            std::to_string(maxLevel()));
    return ch.valuesOfLevel(L);
}

const StencilTable& Refiner::fvarLevelStencils(int c, int L) const {
    const FVarChannelRefinement& ch = channel(c);
    checkRefinedLevel("face-varying stencils", L);
    return ch.levelStencils(L);
}

StencilTable Refiner::fvarFactorizedStencils(int c, int L) const {
    const FVarChannelRefinement& ch = channel(c);
    checkRefinedLevel("factorized face-varying stencils", L);
    CompositionBudget budget("the factorized stencils of face-varying channel " + std::to_string(c) + " at level " +
                                 std::to_string(L),
                             bytes(), options_.memoryBudgetBytes);
    return composeChannelTables(ch, L, budget);
}

void Refiner::checkLimitLevel(const char* what, int L) const {
    if (L < 0 || L > maxLevel())
        throw TopologyError(std::string(what) + " asked for level " + std::to_string(L) + "; refined levels are 0.." +
                            std::to_string(maxLevel()));
}

LimitStencilTable Refiner::limitStencils(int L) const {
    checkLimitLevel("limit stencils", L);
    CompositionBudget budget("the limit stencils of level " + std::to_string(L), bytes(), options_.memoryBudgetBytes);
    return limitTable(*this, L, budget);
}

LimitStencilTable Refiner::factorizedLimitStencils(int L) const {
    checkLimitLevel("limit stencils", L);
    if (L == 0) return limitStencils(0);
    CompositionBudget budget("the factorized limit stencils of level " + std::to_string(L), bytes(),
                             options_.memoryBudgetBytes);
    return composeLimitTables(*this, L, budget);
}

LevelPatchTable Refiner::levelPatches(int L, int K) const { return buildLevelPatchTable(*this, L, K); }

LimitStencilTable Refiner::fvarLimitStencils(int c, int L) const {
    const FVarChannelRefinement& ch = channel(c);
    checkLimitLevel("face-varying limit stencils", L);
    CompositionBudget budget("the limit stencils of face-varying channel " + std::to_string(c) + " at level " +
                                 std::to_string(L),
                             bytes(), options_.memoryBudgetBytes);
    return channelLimitTable(ch, L, options_, budget);
}

LimitStencilTable Refiner::fvarFactorizedLimitStencils(int c, int L) const {
    const FVarChannelRefinement& ch = channel(c);
    checkLimitLevel("face-varying limit stencils", L);
    if (L == 0) return fvarLimitStencils(c, 0);
    CompositionBudget budget("the factorized limit stencils of face-varying channel " + std::to_string(c) +
                                 " at level " + std::to_string(L),
                             bytes(), options_.memoryBudgetBytes);
    return composeChannelLimitTables(ch, L, options_, budget);
}

}  // namespace v0
}  // namespace quadtri
