// The window's swapchain with a colour + depth render pass over its images, and the frame's
// command buffer and synchronization (one frame in flight: the viewer evaluates into buffers the
// previous frame drew from only after its fence). A frame can also copy its image out for a
// screenshot (docs/viewer.md, "A frame").
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <optional>
#include <vector>

#include <quadtri/osd/vulkan_context.h>
#include "osd/vulkan/vulkan_memory.h"

#include "tools/render/attachment.h"
#include "tools/render/image.h"

namespace quadtri::view {

class Swapchain {
public:
    // The render pass and sync objects; the swapchain itself on the first beginFrame.
    Swapchain(VulkanContext& ctx, VkSurfaceKHR surface);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    VkRenderPass renderPass() const { return renderPass_; }
    uint32_t imageCount() const { return uint32_t(images_.size()); }
    uint32_t minImageCount() const { return minImages_; }

    // Waits for the previous frame, (re)creates the swapchain at `size` when needed and acquires
    // an image; false when the window has no area (minimized) or the swapchain went out of date
    // (try again next frame).
    bool beginFrame(VkExtent2D size);
    VkExtent2D extent() const { return extent_; }
    // The frame's command buffer, begun, with the render pass begun on the acquired image.
    VkCommandBuffer commandBuffer() const { return cmd_; }
    void beginRenderPass(const std::array<float, 4>& background);
    // Ends the render pass, copies the image out when `screenshot` is set, submits, waits for the
    // device and presents. The screenshot's pixels are RGBA, row 0 at the top.
    void endFrame(render::Image* screenshot);

private:
    void createRenderPass();
    void createSwapchain(VkExtent2D size);
    void destroySwapchain() noexcept;
    void destroy() noexcept;
    void copyImage(render::Image& out);

    VulkanContext& ctx_;
    VkSurfaceKHR surface_;
    VkSurfaceFormatKHR format_{};
    VkFormat depthFormat_ = VK_FORMAT_UNDEFINED;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{0, 0};
    uint32_t minImages_ = 2;
    std::vector<VkImage> images_;
    std::vector<VkImageView> views_;
    std::vector<VkFramebuffer> framebuffers_;
    std::vector<VkSemaphore> renderDone_;  // per image: presentation waits on it
    render::ImageAttachment depth_;
    VkSemaphore acquired_ = VK_NULL_HANDLE;
    VkFence done_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    uint32_t image_ = 0;
    bool stale_ = true;  // the swapchain must be (re)created
    detail::DeviceBuffer readback_;
};

}  // namespace quadtri::view
