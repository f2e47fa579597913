// The tables one frame of the real-time loop applies: a Refiner's level N, limit positions and
// limit normals, through one of two routes (docs/realtime_loop.md, "The tables").
#pragma once

#include <optional>
#include <string>
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
    // on the bundled cage at level 3 it costs two thirds of the per-level route (9.7 against
    // 5.4 + 9.3 ms of one thread), whose limit pass alone costs as much, having to read back the
    // level the per-level tables just wrote (docs/realtime_loop.md, "The tables").
    FactorizedLimit,
    // Level by level (Refiner::levelStencils(1..N)), then the limit table over level N's own
    // vertices (Refiner::limitStencils(N)). Its tables grow linearly with the level where a
    // factorized table can pass the memory budget (near high-valence vertices, at levels 5-6).
    LevelsThenLimit,
    // Level by level to the patch level K = max(0, N - 3), then level N from K's regular patches
    // (Refiner::levelPatches, docs/patches.md): no index per point where a face is a regular
    // patch, stencils over level K elsewhere. Its points come in the patch table's order.
    Patches,
};
const char* toString(TableRoute route);
// Every route, and the words `quadtri demo --tables` and `quadtri view --tables` name them by
// ("factorized", "levels", "patches").
const std::vector<TableRoute>& allTableRoutes();
const char* tablesWord(TableRoute route);
std::optional<TableRoute> tableRouteNamed(const std::string& word);  // none for another word

// The host tables of `route` for level `level` (>= 0; at level 0 both routes are the cage's own
// limit table) of `refiner` (refined at least that far), copied, so they outlive the Refiner. Throws what the Refiner throws (MemoryBudgetError
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
    // Patches: levels holds levels 1..K, and `patches` gives level N from level K.
    std::optional<LevelPatchTable> patches;
};

// The patch level the Patches route takes for level N: rate-8 grids, the rows of one 8-wide vector.
inline int patchLevelFor(int level) { return level > 3 ? level - 3 : 0; }

// The fastest route's tables: FactorizedLimit, or LevelsThenLimit where the memory budget
// refuses the factorized table (near high-valence vertices at high levels).
SurfaceTables fastestSurfaceTables(const Refiner& refiner, int level);

}  // namespace quadtri::realtime
