// The CLI's Vulkan side (built with QUADTRI_WITH_VULKAN; tools/no_vulkan.cpp stands in without
// it): `refine --evaluator vulkan` (levels, limit, normals) and the demo's Vulkan column.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/far/refiner.h>
#include <quadtri/osd/vulkan_evaluator.h>
#include <quadtri/osd/vulkan_limit_evaluator.h>
#include <quadtri/osd/vulkan_limit_tables.h>
#include "tools/commands.h"

namespace quadtri::cli {

struct VulkanTiming {
    VulkanContext ctx;
};

void VulkanTimingDeleter::operator()(VulkanTiming* timing) const { delete timing; }

// Each item's levels in one Vulkan buffer, one dispatch per level; its last level read back.
std::optional<std::vector<std::vector<float>>> evaluateLevelsOnVulkan(const std::vector<LevelData>& data) {
    try {
        VulkanContext ctx;
        VulkanEvaluator evaluator(ctx);
        std::vector<std::vector<float>> refined;
        for (const LevelData& item : data) {
            if (item.tables.empty()) {
                refined.push_back(*item.control);
                continue;
            }
            const BufferDescriptor d(0, item.width, item.width);
            std::vector<VulkanStencilTable> tables;
            tables.reserve(item.tables.size());
            for (const StencilTable* table : item.tables) tables.emplace_back(ctx, *table);
            std::vector<const VulkanStencilTable*> pointers;
            for (const VulkanStencilTable& t : tables) pointers.push_back(&t);
            const std::vector<int> first = VulkanEvaluator::levelFirstElements(pointers);
            VulkanVertexBuffer all = VulkanVertexBuffer::create(ctx, first.back(), item.width);
            all.updateData(item.control->data(), 0, int(item.control->size()) / item.width);
            evaluator.EvalLevelsAndWait(all, d, pointers);
            std::vector<float> everything(std::size_t(first.back()) * std::size_t(item.width));
            all.readBack(everything.data());
            refined.emplace_back(everything.begin() + std::ptrdiff_t(item.width) * first[pointers.size()], everything.end());
        }
        std::fprintf(stderr, "quadtri: evaluated on Vulkan device %s\n", ctx.deviceName().c_str());
        return refined;
    } catch (const VulkanError& e) {
        std::fprintf(stderr, "quadtri: Vulkan unavailable (%s); using the CPU evaluator\n", e.what());
        return std::nullopt;
    }
}

// The limit table and, for mesh normals, the normal table of level `level`, each one dispatch.
std::optional<Surface> evaluateSurfaceOnVulkan(const Refiner& refiner, int level, const std::vector<float>& refined,
                                               bool limit, NormalKind normals) {
    try {
        const BufferDescriptor d(0, 3, 3);
        const int n = int(refined.size() / 3);
        VulkanContext ctx;
        VulkanLimitEvaluator evaluator(ctx);
        const VulkanMeshNormalTable meshNormals(ctx, buildMeshNormalTable(refiner.faces(level)));
        VulkanVertexBuffer source = VulkanVertexBuffer::create(ctx, n, 3);
        source.updateData(refined.data(), 0, n);
        VulkanVertexBuffer position = VulkanVertexBuffer::create(ctx, n, 3);
        VulkanVertexBuffer normal = VulkanVertexBuffer::create(ctx, n, 3);
        if (limit || normals == NormalKind::Limit) {
            const VulkanLimitStencilTable table(ctx, refiner.limitStencils(level));
            evaluator.EvalLimitStencilsAndWait(source, d, limit ? &position : nullptr, d, nullptr, d, nullptr, d,
                                               normals == NormalKind::Limit ? &normal : nullptr, d, table,
                                               &meshNormals);
        }
        const VulkanVertexBuffer& written = limit ? position : source;
        if (normals == NormalKind::Mesh) evaluator.EvalMeshNormalsAndWait(written, d, normal, d, meshNormals);
        Surface surface;
        surface.positions.resize(refined.size());
        written.readBack(surface.positions.data());
        if (normals != NormalKind::None) {
            surface.normals.resize(refined.size());
            normal.readBack(surface.normals.data());
        }
        std::fprintf(stderr, "quadtri: limit and normals evaluated on Vulkan device %s\n", ctx.deviceName().c_str());
        return surface;
    } catch (const VulkanError& e) {
        std::fprintf(stderr, "quadtri: Vulkan unavailable (%s); using the CPU evaluator\n", e.what());
        return std::nullopt;
    }
}

VulkanTimingPtr openVulkanTiming() {
    try {
        return VulkanTimingPtr(new VulkanTiming{VulkanContext()});
    } catch (const VulkanError& e) {
        std::fprintf(stderr, "quadtri: Vulkan unavailable (%s); no Vulkan timings\n", e.what());
        return nullptr;
    }
}

double vulkanEvalMs(VulkanTiming& timing, const StencilTable& table, const std::vector<float>& control, int runs) {
    VulkanContext& ctx = timing.ctx;
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
