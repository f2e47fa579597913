#include "tools/realtime/vulkan_frame_evaluator.h"

#include <chrono>
#include <cstring>
#include <stdexcept>

namespace quadtri::realtime {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::vector<std::unique_ptr<VulkanStencilTable>> upload(VulkanContext& ctx, const std::vector<StencilTable>& tables,
                                                        bool editable) {
    std::vector<std::unique_ptr<VulkanStencilTable>> uploaded;
    for (const StencilTable& table : tables) uploaded.push_back(std::make_unique<VulkanStencilTable>(ctx, table, editable));
    return uploaded;
}

std::vector<const VulkanStencilTable*> pointers(const std::vector<std::unique_ptr<VulkanStencilTable>>& tables) {
    std::vector<const VulkanStencilTable*> p;
    for (const auto& t : tables) p.push_back(t.get());
    return p;
}

const BufferDescriptor kXyz(0, 3, 3);

}  // namespace

VulkanFrameEvaluator::VulkanFrameEvaluator(VulkanContext& ctx, const SurfaceTables& tables, bool editable)
    : ctx_(ctx), route_(tables.route), numControl_(tables.numControl), levels_(upload(ctx, tables.levels, editable)),
      levelFirst_(levels_.empty() ? std::vector<int>{0, tables.numControl}
                                  : VulkanEvaluator::levelFirstElements(pointers(levels_))),
      limit_(ctx, tables.limit, editable),
      fallback_(tables.route == TableRoute::LevelsThenLimit
                    ? std::make_unique<VulkanMeshNormalTable>(ctx, tables.fallback)
                    : nullptr),
      source_(VulkanVertexBuffer::create(ctx, levelFirst_.back(), 3)),
      positions_(VulkanVertexBuffer::create(ctx, tables.numPoints, 3)),
      normals_(VulkanVertexBuffer::create(ctx, tables.numPoints, 3)), stencilEvaluator_(ctx), limitEvaluator_(ctx) {
    if (!tables.patches) return;
    patches_ = std::make_unique<VulkanLevelPatchTable>(ctx, *tables.patches);
    vertexOfPoint_.resize(std::size_t(tables.numPoints));
    for (int k = 0; k < tables.numPoints; ++k) vertexOfPoint_[std::size_t(k)] = tables.patches->vertexOf(k);
}

void VulkanFrameEvaluator::setCage(const float* cage) { source_.updateData(cage, 0, numControl_); }

void VulkanFrameEvaluator::recordCage(VkCommandBuffer cmd, const float* cage) {
    const VkDeviceSize bytes = VkDeviceSize(numControl_) * 3 * sizeof(float);
    if (staging_.buffer() == VK_NULL_HANDLE)
        staging_ = detail::DeviceBuffer(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    // Host writes to coherent memory before the submission are visible to its transfers.
    std::memcpy(staging_.map(), cage, bytes);
    const VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, staging_.buffer(), source_.buffer(), 1, &region);
    detail::barrierAfterTransferWrite(cmd);
}

void VulkanFrameEvaluator::recordLevels(VkCommandBuffer cmd) {
    if (!levels_.empty()) stencilEvaluator_.EvalLevels(cmd, {source_.buffer(), 0, source_.texels()}, kXyz, pointers(levels_));
}

void VulkanFrameEvaluator::recordLimit(VkCommandBuffer cmd) {
    // The limit table reads the last level: the cage itself for a factorized table.
    const VkDeviceSize lastLevel = VkDeviceSize(levelFirst_[levelFirst_.size() - 2]) * 3 * sizeof(float);
    if (patches_) {
        limitEvaluator_.EvalLevelPatches(cmd, {source_.buffer(), lastLevel, source_.texels()}, kXyz,
                                         {positions_.buffer(), 0}, kXyz, {normals_.buffer(), 0}, kXyz, *patches_);
        return;
    }
    limitEvaluator_.EvalLimitStencils(cmd, {source_.buffer(), lastLevel, source_.texels()}, kXyz, {positions_.buffer(), 0}, kXyz, {},
                                      kXyz, {}, kXyz, {normals_.buffer(), 0}, kXyz, limit_, fallback_.get());
}

void VulkanFrameEvaluator::record(VkCommandBuffer cmd) {
    recordLevels(cmd);
    recordLimit(cmd);
}

void VulkanFrameEvaluator::resetDescriptorSets() {
    stencilEvaluator_.resetDescriptorSets();
    limitEvaluator_.resetDescriptorSets();
}

void VulkanFrameEvaluator::evaluate(PhaseTimes& times) {
    Clock::time_point start = Clock::now();
    if (route_ == TableRoute::FactorizedLimit) {
        ctx_.submitAndWait([this](VkCommandBuffer cmd) { record(cmd); });
        times.evaluateMs = msSince(start);
        times.normalsMs = 0;
    } else {
        ctx_.submitAndWait([this](VkCommandBuffer cmd) { recordLevels(cmd); });
        times.evaluateMs = msSince(start);
        start = Clock::now();
        ctx_.submitAndWait([this](VkCommandBuffer cmd) { recordLimit(cmd); });
        times.normalsMs = msSince(start);
    }
    resetDescriptorSets();
}

void VulkanFrameEvaluator::readBack(std::vector<float>& positions, std::vector<float>& normals) {
    positions.resize(positions_.numFloats());
    normals.resize(normals_.numFloats());
    positions_.readBack(positions.data());
    normals_.readBack(normals.data());
    if (vertexOfPoint_.empty()) return;
    // The patch table's points, back in level order.
    const std::vector<float> p(positions), n(normals);
    for (std::size_t k = 0; k < vertexOfPoint_.size(); ++k) {
        const std::size_t v = std::size_t(vertexOfPoint_[k]);
        for (std::size_t c = 0; c < 3; ++c) positions[3 * v + c] = p[3 * k + c], normals[3 * v + c] = n[3 * k + c];
    }
}

}  // namespace quadtri::realtime
