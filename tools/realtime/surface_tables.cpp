#include "tools/realtime/surface_tables.h"

#include <stdexcept>
#include <string>

namespace quadtri::realtime {

const char* toString(TableRoute route) {
    switch (route) {
        case TableRoute::FactorizedLimit: return "factorized limit";
        case TableRoute::LevelsThenLimit: return "per-level then limit";
        case TableRoute::Patches: return "per-level then patches";
    }
    return "?";
}

const std::vector<TableRoute>& allTableRoutes() {
    static const std::vector<TableRoute> all{TableRoute::FactorizedLimit, TableRoute::LevelsThenLimit,
                                             TableRoute::Patches};
    return all;
}

std::optional<TableRoute> tableRouteNamed(const std::string& word) {
    for (TableRoute route : allTableRoutes())
        if (word == tablesWord(route)) return route;
    return std::nullopt;
}

const char* tablesWord(TableRoute route) {
    switch (route) {
        case TableRoute::FactorizedLimit: return "factorized";
        case TableRoute::LevelsThenLimit: return "levels";
        case TableRoute::Patches: return "patches";
    }
    return "?";
}

SurfaceTables::SurfaceTables(const Refiner& refiner, int level, TableRoute route)
    : route(route), level(level), numControl(refiner.faces(0).numVertices()), numPoints(0) {
    if (level < 0 || level > refiner.maxLevel())
        throw std::invalid_argument("SurfaceTables: level " + std::to_string(level) + " outside the refined 0.." +
                                    std::to_string(refiner.maxLevel()));
    numPoints = refiner.faces(level).numVertices();
    if (route == TableRoute::FactorizedLimit) {
        limit = refiner.factorizedLimitStencils(level);
        return;
    }
    if (route == TableRoute::Patches) {
        if (level == 0) throw std::invalid_argument("SurfaceTables: the patch route needs level 1 or more");
        const int patchLevel = patchLevelFor(level);
        for (int L = 1; L <= patchLevel; ++L) levels.push_back(refiner.levelStencils(L));
        patches = refiner.levelPatches(level, patchLevel);
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
