#include <quadtri/osd/vulkan_stencil_table.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace quadtri {
inline namespace v0 {

namespace detail {

namespace {

// Whether every stencil's entries and weights lie inside the arrays the device will read: the
// shader has no bounds of its own to check against.
bool consistent(const PooledTableBuffers::HostArrays& a) {
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

PooledTableBuffers::PooledTableBuffers(VulkanContext& ctx, const HostArrays& a, const char* table)
    : device_(ctx.device()), numStencils_(int(a.weightOffsets.size())), numSourceVertices_(a.numSourceVertices) {
    if (!consistent(a)) throw std::invalid_argument(std::string("Vulkan") + table + ": inconsistent " + table + " arrays");
    constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    constexpr VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    constexpr VkBufferUsageFlags pool = usage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
    auto add = [&](DeviceBuffer& to, const void* data, std::size_t bytes, std::vector<CopyRegion>& regions) {
        to = DeviceBuffer(ctx, bytes, &to == &indices_ || &to == &weights_ ? pool : usage, local);
        regions.push_back({to.buffer(), 0, data, nullptr, bytes});
    };
    std::vector<CopyRegion> regions;
    if (a.sizes) add(sizes_, a.sizes->data(), a.sizes->size() * sizeof(int), regions);
    add(offsets_, a.offsets.data(), a.offsets.size() * sizeof(int), regions);
    add(indices_, a.indices.data(), a.indices.size() * sizeof(int), regions);
    add(weightOffsets_, a.weightOffsets.data(), a.weightOffsets.size() * sizeof(int), regions);
    add(weights_, a.weights.data(), a.weights.size() * sizeof(float), regions);
    detail::upload(ctx, regions);
    // Texel views only where the device's limit allows them: the shaders read the storage
    // buffers otherwise.
    const std::size_t texels = ctx.texelBufferLimit();
    if (a.indices.size() <= texels && a.weights.size() <= texels) {
        indexTexels_ = TexelView(ctx, indices_, VK_FORMAT_R32_SINT);
        weightTexels_ = TexelView(ctx, weights_, VK_FORMAT_R32_SFLOAT);
    }
}

}  // namespace detail

}  // namespace v0
}  // namespace quadtri
