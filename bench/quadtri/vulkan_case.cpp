#include "bench/quadtri/vulkan_case.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "bench/measure/timing.h"
#include <quadtri/osd/vulkan_evaluator.h>

namespace quadtri::bench {

namespace {

using Tables = std::vector<std::unique_ptr<VulkanStencilTable>>;

std::vector<const VulkanStencilTable*> pointers(const Tables& tables) {
    std::vector<const VulkanStencilTable*> out;
    for (const auto& t : tables) out.push_back(t.get());
    return out;
}

}  // namespace

VulkanFigures measureVulkan(VulkanContext& ctx, const Refiner& refiner, const std::vector<float>& control,
                            const std::vector<float>& expected, double tolerance, int reps) {
    const int numControl = int(control.size() / 3);
    Tables tables;
    auto upload = [&] {
        tables.clear();
        for (int L = 1; L <= refiner.maxLevel(); ++L)
            tables.push_back(std::make_unique<VulkanStencilTable>(ctx, refiner.levelStencils(L)));
    };
    upload();
    const std::vector<int> first = VulkanEvaluator::levelFirstElements(pointers(tables));
    VulkanVertexBuffer buffer = VulkanVertexBuffer::create(ctx, first.back(), 3);
    VulkanEvaluator evaluator(ctx);
    const BufferDescriptor xyz(0, 3, 3);

    buffer.updateData(control.data(), 0, numControl);
    evaluator.EvalLevelsAndWait(buffer, xyz, pointers(tables));
    std::vector<float> all(buffer.numFloats());
    buffer.readBack(all.data());
    const std::size_t lastStart = 3 * std::size_t(first[first.size() - 2]);
    double worst = 0;
    for (std::size_t i = 0; i < expected.size(); ++i)
        worst = std::max(worst, double(std::fabs(all[lastStart + i] - expected[i])));
    if (worst > tolerance)
        throw std::runtime_error("Vulkan evaluation differs from CpuEvaluator by " + std::to_string(worst));

    VulkanFigures f;
    f.uploadMs = timeMs(reps, [&] {
        upload();
        buffer.updateData(control.data(), 0, numControl);
    });
    const std::vector<const VulkanStencilTable*> levels = pointers(tables);
    f.evalMs = timeMs(reps, [&] { evaluator.EvalLevelsAndWait(buffer, xyz, levels); });
    return f;
}

}  // namespace quadtri::bench
