#include "far/tables/table_factory.h"

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "far/fvar/fvar_channel.h"
#include "far/internal/stencil_table_double.h"
#include "far/limit/limit_ring.h"
#include "far/limit/limit_table.h"
#include "far/schemes/scheme.h"
#include "far/tables/level_stencils.h"
#include "far/tables/regular_patches.h"
#include "far/tables/varying_table.h"
#include "far/topology/refine_topology.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

// Bytes of a float table converted to a double one (toDoubleTable).
std::size_t doubleBytes(const StencilTable& t) {
    return std::size_t(2 * t.numStencils()) * sizeof(int) + t.numEntries() * (sizeof(int) + sizeof(double));
}

// The per-level tables a composition reads: table(l, budget) makes level l's over level l-1 in
// double; outer(l, known, budget) is level l's table as the composition of level l reads it,
// `known` its templated stencils (the stored float table, read as its double copy would be, where
// there is one); levelOneUnder(known, budget) is level 1's as level 2's composition reads it
// (`known`: level 2's templated stencils); bytes(l) is what level l's double copy takes, reserved
// before level l is composed whether or not it is made, so that what the budget refuses does not
// depend on which way the table is read.
struct PositionLevels {
    explicit PositionLevels(const Refiner& r) : refiner(r) {}
    const Refiner& refiner;
    // The children of regular control faces are written from templates (regular_patches.h).
    std::unique_ptr<RegularPatches> patches(int L) const {
        return L >= 2 ? std::make_unique<RegularPatches>(refiner, L) : nullptr;
    }
    StencilTableD table(int l, CompositionBudget& budget) const {
        const StencilTable& levelTable = outer(l, nullptr, budget);
        if (!refiner.hasLevelStencils(l)) budget.reserve(doubleBytes(levelTable));  // bytes(l) counted none for it
        return toDoubleTable(levelTable);
    }
    // A level refined without its table (LevelTables::None) has it made here for this
    // composition, with the rows that are read only: the stencils of level l that no template
    // gives; under level 2, the level-1 stencils that those of level 2 read.
    const StencilTable& outer(int l, const KnownStencils* known, CompositionBudget& budget) const {
        if (refiner.hasLevelStencils(l)) return refiner.levelStencils(l);
        if (!known) return made(l, nullptr, budget);
        std::vector<std::uint8_t> wanted(std::size_t(refiner.faces(l).numVertices()));
        for (std::size_t i = 0; i < wanted.size(); ++i) wanted[i] = known->face[i] < 0;
        return made(l, &wanted, budget);
    }
    const StencilTable& levelOneUnder(const KnownStencils* known, CompositionBudget& budget) const {
        if (refiner.hasLevelStencils(1)) return refiner.levelStencils(1);
        if (!known) return made(1, nullptr, budget);
        const StencilTable& two = outer(2, known, budget);  // kept from level 2's own read
        std::vector<std::uint8_t> wanted(std::size_t(refiner.faces(1).numVertices()));
        for (int i = 0; i < two.numStencils(); ++i)
            if (known->face[i] < 0)
                for (int k = two.offsets[i]; k < two.offsets[i + 1]; ++k) wanted[std::size_t(two.indices[k])] = 1;
        return made(1, &wanted, budget);
    }
    std::size_t bytes(int l) const { return refiner.hasLevelStencils(l) ? doubleBytes(refiner.levelStencils(l)) : 0; }

private:
    // Level l's table with the rows `wanted` flags (all where null), made once per composition and
    // kept until it ends, its bytes reserved in `budget`. Where no row is wanted, a table of the
    // level's stencils with no entries (read for its stencil count only).
    const StencilTable& made(int l, const std::vector<std::uint8_t>* wanted, CompositionBudget& budget) const {
        const auto found = made_.find(l);
        if (found != made_.end()) return found->second;
        StencilTable& table = made_[l];
        const Topology& parent = refiner.level(l - 1);  // below the last level: full
        if (wanted && std::find(wanted->begin(), wanted->end(), 1) == wanted->end()) {
            table.numSourceVertices = parent.numVertices;
            table.offsets.assign(wanted->size() + 1, 0);
            table.weightOffsets.assign(wanted->size(), 0);
        } else {
            const std::size_t estimate = refiner.estimateLevelBytes(l);  // the level's bound, its topology included
            budget.reserve(estimate);
            table = buildLevelStencils<StencilTable>(
                parent, numberChildren(parent, rulesOf(refiner.options().scheme).triangleSplit()), refiner.options(),
                nullptr, wanted);
            budget.release(estimate);
        }
        budget.reserve(table.bytes());
        return table;
    }
    mutable std::map<int, StencilTable> made_;  // by level (a map: references to it stay valid)
};

struct ChannelLevels {
    const FVarChannelRefinement& channel;
    std::unique_ptr<RegularPatches> patches(int) const { return nullptr; }
    StencilTableD table(int l, CompositionBudget&) const { return toDoubleTable(channel.levelStencils(l)); }
    const StencilTable& outer(int l, const KnownStencils*, CompositionBudget&) const { return channel.levelStencils(l); }
    const StencilTable& levelOneUnder(const KnownStencils*, CompositionBudget&) const { return channel.levelStencils(1); }
    std::size_t bytes(int l) const { return doubleBytes(channel.levelStencils(l)); }
};

// Varying tables (a level below maxLevel() always has full topology).
struct VaryingLevels {
    const Refiner& refiner;
    std::unique_ptr<RegularPatches> patches(int) const { return nullptr; }
    ChildNumbering numbering(int l) const {
        const Topology& parent = refiner.level(l - 1);
        return numberChildren(parent, rulesOf(refiner.options().scheme).triangleSplit());
    }
    StencilTableD table(int l) const { return buildVaryingStencils(refiner.level(l - 1), numbering(l)); }
    StencilTableD table(int l, CompositionBudget&) const { return table(l); }
    StencilTableD outer(int l, const KnownStencils*, CompositionBudget&) const { return table(l); }
    StencilTableD levelOneUnder(const KnownStencils*, CompositionBudget&) const { return table(1); }
    std::size_t bytes(int l) const { return varyingStencilBytes(refiner.level(l - 1), numbering(l)); }
};

// What `patches` knows of the next level (null without patches), its bytes reserved in `budget`
// in place of the last level's.
const KnownStencils* descend(RegularPatches* patches, CompositionBudget& budget) {
    if (!patches) return nullptr;
    budget.release(patches->bytes());
    const KnownStencils& known = patches->descend();
    budget.reserve(patches->bytes());
    return &known;
}

// Whether `Levels` stores level 1 as a float table (positions, face-varying channels): the
// composition then reads it where it is, with no double copy.
template <class Levels>
constexpr bool kStoresLevelOne =
    std::is_same_v<decltype(std::declval<const Levels&>().outer(1, nullptr, std::declval<CompositionBudget&>())),
                   const StencilTable&>;

// Tables of levels 1..L composed in double, over the control vertices; `patches` (if not null,
// made for at least L levels) gives the stencils it knows. Those of levels 2..L-1 are left out of
// their tables and read from their templates by the composition below them; with `leftOut`,
// level L's too, and *leftOut is what the returned table then lacks (null where it lacks
// nothing), valid until patches descends twice more.
template <class Levels>
StencilTableD composeLevelTables(int L, CompositionBudget& budget, const Levels& levels, RegularPatches* patches,
                                 const KnownStencils** leftOut = nullptr) {
    StencilTableD composed;
    const KnownStencils* innerKnown = nullptr;  // left out of `composed`
    // Level l over innerOf(level l's templated stencils) (of innerBytes in the budget: 0 for a
    // table the Refiner holds).
    auto compose = [&](int l, auto innerOf, std::size_t innerBytes) {
        budget.reserve(levels.bytes(l));
        try {
            const KnownStencils* known = descend(patches, budget);
            const auto& outer = levels.outer(l, known, budget);  // a reference, or a table kept for this step
            const auto& inner = innerOf(known);
            const bool leaveOut = known && (l < L || leftOut);
            StencilTableD next = composeStencils(outer, inner, budget.left(), {known, innerKnown, leaveOut});
            budget.release(levels.bytes(l) + innerBytes);
            budget.reserve(bytesOf(next));
            composed = std::move(next);
            innerKnown = leaveOut ? known : nullptr;
        } catch (const std::length_error&) {
            throw budget.refuse(budget.budget() + 1);  // composition stopped at the budget: more, by how much is unknown
        }
    };
    descend(patches, budget);  // level 1 is its own table
    int l = 2;
    if (kStoresLevelOne<Levels> && L >= 2) {
        // Level 2 straight over level 1's stored table.
        compose(l++, [&](const KnownStencils* known) -> decltype(auto) { return levels.levelOneUnder(known, budget); }, 0);
    } else {
        budget.reserve(levels.bytes(1));
        composed = levels.table(1, budget);
    }
    for (; l <= L; ++l)
        compose(l, [&](const KnownStencils*) -> const StencilTableD& { return composed; }, bytesOf(composed));
    if (leftOut) *leftOut = innerKnown;
    return composed;
}

template <class Levels>
StencilTableD composeLevelTables(int L, CompositionBudget& budget, const Levels& levels) {
    const std::unique_ptr<RegularPatches> patches = levels.patches(L);
    if (patches) budget.reserve(patches->bytes());
    return composeLevelTables(L, budget, levels, patches.get());
}

// Bytes of a float table of n stencils and `entries` entries (an index per entry, two ints per
// stencil, a weight pool of at most one float per entry) and of a 3-float output for it.
std::size_t floatTableBytes(std::size_t n, std::size_t entries) {
    return entries * (sizeof(int) + sizeof(float)) + n * (2 * sizeof(int) + 3 * sizeof(float));
}

// The float table of a composed one, its bytes and output reserved while the double table still
// lives.
StencilTable toFloatWithin(const StencilTableD& composed, CompositionBudget& budget) {
    budget.reserve(floatTableBytes(composed.sizes.size(), composed.indices.size()));
    return toFloatTable(composed);
}

// Level 1 over the control vertices is level 1's own table. A stored float table is copied: its
// double copy rounded back gives the same floats, only at the cost of pooling them again (as long
// as the level's build, for a level-1 factorized table).
template <class Levels>
StencilTable levelOneWithin(CompositionBudget& budget, const Levels& levels) {
    if constexpr (kStoresLevelOne<Levels>) {
        const StencilTable& stored = levels.outer(1, nullptr, budget);
        budget.reserve(floatTableBytes(std::size_t(stored.numStencils()), stored.numEntries()));
        return stored;
    } else {
        return toFloatWithin(composeLevelTables(1, budget, levels), budget);
    }
}

// The tables of levels 1..L composed as composeLevelTables does, stored as float: level L is
// composed over levels 1..L-1 straight into the float table. The budget is kept as for that
// table's double form rounded by toFloatWithin, so that what is refused, and what the refusal
// says, stay the same.
template <class Levels>
StencilTable composeLevelTablesToFloat(int L, CompositionBudget& budget, const Levels& levels) {
    if (L == 1) return levelOneWithin(budget, levels);
    const std::unique_ptr<RegularPatches> patches = levels.patches(L);
    if (patches) budget.reserve(patches->bytes());
    // Level L over innerOf(level L's templated stencils) (of innerBytes in the budget: 0 for a
    // table the Refiner holds).
    auto compose = [&](auto innerOf, const KnownStencils* innerKnown, std::size_t innerBytes) {
        budget.reserve(levels.bytes(L));
        StencilTable composed;
        try {
            const KnownStencils* known = descend(patches.get(), budget);
            const auto& outer = levels.outer(L, known, budget);  // before the inner table: levelOneUnder reads it
            composed = composeStencilsToFloat(outer, innerOf(known), budget.left(), {known, innerKnown});
        } catch (const std::length_error&) {
            throw budget.refuse(budget.budget() + 1);
        }
        budget.release(levels.bytes(L) + innerBytes);
        return composed;
    };
    StencilTable composed;
    if (kStoresLevelOne<Levels> && L == 2) {
        descend(patches.get(), budget);  // level 1 is its own table
        // Level 2 straight over level 1's stored table.
        composed = compose(
            [&](const KnownStencils* known) -> decltype(auto) { return levels.levelOneUnder(known, budget); }, nullptr, 0);
    } else {
        const KnownStencils* innerKnown = nullptr;
        const StencilTableD inner = composeLevelTables(L - 1, budget, levels, patches.get(), &innerKnown);
        composed = compose([&](const KnownStencils*) -> const StencilTableD& { return inner; }, innerKnown,
                           bytesOf(inner));
    }
    budget.reserve(doubleBytes(composed));
    budget.reserve(floatTableBytes(std::size_t(composed.numStencils()), composed.numEntries()));
    return composed;
}

// Entries of the limit stencils of a level: at most the vertex, its edge neighbours and its
// faces' opposite corners.
std::size_t limitEntryBound(const Topology& t) { return t.numVertices + t.vertEdges.size() + t.vertFaces.size(); }

// Bytes of a float limit table of n stencils and `entries` entries (pools of at most an index
// and three floats per entry, three ints per stencil), of the two pools' hash slots (about one
// of three ints per stencil each) and of a 3-float output per stencil.
std::size_t floatLimitBytes(std::size_t n, std::size_t entries) {
    return entries * (sizeof(int) + 3 * sizeof(float)) + n * (3 * sizeof(int) + 2 * 3 * sizeof(int) + 3 * sizeof(float));
}

// What a limit table holds in the budget: a double one its arrays; a float one as
// floatLimitBytes counts it (its entries as if unpooled, with a 3-float output).
std::size_t tableBytes(const LimitStencilTableD& table) { return bytesOf(table); }
std::size_t tableBytes(const LimitStencilTable& table) {
    return floatLimitBytes(std::size_t(table.numStencils()), table.numEntries());
}

// Level L's limit stencils as build(level L's topology, its ring starts) makes them (in double, or
// straight to float), what they allocate reserved in `budget`. A faces-only level is completed
// for this call only.
template <class Build>
auto limitStencilsOf(const Refiner& refiner, int L, CompositionBudget& budget, Build build) {
    const TriangleSplit split = rulesOf(refiner.options().scheme).triangleSplit();
    Topology completed;
    const Topology* topology = nullptr;
    std::size_t completion = 0;  // bytes reserved for the completed level, freed on return
    if (refiner.detail(L) == TopologyDetail::Full) {
        topology = &refiner.level(L);
    } else {
        completion = refiner.estimateLevelBytes(L);
        budget.reserve(completion);
        const Topology& parent = refiner.level(L - 1);
        completed = refineTopology(parent, numberChildren(parent, split), refiner.options().creaseMethod,
                                   TopologyDetail::Full);
        topology = &completed;
    }
    RingStarts starts(refiner.level(0));
    for (int l = 1; l <= L; ++l) {
        const Topology& parent = refiner.level(l - 1);
        starts.descend(parent, numberChildren(parent, split), l == L ? topology->numVertices : refiner.level(l).numVertices);
    }
    const std::size_t bound = limitEntryBound(*topology) * (sizeof(int) + 3 * sizeof(double)) +
                              std::size_t(topology->numVertices) * 2 * sizeof(int);
    budget.reserve(bound);
    auto table = build(*topology, starts);
    // What stays alive is the table itself: the completed level goes, and the bound was an upper
    // one (the composition that follows gets what it leaves).
    budget.release(completion + bound);
    budget.reserve(tableBytes(table));
    return table;
}

// Level L's limit stencils of a face-varying channel in double, what they allocate reserved in
// `budget`: the value mesh copied with its limit sharpness, the table (twice at level 0, where it
// is re-expressed over the channel's own values).
LimitStencilTableD fvarLimitStencilsOf(const FVarChannelRefinement& channel, int L, const Options& options,
                                       CompositionBudget& budget) {
    const std::size_t copy = channel.valueMeshBytes(L);
    budget.reserve(copy);
    const Topology mesh = channel.limitMesh(L, options);
    const std::size_t bound = (L == 0 ? 2 : 1) * (limitEntryBound(mesh) * (sizeof(int) + 3 * sizeof(double)) +
                                                  std::size_t(mesh.numVertices) * 2 * sizeof(int));
    budget.reserve(bound);
    LimitStencilTableD table = channel.limitStencils(L, mesh, options);
    budget.release(copy + bound);
    budget.reserve(bytesOf(table));
    return table;
}

// A limit table (limitOf()) composed with the tables below it (levelsOf()), straight into the
// float table, each made and freed within `budget`.
template <class Limit, class Levels>
LimitStencilTable composeLimitWithin(CompositionBudget& budget, Limit limitOf, Levels levelsOf) {
    LimitStencilTable composed;
    {
        const LimitStencilTableD limit = limitOf();
        const StencilTableD levels = levelsOf();
        try {
            composed = composeLimitStencilsToFloat(limit, levels, budget.left());
        } catch (const std::length_error&) {
            throw budget.refuse(budget.budget() + 1);
        }
        budget.release(bytesOf(limit) + bytesOf(levels));  // both freed at the end of this block
    }
    budget.reserve(floatLimitBytes(std::size_t(composed.numStencils()), composed.numEntries()));
    return composed;
}

}  // namespace

StencilTable composePositionTables(const Refiner& refiner, int L, CompositionBudget& budget) {
    return composeLevelTablesToFloat(L, budget, PositionLevels(refiner));
}

StencilTable varyingTable(const Refiner& refiner, int L) { return toFloatTable(VaryingLevels{refiner}.table(L)); }

StencilTable composeVaryingTables(const Refiner& refiner, int L, CompositionBudget& budget) {
    return composeLevelTablesToFloat(L, budget, VaryingLevels{refiner});
}

StencilTable composeChannelTables(const FVarChannelRefinement& channel, int L, CompositionBudget& budget) {
    return composeLevelTablesToFloat(L, budget, ChannelLevels{channel});
}

LimitStencilTable limitTable(const Refiner& refiner, int L, CompositionBudget& budget) {
    // Straight to float: the bound reserved for the double table covers the float one.
    return limitStencilsOf(refiner, L, budget, [&](const Topology& level, const RingStarts& starts) {
        return buildLimitStencilsToFloat(level, refiner.options(), &starts);
    });
}

LimitStencilTable composeLimitTables(const Refiner& refiner, int L, CompositionBudget& budget) {
    return composeLimitWithin(
        budget,
        [&] {
            return limitStencilsOf(refiner, L, budget, [&](const Topology& level, const RingStarts& starts) {
                return buildLimitStencils(level, refiner.options(), &starts);
            });
        },
        [&] { return composeLevelTables(L, budget, PositionLevels(refiner)); });
}

LimitStencilTable channelLimitTable(const FVarChannelRefinement& channel, int L, const Options& options,
                                    CompositionBudget& budget) {
    const LimitStencilTableD table = fvarLimitStencilsOf(channel, L, options, budget);
    budget.reserve(floatLimitBytes(table.sizes.size(), table.indices.size()));
    return toFloatTable(table);
}

LimitStencilTable composeChannelLimitTables(const FVarChannelRefinement& channel, int L, const Options& options,
                                            CompositionBudget& budget) {
    return composeLimitWithin(
        budget, [&] { return fvarLimitStencilsOf(channel, L, options, budget); },
        [&] { return composeLevelTables(L, budget, ChannelLevels{channel}); });
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
