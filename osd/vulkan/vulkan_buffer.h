// Per-vertex float data in a device-local Vulkan storage buffer: numElements elements of
// `stride` floats each (element i at floats [i*stride, (i+1)*stride)).
#pragma once

#include <memory>

#include <vulkan/vulkan.h>

#include <quadtri/export.h>
#include <quadtri/osd/vulkan_context.h>

namespace quadtri {
inline namespace v0 {

class QUADTRI_API VulkanVertexBuffer {
public:
    // Zero-filled. Usable as a storage buffer, a vertex buffer, a transfer source/target and a
    // uniform texel buffer (texels()).
    static VulkanVertexBuffer create(VulkanContext& ctx, int numElements, int stride);
    ~VulkanVertexBuffer();
    VulkanVertexBuffer(VulkanVertexBuffer&&) noexcept;
    VulkanVertexBuffer& operator=(VulkanVertexBuffer&&) noexcept;

    // Copies `count` elements (count*stride floats) from host memory into elements
    // [start, start+count). Waits for the copy. std::invalid_argument when out of range.
    void updateData(const float* src, int start, int count);
    // Copies every element (numElements*stride floats) into host memory. Waits.
    void readBack(float* dst) const;

    VkBuffer buffer() const;
    // An R32_SFLOAT view of the whole buffer, through which the evaluators read it as a source
    // (faster on lavapipe: docs/decisions/0003-vulkan-on-lavapipe.md); VK_NULL_HANDLE when empty or past the context's
    // texelBufferLimit().
    VkBufferView texels() const;
    int numElements() const { return numElements_; }
    int stride() const { return stride_; }
    std::size_t numFloats() const { return std::size_t(numElements_) * std::size_t(stride_); }

private:
    VulkanVertexBuffer(VulkanContext& ctx, int numElements, int stride);
    VulkanContext* ctx_;
    int numElements_, stride_;
    struct Storage;  // the buffer and its texel view
    std::unique_ptr<Storage> storage_;
};

}  // namespace v0
}  // namespace quadtri
