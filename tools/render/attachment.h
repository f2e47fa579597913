// The framebuffer pieces the offscreen target and the viewer's swapchain share: an image with its
// memory and view (a colour or depth attachment), a depth format, and the one-subpass colour +
// depth render pass both draw in.
#pragma once

#include <vulkan/vulkan.h>

#include <quadtri/osd/vulkan_context.h>

namespace quadtri::render {

// A depth format the device can attach (D32_SFLOAT, else D24 + stencil, else D16).
VkFormat pickDepthFormat(VkPhysicalDevice physicalDevice);

struct ImageAttachment {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
};
// A 2D image of `extent` in device-local memory with a view of `aspect`; nothing is left behind
// when it throws.
ImageAttachment createImageAttachment(VulkanContext& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                                      VkImageAspectFlags aspect);
// Destroys what `attachment` holds (any of it may be null) and empties it.
void destroyImageAttachment(VkDevice device, ImageAttachment& attachment) noexcept;

// One subpass drawing into attachment 0 (colour: cleared, stored, then in `colorFinalLayout`)
// with attachment 1 as its depth (cleared, discarded), and the caller's subpass dependencies.
VkRenderPass createColorDepthRenderPass(VkDevice device, VkFormat colorFormat, VkImageLayout colorFinalLayout,
                                        VkFormat depthFormat, const VkSubpassDependency* dependencies,
                                        uint32_t numDependencies);

}  // namespace quadtri::render
