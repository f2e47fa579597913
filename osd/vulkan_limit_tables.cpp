#include <quadtri/osd/vulkan_limit_tables.h>

#include <stdexcept>
#include <vector>

namespace quadtri {
inline namespace v0 {

namespace {

constexpr VkBufferUsageFlags kUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkMemoryPropertyFlags kLocal = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;

// Four arrays into their device buffers, one staging copy.
template <class A, class B, class C, class D>
void uploadFour(VulkanContext& ctx, detail::DeviceBuffer (&to)[4], const A& a, const B& b, const C& c, const D& d) {
    const void* data[4] = {a.data(), b.data(), c.data(), d.data()};
    const std::size_t bytes[4] = {a.size() * sizeof(a[0]), b.size() * sizeof(b[0]), c.size() * sizeof(c[0]),
                                  d.size() * sizeof(d[0])};
    std::vector<detail::CopyRegion> regions;
    for (int k = 0; k < 4; ++k) {
        to[k] = detail::DeviceBuffer(ctx, bytes[k], kUsage, kLocal);
        if (bytes[k]) regions.push_back({to[k].buffer(), 0, data[k], nullptr, bytes[k]});
    }
    detail::upload(ctx, regions);
}

}  // namespace

VulkanLimitStencilTable::VulkanLimitStencilTable(VulkanContext& ctx, const LimitStencilTable& t)
    : device_(ctx.device()), numStencils_(t.numStencils()), numSourceVertices_(t.numSourceVertices) {
    if (t.offsets.size() != t.weightOffsets.size() + 1 || std::size_t(t.offsets.back()) != t.indices.size())
        throw std::invalid_argument("VulkanLimitStencilTable: inconsistent LimitStencilTable arrays");
    detail::DeviceBuffer b[4];
    uploadFour(ctx, b, t.offsets, t.indices, t.weightOffsets, t.weights);
    offsets_ = std::move(b[0]), indices_ = std::move(b[1]), weightOffsets_ = std::move(b[2]), weights_ = std::move(b[3]);
}

VulkanMeshNormalTable::VulkanMeshNormalTable(VulkanContext& ctx, const MeshNormalTable& t)
    : device_(ctx.device()), numVertices_(t.numVertices) {
    if (t.vertexOffsets.size() != std::size_t(t.numVertices) + 1 ||
        std::size_t(t.vertexOffsets.back()) != t.vertexFaces.size() ||
        std::size_t(t.faceOffsets.back()) != t.faceVerts.size())
        throw std::invalid_argument("VulkanMeshNormalTable: inconsistent MeshNormalTable arrays");
    detail::DeviceBuffer b[4];
    uploadFour(ctx, b, t.vertexOffsets, t.vertexFaces, t.faceOffsets, t.faceVerts);
    vertexOffsets_ = std::move(b[0]), vertexFaces_ = std::move(b[1]), faceOffsets_ = std::move(b[2]),
    faceVerts_ = std::move(b[3]);
}

}  // namespace v0
}  // namespace quadtri
