// An offscreen colour (RGBA8) + depth target with its render pass and framebuffer, and the
// read-back of a rendered frame into host memory: what `quadtri render` and the tests draw into
// (the viewer draws into its swapchain images with the same Renderer instead).
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <quadtri/osd/vulkan_context.h>
#include "osd/vulkan/vulkan_memory.h"

#include "tools/render/attachment.h"
#include "tools/render/image.h"

namespace quadtri::render {

class OffscreenTarget {
public:
    static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;

    OffscreenTarget(VulkanContext& ctx, uint32_t width, uint32_t height);
    ~OffscreenTarget();
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;

    // Colour cleared, stored and left ready to copy; depth cleared and discarded.
    VkRenderPass renderPass() const { return renderPass_; }
    VkFormat depthFormat() const { return depthFormat_; }
    VkExtent2D extent() const { return {width_, height_}; }

    // Records `beforePass` (if set: e.g. the frame's evaluation), begins the render pass
    // (clearing to `background`, RGBA in 0..1), lets `draw` record inside it, ends it, copies the
    // colour image out, submits it all at once, waits and returns the pixels, row 0 at the top.
    Image render(const std::array<float, 4>& background, const std::function<void(VkCommandBuffer, VkExtent2D)>& draw,
                 const std::function<void(VkCommandBuffer)>& beforePass = {});

private:
    void createRenderPass();
    void destroy() noexcept;

    VulkanContext& ctx_;
    uint32_t width_, height_;
    VkFormat depthFormat_;
    ImageAttachment color_, depth_;
    VkRenderPass renderPass_ = VK_NULL_HANDLE;
    VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
    detail::DeviceBuffer readback_;
};

}  // namespace quadtri::render
