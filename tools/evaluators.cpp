// `quadtri refine --evaluator cpu|tbb|vulkan`: the per-level tables, and the limit or mesh normals
// of `--limit` / `--normals`, applied by the chosen evaluator.
#include <algorithm>
#include <optional>
#include <utility>

#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/far/refiner.h>
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include "tools/commands.h"

namespace quadtri::cli {

LevelData positionLevels(const Refiner& refiner, int level, const std::vector<float>& control) {
    LevelData data{{}, 3, &control};
    for (int L = 1; L <= level; ++L) data.tables.push_back(&refiner.levelStencils(L));
    return data;
}

LevelData fvarLevels(const Refiner& refiner, int channel, int level, const std::vector<float>& values, int width) {
    LevelData data{{}, width, &values};
    for (int L = 1; L <= level; ++L) data.tables.push_back(&refiner.fvarLevelStencils(channel, L));
    return data;
}

std::vector<std::vector<float>> evaluateLevels(EvaluatorKind kind, const std::vector<LevelData>& data) {
    const bool anyTable = std::any_of(data.begin(), data.end(), [](const LevelData& d) { return !d.tables.empty(); });
    if (kind == EvaluatorKind::Vulkan && anyTable) {
        if (std::optional<std::vector<std::vector<float>>> refined = evaluateLevelsOnVulkan(data))
            return std::move(*refined);
        kind = EvaluatorKind::Cpu;
    }
    std::vector<std::vector<float>> refined;
    for (const LevelData& item : data) {
        const BufferDescriptor d(0, item.width, item.width);
        std::vector<float> previous = *item.control, next;
        for (const StencilTable* table : item.tables) {
            next.assign(std::size_t(table->numStencils()) * std::size_t(item.width), 0.0f);
            if (kind == EvaluatorKind::Tbb)
                TbbEvaluator::EvalStencils(previous.data(), d, next.data(), d, *table);
            else
                CpuEvaluator::EvalStencils(previous.data(), d, next.data(), d, *table);
            previous.swap(next);
        }
        refined.push_back(std::move(previous));
    }
    return refined;
}

std::vector<float> evaluateLevels(EvaluatorKind kind, const Refiner& refiner, int level, const std::vector<float>& control) {
    return std::move(evaluateLevels(kind, {positionLevels(refiner, level, control)})[0]);
}

Surface evaluateSurface(EvaluatorKind kind, const Refiner& refiner, int level, std::vector<float> refined, bool limit,
                        NormalKind normals) {
    if (!limit && normals == NormalKind::None) return {std::move(refined), {}};
    if (kind == EvaluatorKind::Vulkan) {
        if (std::optional<Surface> surface = evaluateSurfaceOnVulkan(refiner, level, refined, limit, normals))
            return std::move(*surface);
        kind = EvaluatorKind::Cpu;
    }
    const bool tbb = kind == EvaluatorKind::Tbb;
    const BufferDescriptor d(0, 3, 3);
    const std::size_t n = refined.size() / 3;
    // Where a limit normal is undefined (parallel tangents) the evaluators use the mesh normal.
    const MeshNormalTable meshNormals = buildMeshNormalTable(refiner.faces(level));
    Surface surface;
    if (limit || normals == NormalKind::Limit) {
        const LimitStencilTable table = refiner.limitStencils(level);
        if (limit) surface.positions.assign(3 * n, 0.0f);
        if (normals == NormalKind::Limit) surface.normals.assign(3 * n, 0.0f);
        float* position = limit ? surface.positions.data() : nullptr;
        float* normal = normals == NormalKind::Limit ? surface.normals.data() : nullptr;
        if (tbb)
            TbbEvaluator::EvalLimitStencils(refined.data(), d, position, d, nullptr, d, nullptr, d, normal, d, table,
                                            &meshNormals);
        else
            CpuEvaluator::EvalLimitStencils(refined.data(), d, position, d, nullptr, d, nullptr, d, normal, d, table,
                                            &meshNormals);
    }
    if (!limit) surface.positions = std::move(refined);
    if (normals == NormalKind::Mesh) {  // of the positions written, limit or not
        surface.normals.assign(3 * n, 0.0f);
        if (tbb)
            TbbEvaluator::EvalMeshNormals(surface.positions.data(), d, surface.normals.data(), d, meshNormals);
        else
            CpuEvaluator::EvalMeshNormals(surface.positions.data(), d, surface.normals.data(), d, meshNormals);
    }
    return surface;
}

}  // namespace quadtri::cli
