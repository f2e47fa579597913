// A StencilTable uploaded once to device-local storage buffers, for VulkanEvaluator.
#pragma once

#include <vector>

#include <vulkan/vulkan.h>

#include <quadtri/far/stencil_table.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_memory.h>

namespace quadtri {
inline namespace v0 {

namespace detail {

// The four arrays of a pooled stencil table (StencilTable, LimitStencilTable: offsets, indices,
// per-stencil weight offsets, the weight pool) in device-local storage buffers.
class PooledTableBuffers {
public:
    int numStencils() const { return numStencils_; }
    int numSourceVertices() const { return numSourceVertices_; }
    VkBuffer offsets() const { return offsets_.buffer(); }
    VkBuffer indices() const { return indices_.buffer(); }
    VkBuffer weightOffsets() const { return weightOffsets_.buffer(); }
    VkBuffer weights() const { return weights_.buffer(); }
    VkDevice device() const { return device_; }

protected:
    // Copies the arrays through one staging buffer (waits); std::invalid_argument naming `table`
    // ("StencilTable") when they are inconsistent.
    PooledTableBuffers(VulkanContext& ctx, int numSourceVertices, const std::vector<int>& offsets,
                       const std::vector<int>& indices, const std::vector<int>& weightOffsets,
                       const std::vector<float>& weights, const char* table);

private:
    VkDevice device_;
    int numStencils_ = 0, numSourceVertices_ = 0;
    DeviceBuffer offsets_, indices_, weightOffsets_, weights_;
};

}  // namespace detail

class VulkanStencilTable : public detail::PooledTableBuffers {
public:
    VulkanStencilTable(VulkanContext& ctx, const StencilTable& table)
        : PooledTableBuffers(ctx, table.numSourceVertices, table.offsets, table.indices, table.weightOffsets,
                             table.weights, "StencilTable") {}
};

}  // namespace v0
}  // namespace quadtri
