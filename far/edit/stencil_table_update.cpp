// FactorizedTableUpdate (docs/edits.md, "Factorized tables").
#include <quadtri/far/stencil_table_update.h>

#include <stdexcept>
#include <string>

#include <quadtri/far/refiner.h>

#include "far/edit/composed_rows.h"
#include "far/edit/stencil_splice.h"

namespace quadtri {
inline namespace v0 {

using namespace internal;

FactorizedTableUpdate::FactorizedTableUpdate(const Refiner& refiner, int level) : refiner_(&refiner), level_(level) {
    if (level < 1 || level > refiner.maxLevel())
        throw std::logic_error("FactorizedTableUpdate: level " + std::to_string(level) + " outside the refined 1.." +
                               std::to_string(refiner.maxLevel()));
    for (int l = 1; l <= level; ++l) refiner.levelStencils(l);  // std::logic_error without them
}

FactorizedTableUpdate::~FactorizedTableUpdate() = default;
FactorizedTableUpdate::FactorizedTableUpdate(FactorizedTableUpdate&&) noexcept = default;
FactorizedTableUpdate& FactorizedTableUpdate::operator=(FactorizedTableUpdate&&) noexcept = default;

StencilTableChange FactorizedTableUpdate::update(const EditReport& report, StencilTable& table) {
    if (int(report.levels.size()) <= level_)
        throw std::invalid_argument("FactorizedTableUpdate: the report covers levels 0.." +
                                    std::to_string(int(report.levels.size()) - 1) + ", the table is of level " +
                                    std::to_string(level_));
    const std::vector<std::uint8_t> changed = composedChanges(*refiner_, level_, report);
    std::vector<int> rows;
    for (int v = 0; v < int(changed.size()); ++v)
        if (changed[std::size_t(v)]) rows.push_back(v);
    StencilTableChange out;
    if (rows.empty()) return out;
    const StencilTable fresh = toFloatTable(composedRows(*refiner_, level_, rows));
    if (poolMark_ == 0) poolMark_ = table.weights.size();
    Splice splice = spliceStencils(table, rows, fresh, poolMark_);
    out.stencils = std::move(splice.changed);
    out.resized = splice.resized;
    out.poolLaidOut = splice.poolLaidOut;
    return out;
}

}  // namespace v0
}  // namespace quadtri
