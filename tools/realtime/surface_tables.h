// The tables one frame of the real-time loop applies: a Refiner's level N, limit positions and
// limit normals, through one of two routes (docs/realtime_loop.md, "The tables").
#pragma once

#include <vector>

#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/far/refiner.h>
#include <quadtri/far/stencil_table.h>

namespace quadtri::realtime {

enum class TableRoute {
    // One limit pass straight from the cage: Refiner::factorizedLimitStencils(N) gives the limit
    // positions and both tangents of every level-N vertex from the control vertices, so a frame
    // reads only the cage (tens of kilobytes, in cache) and writes the outputs once. The default:
    // the fastest route on the bundled cage (docs/realtime_loop.md has the measurements).
    FactorizedLimit,
    // Level by level (Refiner::levelStencils(1..N)), then the limit table over level N's own
    // vertices (Refiner::limitStencils(N)). Its tables grow linearly with the level where a
    // factorized table can pass the memory budget (near high-valence vertices, at levels 5-6).
    LevelsThenLimit,
};
const char* toString(TableRoute route);

// The host tables of `route` for level `level` (>= 1; LevelsThenLimit also 0) of `refiner` (refined at least that far),
// copied, so they outlive the Refiner. Throws what the Refiner throws (MemoryBudgetError
// included).
struct SurfaceTables {
    SurfaceTables(const Refiner& refiner, int level, TableRoute route);

    TableRoute route;
    int level;
    int numControl;                   // the cage's vertices: what a frame deforms
    int numPoints;                    // level N's vertices: what a frame outputs
    std::vector<StencilTable> levels; // LevelsThenLimit: levels 1..N, each over the level before
    LimitStencilTable limit;          // over the cage (FactorizedLimit) or over level N
    // LevelsThenLimit: level N's mesh normals, the normal where the tangents are degenerate (a
    // factorized table never sees level N, so it has none: docs/limit_evaluation.md).
    MeshNormalTable fallback;
};

// The fastest route's tables: FactorizedLimit, or LevelsThenLimit where the memory budget
// refuses the factorized table (near high-valence vertices at high levels).
SurfaceTables fastestSurfaceTables(const Refiner& refiner, int level);

}  // namespace quadtri::realtime
