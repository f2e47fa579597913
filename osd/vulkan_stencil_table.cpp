#include <quadtri/osd/vulkan_stencil_table.h>

#include <stdexcept>
#include <string>

namespace quadtri {
inline namespace v0 {

namespace detail {

PooledTableBuffers::PooledTableBuffers(VulkanContext& ctx, int numSourceVertices, const std::vector<int>& offsets,
                                       const std::vector<int>& indices, const std::vector<int>& weightOffsets,
                                       const std::vector<float>& weights, const char* table)
    : device_(ctx.device()), numStencils_(int(weightOffsets.size())), numSourceVertices_(numSourceVertices) {
    if (offsets.size() != weightOffsets.size() + 1 || std::size_t(offsets.back()) != indices.size())
        throw std::invalid_argument(std::string("Vulkan") + table + ": inconsistent " + table + " arrays");
    constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    constexpr VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    offsets_ = DeviceBuffer(ctx, offsets.size() * sizeof(int), usage, local);
    indices_ = DeviceBuffer(ctx, indices.size() * sizeof(int), usage, local);
    weightOffsets_ = DeviceBuffer(ctx, weightOffsets.size() * sizeof(int), usage, local);
    weights_ = DeviceBuffer(ctx, weights.size() * sizeof(float), usage, local);
    upload(ctx, {
        {offsets_.buffer(), 0, offsets.data(), nullptr, offsets.size() * sizeof(int)},
        {indices_.buffer(), 0, indices.data(), nullptr, indices.size() * sizeof(int)},
        {weightOffsets_.buffer(), 0, weightOffsets.data(), nullptr, weightOffsets.size() * sizeof(int)},
        {weights_.buffer(), 0, weights.data(), nullptr, weights.size() * sizeof(float)},
    });
}

}  // namespace detail

}  // namespace v0
}  // namespace quadtri
