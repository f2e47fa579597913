// A StencilTable uploaded once to device-local storage buffers, for VulkanEvaluator.
#pragma once

#include <vulkan/vulkan.h>

#include <quadtri/far/stencil_table.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_memory.h>

namespace quadtri {
inline namespace v0 {

class VulkanStencilTable {
public:
    // Copies the table's four arrays to device-local buffers through one staging buffer (waits).
    VulkanStencilTable(VulkanContext& ctx, const StencilTable& table);

    int numStencils() const { return numStencils_; }
    int numSourceVertices() const { return numSourceVertices_; }
    VkBuffer offsets() const { return offsets_.buffer(); }
    VkBuffer indices() const { return indices_.buffer(); }
    VkBuffer weightOffsets() const { return weightOffsets_.buffer(); }
    VkBuffer weights() const { return weights_.buffer(); }
    VkDevice device() const { return device_; }

private:
    VkDevice device_;
    int numStencils_ = 0, numSourceVertices_ = 0;
    detail::DeviceBuffer offsets_, indices_, weightOffsets_, weights_;
};

}  // namespace v0
}  // namespace quadtri
