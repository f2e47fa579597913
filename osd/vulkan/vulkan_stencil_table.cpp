#include <quadtri/osd/vulkan_stencil_table.h>

#include <cstdint>
#include <stdexcept>
#include <string>

#include "osd/vulkan/vulkan_memory.h"

namespace quadtri {
inline namespace v0 {

namespace {

// Whether every stencil's entries and weights lie inside the arrays the device will read: the
// shader has no bounds of its own to check against.
template <class HostArrays>
bool consistent(const HostArrays& a) {
    const std::size_t n = a.weightOffsets.size();
    if (a.sizes ? (a.sizes->size() != n || a.offsets.size() != n)
                : (a.offsets.size() != n + 1 || std::size_t(a.offsets.back()) != a.indices.size()))
        return false;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int64_t first = a.offsets[i], size = a.sizes ? (*a.sizes)[i] : a.offsets[i + 1] - first;
        const std::int64_t weights = a.weightOffsets[i];
        if (first < 0 || size < 0 || first + size > std::int64_t(a.indices.size()) || weights < 0 ||
            weights + a.weightsPerEntry * size > std::int64_t(a.weights.size()))
            return false;
    }
    return true;
}

}  // namespace

struct VulkanPooledTable::Buffers {
    VkDevice device;
    int numStencils, numSourceVertices;
    detail::DeviceBuffer sizes, offsets, indices, weightOffsets, weights;
    detail::TexelView indexTexels, weightTexels;
};

VulkanPooledTable::VulkanPooledTable(VulkanContext& ctx, const HostArrays& a, const char* table)
    : buffers_(new Buffers{ctx.device(), int(a.weightOffsets.size()), a.numSourceVertices, {}, {}, {}, {}, {}, {}, {}}) {
    if (!consistent(a)) throw std::invalid_argument(std::string("Vulkan") + table + ": inconsistent " + table + " arrays");
    Buffers& b = *buffers_;
    constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    constexpr VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    constexpr VkBufferUsageFlags pool = usage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    auto add = [&](detail::DeviceBuffer& to, const void* data, std::size_t bytes, std::vector<detail::CopyRegion>& regions) {
        to = detail::DeviceBuffer(ctx, bytes, &to == &b.indices || &to == &b.weights ? pool : usage, local);
        regions.push_back({to.buffer(), 0, data, nullptr, bytes});
    };
    std::vector<detail::CopyRegion> regions;
    if (a.sizes) add(b.sizes, a.sizes->data(), a.sizes->size() * sizeof(int), regions);
    add(b.offsets, a.offsets.data(), a.offsets.size() * sizeof(int), regions);
    add(b.indices, a.indices.data(), a.indices.size() * sizeof(int), regions);
    add(b.weightOffsets, a.weightOffsets.data(), a.weightOffsets.size() * sizeof(int), regions);
    add(b.weights, a.weights.data(), a.weights.size() * sizeof(float), regions);
    detail::upload(ctx, regions);
    // Texel views only where the device's limit allows them: the shaders read the storage
    // buffers otherwise.
    const std::size_t texels = ctx.texelBufferLimit();
    if (a.indices.size() <= texels && a.weights.size() <= texels) {
        b.indexTexels = detail::TexelView(ctx, b.indices, VK_FORMAT_R32_SINT);
        b.weightTexels = detail::TexelView(ctx, b.weights, VK_FORMAT_R32_SFLOAT);
    }
}

// A moved-from table reads as an empty one.
VulkanPooledTable::~VulkanPooledTable() = default;
VulkanPooledTable::VulkanPooledTable(VulkanPooledTable&&) noexcept = default;
VulkanPooledTable& VulkanPooledTable::operator=(VulkanPooledTable&&) noexcept = default;

int VulkanPooledTable::numStencils() const { return buffers_ ? buffers_->numStencils : 0; }
int VulkanPooledTable::numSourceVertices() const { return buffers_ ? buffers_->numSourceVertices : 0; }
VkBuffer VulkanPooledTable::sizes() const { return buffers_ ? buffers_->sizes.buffer() : VK_NULL_HANDLE; }
VkBuffer VulkanPooledTable::offsets() const { return buffers_ ? buffers_->offsets.buffer() : VK_NULL_HANDLE; }
VkBuffer VulkanPooledTable::indices() const { return buffers_ ? buffers_->indices.buffer() : VK_NULL_HANDLE; }
VkBuffer VulkanPooledTable::weightOffsets() const { return buffers_ ? buffers_->weightOffsets.buffer() : VK_NULL_HANDLE; }
VkBuffer VulkanPooledTable::weights() const { return buffers_ ? buffers_->weights.buffer() : VK_NULL_HANDLE; }
VkBufferView VulkanPooledTable::indexTexels() const { return buffers_ ? buffers_->indexTexels.view() : VK_NULL_HANDLE; }
VkBufferView VulkanPooledTable::weightTexels() const { return buffers_ ? buffers_->weightTexels.view() : VK_NULL_HANDLE; }
VkDevice VulkanPooledTable::device() const { return buffers_ ? buffers_->device : VK_NULL_HANDLE; }

}  // namespace v0
}  // namespace quadtri
