#include <quadtri/osd/vulkan_limit_tables.h>

#include <stdexcept>
#include <vector>

#include "osd/vulkan/vulkan_memory.h"

namespace quadtri {
inline namespace v0 {

namespace {

constexpr VkBufferUsageFlags kUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkMemoryPropertyFlags kLocal = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;

// Arrays (data, bytes) into device buffers of their own, one staging copy.
template <std::size_t N>
void uploadAll(VulkanContext& ctx, detail::DeviceBuffer (&to)[N], const void* const (&data)[N],
               const std::size_t (&bytes)[N]) {
    std::vector<detail::CopyRegion> regions;
    for (std::size_t k = 0; k < N; ++k) {
        to[k] = detail::DeviceBuffer(ctx, bytes[k], kUsage, kLocal);
        if (bytes[k]) regions.push_back({to[k].buffer(), 0, data[k], nullptr, bytes[k]});
    }
    detail::upload(ctx, regions);
}

}  // namespace

struct VulkanMeshNormalTable::Arrays {
    detail::DeviceBuffer buffers[4];
};

VulkanMeshNormalTable::VulkanMeshNormalTable(VulkanContext& ctx, const MeshNormalTable& t)
    : device_(ctx.device()), numVertices_(t.numVertices), arrays_(std::make_unique<Arrays>()) {
    if (t.faceOffsets.empty() || std::size_t(t.faceOffsets.back()) != t.faceCorners.size() ||
        t.vertexFaceOffsets.size() != std::size_t(t.numVertices) + 1 ||
        std::size_t(t.vertexFaceOffsets.back()) != t.vertexFaces.size())
        throw std::invalid_argument("VulkanMeshNormalTable: inconsistent MeshNormalTable arrays");
    const std::vector<int>* arrays[4] = {&t.faceOffsets, &t.faceCorners, &t.vertexFaceOffsets, &t.vertexFaces};
    uploadAll(ctx, arrays_->buffers, {arrays[0]->data(), arrays[1]->data(), arrays[2]->data(), arrays[3]->data()},
              {arrays[0]->size() * sizeof(int), arrays[1]->size() * sizeof(int), arrays[2]->size() * sizeof(int),
               arrays[3]->size() * sizeof(int)});
    for (int k = 0; k < 4; ++k) handles_[k] = arrays_->buffers[k].buffer();
}

VulkanMeshNormalTable::~VulkanMeshNormalTable() = default;
VulkanMeshNormalTable::VulkanMeshNormalTable(VulkanMeshNormalTable&&) noexcept = default;
VulkanMeshNormalTable& VulkanMeshNormalTable::operator=(VulkanMeshNormalTable&&) noexcept = default;

}  // namespace v0
}  // namespace quadtri
