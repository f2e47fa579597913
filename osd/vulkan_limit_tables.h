// A LimitStencilTable and a MeshNormalTable uploaded once to device-local storage buffers, for
// VulkanLimitEvaluator (like VulkanStencilTable for VulkanEvaluator).
#pragma once

#include <vulkan/vulkan.h>

#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_memory.h>

namespace quadtri {
inline namespace v0 {

class VulkanLimitStencilTable {
public:
    // Copies the table's four arrays through one staging buffer (waits).
    VulkanLimitStencilTable(VulkanContext& ctx, const LimitStencilTable& table);

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

class VulkanMeshNormalTable {
public:
    // Copies the table's two arrays through one staging buffer (waits).
    VulkanMeshNormalTable(VulkanContext& ctx, const MeshNormalTable& table);

    int numVertices() const { return numVertices_; }
    VkBuffer offsets() const { return offsets_.buffer(); }
    VkBuffer corners() const { return corners_.buffer(); }
    VkDevice device() const { return device_; }

private:
    VkDevice device_;
    int numVertices_ = 0;
    detail::DeviceBuffer offsets_, corners_;
};

}  // namespace v0
}  // namespace quadtri
