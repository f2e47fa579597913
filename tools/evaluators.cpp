// `quadtri refine --evaluator cpu|tbb|vulkan`: the factorized table applied by the chosen evaluator.
#include <cstdio>

#include "osd/cpu_evaluator.h"
#include "osd/tbb_evaluator.h"
#include "osd/vulkan_evaluator.h"
#include "tools/commands.h"

namespace quadtri::cli {

std::vector<float> evaluatePositions(EvaluatorKind kind, const StencilTable& table, const std::vector<float>& control) {
    const BufferDescriptor d(0, 3, 3);
    std::vector<float> out(std::size_t(table.numStencils()) * 3);
    if (kind == EvaluatorKind::Vulkan) {
        try {
            VulkanContext ctx;
            VulkanStencilTable gpuTable(ctx, table);
            VulkanVertexBuffer src = VulkanVertexBuffer::create(ctx, table.numSourceVertices, 3);
            VulkanVertexBuffer dst = VulkanVertexBuffer::create(ctx, table.numStencils(), 3);
            src.updateData(control.data(), 0, table.numSourceVertices);
            VulkanEvaluator evaluator(ctx);
            evaluator.EvalStencilsAndWait(src, d, dst, d, gpuTable);
            dst.readBack(out.data());
            std::fprintf(stderr, "quadtri: evaluated on Vulkan device %s\n", ctx.deviceName().c_str());
            return out;
        } catch (const VulkanError& e) {
            std::fprintf(stderr, "quadtri: Vulkan unavailable (%s); using the CPU evaluator\n", e.what());
        }
        kind = EvaluatorKind::Cpu;
    }
    if (kind == EvaluatorKind::Tbb)
        TbbEvaluator::EvalStencils(control.data(), d, out.data(), d, table);
    else
        CpuEvaluator::EvalStencils(control.data(), d, out.data(), d, table);
    return out;
}

}  // namespace quadtri::cli
