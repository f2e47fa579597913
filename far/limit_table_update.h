// A limit stencil table kept up to date with its Refiner's edits (docs/edits.md, "Limit
// tables"): after Refiner::applyEdits, only the stencils the edit can change are computed again
// and put back, instead of the whole table.
#pragma once

#include <memory>
#include <vector>

#include <quadtri/export.h>
#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/tag_edits.h>

namespace quadtri {
inline namespace v0 {

class Refiner;

// What an update wrote into a limit table.
struct LimitTableChange {
    std::vector<int> stencils;  // whose size, run of sources or weights changed, sorted
    // The pools were laid out again (grown past twice their size): every stencil's offsets may
    // have changed, and a copy of the table elsewhere must be made again. Otherwise the pools only
    // grew at their ends, and a copy needs the changed stencils and the pools' new tails.
    bool poolsLaidOut = false;
};

class QUADTRI_API LimitTableUpdate {
public:
    // Which of the Refiner's limit tables of a level is kept up to date.
    enum class Sources {
        Level,    // Refiner::limitStencils(L): over level L's vertices
        Control,  // Refiner::factorizedLimitStencils(L): over the control vertices
    };

    // For `refiner`'s table of level `level` over `sources`, as built before the edits to come.
    // Reads the Refiner at every update: it must outlive this object and hold level L with its
    // full topology (refineUniform(L, TopologyDetail::Full)) and, for Sources::Control, the
    // per-level tables of levels 1..L; std::logic_error otherwise. Sources::Control builds the
    // level's limit masks once (what limitStencils(L) costs).
    LimitTableUpdate(const Refiner& refiner, int level, Sources sources);
    ~LimitTableUpdate();
    LimitTableUpdate(LimitTableUpdate&&) noexcept;
    LimitTableUpdate& operator=(LimitTableUpdate&&) noexcept;

    // After `report` = refiner.applyEdits(...): the stencils of `table` (the table this object
    // keeps, as built or updated since) that the edit can change are computed again and written
    // where they differ, their runs of sources and weights appended to the table's pools (laid
    // out again once grown past twice their size). Returns what it wrote. The table
    // then equals the one the Refiner would build: bit for bit over level L; over the control
    // vertices within float rounding (the Refiner composes regular faces from templates, an update
    // composes directly).
    LimitTableChange update(const EditReport& report, LimitStencilTable& table);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace v0
}  // namespace quadtri
