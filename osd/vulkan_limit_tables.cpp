#include <quadtri/osd/vulkan_limit_tables.h>

#include <stdexcept>
#include <vector>

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

VulkanMeshNormalTable::VulkanMeshNormalTable(VulkanContext& ctx, const MeshNormalTable& t)
    : device_(ctx.device()), numVertices_(t.numVertices) {
    if (t.offsets.size() != std::size_t(t.numVertices) + 1 || 3 * std::size_t(t.offsets.back()) != t.corners.size())
        throw std::invalid_argument("VulkanMeshNormalTable: inconsistent MeshNormalTable arrays");
    detail::DeviceBuffer b[2];
    uploadAll(ctx, b, {t.offsets.data(), t.corners.data()},
              {t.offsets.size() * sizeof(int), t.corners.size() * sizeof(int)});
    offsets_ = std::move(b[0]), corners_ = std::move(b[1]);
}

}  // namespace v0
}  // namespace quadtri
