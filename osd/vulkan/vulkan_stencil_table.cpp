#include <quadtri/osd/vulkan_stencil_table.h>

#include <algorithm>
#include <cstdint>
#include <utility>
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
    // Elements of each pool on the device, and the room its buffer has.
    std::size_t indicesUsed = 0, weightsUsed = 0, indicesRoom = 0, weightsRoom = 0;
};

namespace {

std::size_t roomFor(std::size_t used, bool roomToGrow) { return roomToGrow ? used + std::max<std::size_t>(used / 2, 16384) : used; }

}  // namespace

VulkanPooledTable::VulkanPooledTable(VulkanContext& ctx, const HostArrays& a, const char* table)
    : buffers_(new Buffers{ctx.device(), int(a.weightOffsets.size()), a.numSourceVertices, {}, {}, {}, {}, {}, {}, {}}) {
    if (!consistent(a)) throw std::invalid_argument(std::string("Vulkan") + table + ": inconsistent " + table + " arrays");
    Buffers& b = *buffers_;
    constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    constexpr VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    constexpr VkBufferUsageFlags pool = usage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    auto add = [&](detail::DeviceBuffer& to, const void* data, std::size_t bytes, std::vector<detail::CopyRegion>& regions,
                   std::size_t room) {
        to = detail::DeviceBuffer(ctx, std::max(bytes, room), &to == &b.indices || &to == &b.weights ? pool : usage, local);
        regions.push_back({to.buffer(), 0, data, nullptr, bytes});
    };
    b.indicesUsed = a.indices.size(), b.weightsUsed = a.weights.size();
    b.indicesRoom = roomFor(b.indicesUsed, a.roomToGrow && a.sizes), b.weightsRoom = roomFor(b.weightsUsed, a.roomToGrow);
    std::vector<detail::CopyRegion> regions;
    if (a.sizes) add(b.sizes, a.sizes->data(), a.sizes->size() * sizeof(int), regions, 0);
    add(b.offsets, a.offsets.data(), a.offsets.size() * sizeof(int), regions, 0);
    add(b.indices, a.indices.data(), a.indices.size() * sizeof(int), regions, b.indicesRoom * sizeof(int));
    add(b.weightOffsets, a.weightOffsets.data(), a.weightOffsets.size() * sizeof(int), regions, 0);
    add(b.weights, a.weights.data(), a.weights.size() * sizeof(float), regions, b.weightsRoom * sizeof(float));
    detail::upload(ctx, regions);
    // Texel views only where the device's limit allows them: the shaders read the storage
    // buffers otherwise.
    const std::size_t texels = ctx.texelBufferLimit();
    if (b.indicesRoom <= texels && b.weightsRoom <= texels) {
        b.indexTexels = detail::TexelView(ctx, b.indices, VK_FORMAT_R32_SINT);
        b.weightTexels = detail::TexelView(ctx, b.weights, VK_FORMAT_R32_SFLOAT);
    }
}

bool VulkanPooledTable::updateStencils(VulkanContext& ctx, const HostArrays& a, const std::vector<int>& stencils) {
    if (!buffers_) return false;
    Buffers& b = *buffers_;
    // A limit table's runs are a pool that may grow at its end; a CSR table's entries must stay put.
    const bool csr = a.sizes == nullptr;
    if (int(a.weightOffsets.size()) != b.numStencils ||
        a.offsets.size() != a.weightOffsets.size() + (csr ? 1 : 0) || (a.sizes && a.sizes->size() != a.weightOffsets.size()) ||
        (csr ? a.indices.size() != b.indicesUsed : a.indices.size() < b.indicesUsed) || a.weights.size() < b.weightsUsed ||
        a.indices.size() > b.indicesRoom || a.weights.size() > b.weightsRoom)
        return false;
    auto sizeOf = [&](int i) { return csr ? a.offsets[std::size_t(i) + 1] - a.offsets[std::size_t(i)] : (*a.sizes)[std::size_t(i)]; };
    for (int i : stencils) {
        if (i < 0 || i >= b.numStencils)
            throw std::invalid_argument("VulkanPooledTable: stencil " + std::to_string(i) + " out of range");
        const std::int64_t first = a.offsets[std::size_t(i)], size = sizeOf(i), weights = a.weightOffsets[std::size_t(i)];
        if (first < 0 || size < 0 || first + size > std::int64_t(a.indices.size()) || weights < 0 ||
            weights + a.weightsPerEntry * size > std::int64_t(a.weights.size()))
            throw std::invalid_argument("VulkanPooledTable: stencil " + std::to_string(i) + " reaches outside its arrays");
    }
    std::vector<detail::CopyRegion> regions;
    auto range = [&](const detail::DeviceBuffer& to, const auto* data, std::size_t from, std::size_t until) {
        if (until > from)
            regions.push_back({to.buffer(), from * sizeof(*data), data + from, nullptr, (until - from) * sizeof(*data)});
    };
    if (!csr) range(b.indices, a.indices.data(), b.indicesUsed, a.indices.size());
    range(b.weights, a.weights.data(), b.weightsUsed, a.weights.size());
    // Each run of consecutive stencils in one region per array.
    for (std::size_t k = 0; k < stencils.size();) {
        std::size_t end = k + 1;
        while (end < stencils.size() && stencils[end] == stencils[end - 1] + 1) ++end;
        const std::size_t first = std::size_t(stencils[k]), last = std::size_t(stencils[end - 1]) + 1;
        range(b.weightOffsets, a.weightOffsets.data(), first, last);
        if (csr) {
            range(b.indices, a.indices.data(), std::size_t(a.offsets[first]), std::size_t(a.offsets[last]));
        } else {
            range(b.sizes, a.sizes->data(), first, last);
            range(b.offsets, a.offsets.data(), first, last);
        }
        k = end;
    }
    if (!regions.empty()) detail::upload(ctx, regions);
    b.indicesUsed = a.indices.size(), b.weightsUsed = a.weights.size();
    return true;
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
