#include "osd/vulkan/vulkan_memory.h"

#include <cstring>
#include <utility>

namespace quadtri {
inline namespace v0 {
namespace detail {

DeviceBuffer::DeviceBuffer(VulkanContext& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                           VkMemoryPropertyFlags properties)
    : device_(ctx.device()), size_(size < 4 ? 4 : size) {
    auto bi = detail::vkStruct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    bi.size = size_;
    bi.usage = usage;
    bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    vkCheck(vkCreateBuffer(device_, &bi, nullptr, &buffer_), "vkCreateBuffer");
    try {
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device_, buffer_, &req);
        auto ai = detail::vkStruct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, properties);
        vkCheck(vkAllocateMemory(device_, &ai, nullptr, &memory_), "vkAllocateMemory");
        vkCheck(vkBindBufferMemory(device_, buffer_, memory_, 0), "vkBindBufferMemory");
    } catch (...) {
        reset();
        throw;
    }
}

DeviceBuffer& DeviceBuffer::operator=(DeviceBuffer&& other) noexcept {
    if (this != &other) {
        reset();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        mapped_ = std::exchange(other.mapped_, nullptr);
    }
    return *this;
}

void* DeviceBuffer::map() {
    if (!mapped_) vkCheck(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
    return mapped_;
}

void DeviceBuffer::reset() noexcept {
    if (!device_) return;
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    if (memory_) vkFreeMemory(device_, memory_, nullptr);  // unmaps implicitly
    buffer_ = VK_NULL_HANDLE, memory_ = VK_NULL_HANDLE, mapped_ = nullptr, size_ = 0, device_ = VK_NULL_HANDLE;
}

TexelView::TexelView(VulkanContext& ctx, const DeviceBuffer& buffer, VkFormat format) : device_(ctx.device()) {
    auto vi = detail::vkStruct<VkBufferViewCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO);
    vi.buffer = buffer.buffer();
    vi.format = format;
    vi.offset = 0;
    vi.range = VK_WHOLE_SIZE;
    vkCheck(vkCreateBufferView(device_, &vi, nullptr, &view_), "vkCreateBufferView");
}

TexelView& TexelView::operator=(TexelView&& other) noexcept {
    if (this != &other) {
        reset();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    }
    return *this;
}

void TexelView::reset() noexcept {
    if (device_ && view_) vkDestroyBufferView(device_, view_, nullptr);
    view_ = VK_NULL_HANDLE, device_ = VK_NULL_HANDLE;
}

namespace {

constexpr VkMemoryPropertyFlags kHostMemory = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;

VkDeviceSize totalBytes(const std::vector<CopyRegion>& regions) {
    VkDeviceSize total = 0;
    for (const auto& r : regions) total += r.bytes;
    return total;
}

}  // namespace

void upload(VulkanContext& ctx, const std::vector<CopyRegion>& regions) {
    DeviceBuffer staging(ctx, totalBytes(regions), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, kHostMemory);
    auto* bytes = static_cast<unsigned char*>(staging.map());
    VkDeviceSize at = 0;
    for (const auto& r : regions) {
        if (r.bytes) std::memcpy(bytes + at, r.source, r.bytes);
        at += r.bytes;
    }
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        VkDeviceSize from = 0;
        for (const auto& r : regions) {
            if (r.bytes) {
                const VkBufferCopy copy{from, r.offset, r.bytes};
                vkCmdCopyBuffer(cmd, staging.buffer(), r.buffer, 1, &copy);
            }
            from += r.bytes;
        }
        barrierAfterTransferWrite(cmd);
    });
}

void barrierAfterTransferWrite(VkCommandBuffer cmd) {
    auto barrier = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask =
        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0, nullptr,
                         0, nullptr);
}

void download(VulkanContext& ctx, const std::vector<CopyRegion>& regions) {
    DeviceBuffer staging(ctx, totalBytes(regions), VK_BUFFER_USAGE_TRANSFER_DST_BIT, kHostMemory);
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        VkDeviceSize to = 0;
        for (const auto& r : regions) {
            if (r.bytes) {
                const VkBufferCopy copy{r.offset, to, r.bytes};
                vkCmdCopyBuffer(cmd, r.buffer, staging.buffer(), 1, &copy);
            }
            to += r.bytes;
        }
        auto barrier = detail::vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr,
                             0, nullptr);
    });
    const auto* bytes = static_cast<const unsigned char*>(staging.map());
    VkDeviceSize at = 0;
    for (const auto& r : regions) {
        if (r.bytes) std::memcpy(r.target, bytes + at, r.bytes);
        at += r.bytes;
    }
}

UnusedBindings::UnusedBindings(VulkanContext& ctx, VkBufferUsageFlags usage)
    : buffer(ctx, 16, usage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT),
      indexTexels(ctx, buffer, VK_FORMAT_R32_SINT), uintTexels(ctx, buffer, VK_FORMAT_R32_UINT),
      floatTexels(ctx, buffer, VK_FORMAT_R32_SFLOAT) {}

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
