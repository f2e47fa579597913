#include "tools/realtime/surface_tables.h"

#include <stdexcept>
#include <string>

namespace quadtri::realtime {

const char* toString(TableRoute route) {
    return route == TableRoute::FactorizedLimit ? "factorized limit" : "per-level then limit";
}

SurfaceTables::SurfaceTables(const Refiner& refiner, int level, TableRoute route)
    : route(route), level(level), numControl(refiner.faces(0).numVertices()), numPoints(0) {
    // Level 0 (the cage's own limit surface, for the viewer) has no factorized table.
    const int lowest = route == TableRoute::FactorizedLimit ? 1 : 0;
    if (level < lowest || level > refiner.maxLevel())
        throw std::invalid_argument("SurfaceTables: level " + std::to_string(level) + " outside the refined " +
                                    std::to_string(lowest) + ".." + std::to_string(refiner.maxLevel()));
    numPoints = refiner.faces(level).numVertices();
    if (route == TableRoute::FactorizedLimit) {
        limit = refiner.factorizedLimitStencils(level);
        return;
    }
    for (int L = 1; L <= level; ++L) levels.push_back(refiner.levelStencils(L));
    limit = refiner.limitStencils(level);
    fallback = buildMeshNormalTable(refiner.faces(level));
}

SurfaceTables fastestSurfaceTables(const Refiner& refiner, int level) {
    try {
        return SurfaceTables(refiner, level, TableRoute::FactorizedLimit);
    } catch (const MemoryBudgetError&) {
        return SurfaceTables(refiner, level, TableRoute::LevelsThenLimit);
    }
}

}  // namespace quadtri::realtime
