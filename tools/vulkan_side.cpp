// The CLI's Vulkan side (built with QUADTRI_WITH_VULKAN; tools/no_vulkan.cpp stands in without
// it): `refine --evaluator vulkan` (levels, limit, normals) and the demo's Vulkan evaluator.
#include <cstdio>

#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/far/refiner.h>
#include <quadtri/osd/vulkan_evaluator.h>
#include <quadtri/osd/vulkan_limit_evaluator.h>
#include <quadtri/osd/vulkan_limit_tables.h>
#include "tools/commands.h"
#include "tools/realtime/vulkan_frame_evaluator.h"

namespace quadtri::cli {

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

namespace {

// The demo's Vulkan evaluator with a headless context of its own.
class HeadlessFrameEvaluator : public realtime::FrameEvaluator {
public:
    explicit HeadlessFrameEvaluator(const realtime::SurfaceTables& tables) : evaluator_(ctx_, tables) {}
    std::string name() const override { return evaluator_.name(); }
    void setCage(const float* cage) override { evaluator_.setCage(cage); }
    void evaluate(realtime::PhaseTimes& times) override { evaluator_.evaluate(times); }
    void readBack(std::vector<float>& positions, std::vector<float>& normals) override {
        evaluator_.readBack(positions, normals);
    }
    std::string deviceName() const { return ctx_.deviceName(); }

private:
    VulkanContext ctx_;
    realtime::VulkanFrameEvaluator evaluator_;
};

}  // namespace

std::unique_ptr<realtime::FrameEvaluator> makeVulkanFrameEvaluator(const realtime::SurfaceTables& tables,
                                                                   std::string& device) {
    try {
        auto evaluator = std::make_unique<HeadlessFrameEvaluator>(tables);
        device = evaluator->deviceName();
        return evaluator;
    } catch (const VulkanError& e) {
        std::fprintf(stderr, "quadtri: Vulkan unavailable (%s); vulkan skipped\n", e.what());
        return nullptr;
    }
}

}  // namespace quadtri::cli
