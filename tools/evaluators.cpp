// `quadtri refine --evaluator cpu|tbb|vulkan`: the factorized table applied by the chosen evaluator.
#include <algorithm>
#include <chrono>
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

std::unique_ptr<VulkanContext> openVulkan() {
    try {
        return std::make_unique<VulkanContext>();
    } catch (const VulkanError& e) {
        std::fprintf(stderr, "quadtri: Vulkan unavailable (%s); no Vulkan timings\n", e.what());
        return nullptr;
    }
}

double vulkanEvalMs(VulkanContext& ctx, const StencilTable& table, const std::vector<float>& control, int runs) {
    const BufferDescriptor d(0, 3, 3);
    VulkanStencilTable gpuTable(ctx, table);
    VulkanVertexBuffer src = VulkanVertexBuffer::create(ctx, table.numSourceVertices, 3);
    VulkanVertexBuffer dst = VulkanVertexBuffer::create(ctx, table.numStencils(), 3);
    src.updateData(control.data(), 0, table.numSourceVertices);
    VulkanEvaluator evaluator(ctx);
    evaluator.EvalStencilsAndWait(src, d, dst, d, gpuTable);  // warm-up: pipeline creation
    std::vector<double> ms;
    for (int run = 0; run < runs; ++run) {
        const auto start = std::chrono::steady_clock::now();
        evaluator.EvalStencilsAndWait(src, d, dst, d, gpuTable);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::nth_element(ms.begin(), ms.begin() + runs / 2, ms.end());
    return ms[runs / 2];
}

}  // namespace quadtri::cli
