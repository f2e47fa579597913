// Private helpers of the Vulkan evaluators (never installed): an owning VkBuffer + VkDeviceMemory, and copies
// between host memory and device buffers through a staging buffer.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include <quadtri/export.h>
#include <quadtri/osd/vulkan_context.h>

namespace quadtri {
inline namespace v0 {
namespace detail {

class QUADTRI_API DeviceBuffer {
public:
    DeviceBuffer() = default;
    // size 0 is rounded up to 4 bytes (Vulkan has no empty buffers).
    DeviceBuffer(VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags properties);
    ~DeviceBuffer() { reset(); }
    DeviceBuffer(DeviceBuffer&& other) noexcept { *this = std::move(other); }
    DeviceBuffer& operator=(DeviceBuffer&& other) noexcept;
    DeviceBuffer(const DeviceBuffer&) = delete;
    DeviceBuffer& operator=(const DeviceBuffer&) = delete;

    VkBuffer buffer() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    // Host pointer to the whole buffer (host-visible memory only); mapped on first call.
    void* map();
    void reset() noexcept;

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    void* mapped_ = nullptr;
};

// A VkBufferView over a whole buffer created with VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT: the
// shaders read the tables' pools through it (texelFetch), which lavapipe compiles to vector
// gathers where a storage-buffer load is a branch per lane (docs/decisions/0003-vulkan-on-lavapipe.md).
class QUADTRI_API TexelView {
public:
    TexelView() = default;
    TexelView(VulkanContext& ctx, const DeviceBuffer& buffer, VkFormat format);
    ~TexelView() { reset(); }
    TexelView(TexelView&& other) noexcept { *this = std::move(other); }
    TexelView& operator=(TexelView&& other) noexcept;
    TexelView(const TexelView&) = delete;
    TexelView& operator=(const TexelView&) = delete;

    VkBufferView view() const { return view_; }
    void reset() noexcept;

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkBufferView view_ = VK_NULL_HANDLE;
};

// One host <-> device copy: `bytes` bytes between host memory and buffer at byte `offset`.
struct CopyRegion {
    VkBuffer buffer;
    VkDeviceSize offset;
    const void* source;  // upload: host data
    void* target;        // download: host destination
    VkDeviceSize bytes;
};

// Uploads every region's `source` (one staging buffer, one submission, waited on) and makes the
// writes visible to later compute-shader and transfer reads.
QUADTRI_API void upload(VulkanContext& ctx, const std::vector<CopyRegion>& regions);
// Copies every region into its `target`, waiting for the device.
QUADTRI_API void download(VulkanContext& ctx, const std::vector<CopyRegion>& regions);

// A small buffer with R32_SINT, R32_UINT and R32_SFLOAT texel views over it: bound where an evaluation has
// no buffer or view of its own for a binding (a table whose pools have no texel views, an absent
// output), since every binding of a descriptor set must name something.
struct UnusedBindings {
    UnusedBindings(VulkanContext& ctx, VkBufferUsageFlags usage);
    DeviceBuffer buffer;
    TexelView indexTexels, uintTexels, floatTexels;
};

// Makes transfer writes (copies, fills) visible to later compute-shader and transfer access.
QUADTRI_API void barrierAfterTransferWrite(VkCommandBuffer cmd);

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
