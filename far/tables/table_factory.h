// The tables a Refiner composes over its control data, each within a CompositionBudget:
// factorized (per-level tables composed), varying, limit and face-varying ones. The Refiner holds
// the levels; this file makes tables from them (as OpenSubdiv keeps StencilTableFactory apart
// from TopologyRefiner). docs/factorized_templates.md explains the composition.
#pragma once

#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/options.h>
#include <quadtri/far/refiner.h>
#include <quadtri/far/stencil_table.h>

#include "far/tables/composition_budget.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

class FVarChannelRefinement;

// Level L's stencils over the control vertices (L >= 1): Refiner::factorizedStencils.
StencilTable composePositionTables(const Refiner& refiner, int L, CompositionBudget& budget);
// Level L's varying stencils over level L - 1 (Refiner::varyingStencils), and over the control
// vertices (Refiner::factorizedVaryingStencils).
StencilTable varyingTable(const Refiner& refiner, int L);
StencilTable composeVaryingTables(const Refiner& refiner, int L, CompositionBudget& budget);
// A face-varying channel's level-L values over its own: Refiner::fvarFactorizedStencils.
StencilTable composeChannelTables(const FVarChannelRefinement& channel, int L, CompositionBudget& budget);

// Level L's limit stencils over its own vertices (Refiner::limitStencils) and over the control
// vertices (Refiner::factorizedLimitStencils, L >= 1).
LimitStencilTable limitTable(const Refiner& refiner, int L, CompositionBudget& budget);
LimitStencilTable composeLimitTables(const Refiner& refiner, int L, CompositionBudget& budget);
// The same for a face-varying channel's values (Refiner::fvarLimitStencils and
// Refiner::fvarFactorizedLimitStencils, L >= 1 for the latter).
LimitStencilTable channelLimitTable(const FVarChannelRefinement& channel, int L, const Options& options,
                                    CompositionBudget& budget);
LimitStencilTable composeChannelLimitTables(const FVarChannelRefinement& channel, int L, const Options& options,
                                            CompositionBudget& budget);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
