// Refiner::factorizedStencils(L) kept up to date with its Refiner's edits (docs/edits.md,
// "Factorized tables"): after Refiner::applyEdits, only the stencils over the control vertices
// that the edit changed are composed again and put back.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include <quadtri/export.h>
#include <quadtri/far/stencil_table.h>
#include <quadtri/far/tag_edits.h>

namespace quadtri {
inline namespace v0 {

class Refiner;

// What an update wrote into a table (as EditedLevel says it of the per-level tables).
struct StencilTableChange {
    std::vector<int> stencils;  // that changed, sorted
    bool resized = false;       // one changed its size: the arrays moved from the first on
    bool poolLaidOut = false;   // the weight pool was laid out again (else it only grew at its end)
};

class QUADTRI_API FactorizedTableUpdate {
public:
    // For `refiner`'s factorizedStencils(level) (level >= 1), as built before the edits to come.
    // Reads the Refiner at every update: it must outlive this object and hold the per-level tables
    // of levels 1..L; std::logic_error otherwise.
    FactorizedTableUpdate(const Refiner& refiner, int level);
    ~FactorizedTableUpdate();
    FactorizedTableUpdate(FactorizedTableUpdate&&) noexcept;
    FactorizedTableUpdate& operator=(FactorizedTableUpdate&&) noexcept;

    // After `report` = refiner.applyEdits(...): the stencils of `table` that read a changed
    // per-level stencil, at any level, composed again (in double, level by level, directly) and
    // written where they differ. The table then equals factorizedStencils(L) within float
    // rounding (the Refiner composes regular faces from templates).
    StencilTableChange update(const EditReport& report, StencilTable& table);

private:
    const Refiner* refiner_;
    int level_;
    std::size_t poolMark_ = 0;
};

}  // namespace v0
}  // namespace quadtri
