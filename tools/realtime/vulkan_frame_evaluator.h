// The real-time loop on a Vulkan device: the deformed cage uploaded, the tables applied by
// VulkanEvaluator / VulkanLimitEvaluator, level N's limit positions and normals left in device
// buffers (VulkanVertexBuffer: storage and vertex buffers both), where a renderer's vertex
// shader reads them with no trip through the host.
#pragma once

#include <memory>
#include <vector>

#include <quadtri/osd/vulkan_buffer.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_evaluator.h>
#include <quadtri/osd/vulkan_limit_evaluator.h>
#include <quadtri/osd/vulkan_limit_tables.h>
#include "osd/vulkan/vulkan_memory.h"
#include <quadtri/osd/vulkan_stencil_table.h>
#include "tools/realtime/frame_evaluator.h"
#include "tools/realtime/surface_tables.h"

namespace quadtri::realtime {

class VulkanFrameEvaluator : public FrameEvaluator {
public:
    // Uploads `tables` to `ctx`'s device once (waits). The context (headless, or adopted from a
    // renderer: VulkanContext::External) must outlive the evaluator; `tables` need not.
    // `editable`: the limit table is uploaded with room for edits' updates (updateLimit).
    VulkanFrameEvaluator(VulkanContext& ctx, const SurfaceTables& tables, bool editable = false);

    // After `change` = LimitTableUpdate::update(..., tables.limit) on the tables this evaluator was
    // made from (editable): the device's limit table updated by range (waits). False where it
    // cannot be (make the evaluator again then).
    bool updateLimit(const LimitStencilTable& limit, const LimitTableChange& change) {
        return limit_.update(ctx_, limit, change);
    }
    // The same for the per-level table of level L (1..N under LevelsThenLimit, 1..K under
    // Patches) after Refiner::applyEdits changed it as `edited` says.
    bool updateLevel(int L, const StencilTable& table, const EditedLevel& edited) {
        return levels_.at(std::size_t(L) - 1)->update(ctx_, table, edited.stencils, edited.tableResized, edited.poolLaidOut);
    }

    std::string name() const override { return "vulkan"; }
    // Uploads the cage (one staging copy, waited on).
    void setCage(const float* cage) override;
    // record() into a command buffer of the context's, submitted and waited on (the levels and
    // the limit or patch pass in two submissions under LevelsThenLimit and Patches, to time them
    // apart).
    void evaluate(PhaseTimes& times) override;
    void readBack(std::vector<float>& positions, std::vector<float>& normals) override;

    // For a renderer, a frame with no wait: recordCage(cmd, cage) copies the cage into a
    // host-visible staging buffer of the evaluator's and records its upload into `cmd` (a primary
    // command buffer of the context's device on a compute-capable queue family); the staging
    // buffer is reused, so the device must have finished the previous frame's `cmd`. record(cmd)
    // then records the evaluation; its last barrier makes the outputs visible to compute,
    // transfer and host reads: add a barrier to the vertex-input stage before drawing from them.
    // Call resetDescriptorSets() once the device has finished `cmd`.
    void recordCage(VkCommandBuffer cmd, const float* cage);
    void record(VkCommandBuffer cmd);
    void resetDescriptorSets();

    // Level N's limit positions and unit normals, 3 floats per vertex, element i = vertex i (under
    // TableRoute::Patches, element k = the patch table's point k: LevelPatchTable::vertexOf;
    // readBack puts them back in level order).
    const VulkanVertexBuffer& positions() const { return positions_; }
    const VulkanVertexBuffer& normals() const { return normals_; }
    VulkanContext& context() const { return ctx_; }

private:
    void recordLevels(VkCommandBuffer cmd);
    void recordLimit(VkCommandBuffer cmd);

    VulkanContext& ctx_;
    TableRoute route_;
    int numControl_;
    std::vector<std::unique_ptr<VulkanStencilTable>> levels_;
    std::vector<int> levelFirst_;   // first element of each level in source_ (EvalLevels' layout)
    VulkanLimitStencilTable limit_;
    std::unique_ptr<VulkanMeshNormalTable> fallback_;
    std::unique_ptr<VulkanLevelPatchTable> patches_;  // Patches: level N from the last level
    std::vector<int> vertexOfPoint_;                  // Patches: each point's level-N vertex
    // The cage at elements [0, numControl), followed by levels 1..N under LevelsThenLimit.
    VulkanVertexBuffer source_, positions_, normals_;
    detail::DeviceBuffer staging_;  // recordCage's copy of the cage
    VulkanEvaluator stencilEvaluator_;
    VulkanLimitEvaluator limitEvaluator_;
};

}  // namespace quadtri::realtime
