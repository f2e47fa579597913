#include <quadtri/osd/vulkan_buffer.h>

#include <stdexcept>
#include <string>

#include "osd/vulkan/vulkan_memory.h"

namespace quadtri {
inline namespace v0 {

struct VulkanVertexBuffer::Storage {
    detail::DeviceBuffer buffer;
    detail::TexelView texels;
};

VulkanVertexBuffer VulkanVertexBuffer::create(VulkanContext& ctx, int numElements, int stride) {
    if (numElements < 0 || stride <= 0)
        throw std::invalid_argument("VulkanVertexBuffer: need numElements >= 0 and stride > 0, got " +
                                    std::to_string(numElements) + " and " + std::to_string(stride));
    return VulkanVertexBuffer(ctx, numElements, stride);
}

VulkanVertexBuffer::VulkanVertexBuffer(VulkanContext& ctx, int numElements, int stride)
    : ctx_(&ctx), numElements_(numElements), stride_(stride),
      storage_(new Storage{detail::DeviceBuffer(ctx, numFloats() * sizeof(float),
                                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                                                    VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                                                    VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                                                VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT),
                           {}}) {
    if (numFloats() > 0 && numFloats() <= ctx.texelBufferLimit())
        storage_->texels = detail::TexelView(ctx, storage_->buffer, VK_FORMAT_R32_SFLOAT);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, buffer(), 0, VK_WHOLE_SIZE, 0);
        detail::barrierAfterTransferWrite(cmd);
    });
}

VulkanVertexBuffer::~VulkanVertexBuffer() = default;
VulkanVertexBuffer::VulkanVertexBuffer(VulkanVertexBuffer&&) noexcept = default;
VulkanVertexBuffer& VulkanVertexBuffer::operator=(VulkanVertexBuffer&&) noexcept = default;

VkBuffer VulkanVertexBuffer::buffer() const { return storage_ ? storage_->buffer.buffer() : VK_NULL_HANDLE; }
VkBufferView VulkanVertexBuffer::texels() const { return storage_ ? storage_->texels.view() : VK_NULL_HANDLE; }

void VulkanVertexBuffer::updateData(const float* src, int start, int count) {
    if (start < 0 || count < 0 || start + count > numElements_)
        throw std::invalid_argument("VulkanVertexBuffer::updateData: elements [" + std::to_string(start) + ", " +
                                    std::to_string(start + count) + ") outside the buffer's " +
                                    std::to_string(numElements_));
    if (count == 0) return;
    if (!src) throw std::invalid_argument("VulkanVertexBuffer::updateData: null source");
    const VkDeviceSize elementBytes = VkDeviceSize(stride_) * sizeof(float);
    detail::upload(*ctx_, {{buffer(), VkDeviceSize(start) * elementBytes, src, nullptr,
                            VkDeviceSize(count) * elementBytes}});
}

void VulkanVertexBuffer::readBack(float* dst) const {
    if (numFloats() == 0) return;
    if (!dst) throw std::invalid_argument("VulkanVertexBuffer::readBack: null destination");
    detail::download(*ctx_, {{buffer(), 0, nullptr, dst, numFloats() * sizeof(float)}});
}

}  // namespace v0
}  // namespace quadtri
