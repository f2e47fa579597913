// `quadtri refine --evaluator cpu|tbb|vulkan`: the per-level tables applied by the chosen evaluator.
#include <optional>
#include <utility>

#include <quadtri/far/refiner.h>
#include <quadtri/osd/cpu_evaluator.h>
#include <quadtri/osd/tbb_evaluator.h>
#include "tools/commands.h"

namespace quadtri::cli {

std::vector<float> evaluateLevels(EvaluatorKind kind, const Refiner& refiner, int level, const std::vector<float>& control) {
    if (kind == EvaluatorKind::Vulkan) {
        if (std::optional<std::vector<float>> positions = evaluateLevelsOnVulkan(refiner, level, control))
            return std::move(*positions);
        kind = EvaluatorKind::Cpu;
    }
    const BufferDescriptor d(0, 3, 3);
    std::vector<float> previous = control, next;
    for (int L = 1; L <= level; ++L) {
        const StencilTable& table = refiner.levelStencils(L);
        next.assign(std::size_t(table.numStencils()) * 3, 0.0f);
        if (kind == EvaluatorKind::Tbb)
            TbbEvaluator::EvalStencils(previous.data(), d, next.data(), d, table);
        else
            CpuEvaluator::EvalStencils(previous.data(), d, next.data(), d, table);
        previous.swap(next);
    }
    return previous;
}

}  // namespace quadtri::cli
