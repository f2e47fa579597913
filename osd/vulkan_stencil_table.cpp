#include <quadtri/osd/vulkan_stencil_table.h>

#include <stdexcept>

namespace quadtri {
inline namespace v0 {

VulkanStencilTable::VulkanStencilTable(VulkanContext& ctx, const StencilTable& t)
    : device_(ctx.device()), numStencils_(t.numStencils()), numSourceVertices_(t.numSourceVertices) {
    if (t.offsets.size() != t.weightOffsets.size() + 1 || std::size_t(t.offsets.back()) != t.indices.size())
        throw std::invalid_argument("VulkanStencilTable: inconsistent StencilTable arrays");
    constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    constexpr VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    offsets_ = detail::DeviceBuffer(ctx, t.offsets.size() * sizeof(int), usage, local);
    indices_ = detail::DeviceBuffer(ctx, t.indices.size() * sizeof(int), usage, local);
    weightOffsets_ = detail::DeviceBuffer(ctx, t.weightOffsets.size() * sizeof(int), usage, local);
    weights_ = detail::DeviceBuffer(ctx, t.weights.size() * sizeof(float), usage, local);
    detail::upload(ctx, {
        {offsets_.buffer(), 0, t.offsets.data(), nullptr, t.offsets.size() * sizeof(int)},
        {indices_.buffer(), 0, t.indices.data(), nullptr, t.indices.size() * sizeof(int)},
        {weightOffsets_.buffer(), 0, t.weightOffsets.data(), nullptr, t.weightOffsets.size() * sizeof(int)},
        {weights_.buffer(), 0, t.weights.data(), nullptr, t.weights.size() * sizeof(float)},
    });
}

}  // namespace v0
}  // namespace quadtri
