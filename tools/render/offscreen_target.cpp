#include "tools/render/offscreen_target.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace quadtri::render {

using detail::vkStruct;

OffscreenTarget::OffscreenTarget(VulkanContext& ctx, uint32_t width, uint32_t height)
    : ctx_(ctx), width_(width), height_(height), depthFormat_(pickDepthFormat(ctx.physicalDevice())) {
    const VkPhysicalDeviceLimits& limits = ctx_.properties().limits;
    const uint32_t largest =
        std::min({limits.maxImageDimension2D, limits.maxFramebufferWidth, limits.maxFramebufferHeight});
    if (width == 0 || height == 0 || width > largest || height > largest)
        throw VulkanError("an image of " + std::to_string(width) + "x" + std::to_string(height) +
                          " pixels: the Vulkan device draws 1 to " + std::to_string(largest) + " per side");
    try {
        const VkExtent2D extent{width_, height_};
        color_ = createImageAttachment(ctx_, extent, kColorFormat,
                                       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                       VK_IMAGE_ASPECT_COLOR_BIT);
        depth_ = createImageAttachment(ctx_, extent, depthFormat_, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                       VK_IMAGE_ASPECT_DEPTH_BIT);
        createRenderPass();
        const VkImageView views[2] = {color_.view, depth_.view};
        auto fb = vkStruct<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
        fb.renderPass = renderPass_;
        fb.attachmentCount = 2;
        fb.pAttachments = views;
        fb.width = width_;
        fb.height = height_;
        fb.layers = 1;
        vkCheck(vkCreateFramebuffer(ctx_.device(), &fb, nullptr, &framebuffer_), "vkCreateFramebuffer");
        readback_ = detail::DeviceBuffer(ctx_, VkDeviceSize(width_) * height_ * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                         VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    } catch (...) {
        destroy();
        throw;
    }
}

OffscreenTarget::~OffscreenTarget() { destroy(); }

void OffscreenTarget::createRenderPass() {
    // Earlier compute writes (the evaluators' outputs) are read by the vertex shader; the colour
    // writes are copied out after the pass.
    VkSubpassDependency deps[2] = {};
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                           VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    deps[0].dstStageMask = VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT |
                           VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
    deps[0].srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT |
                            VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    deps[0].dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                            VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    deps[1].srcSubpass = 0;
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    renderPass_ = createColorDepthRenderPass(ctx_.device(), kColorFormat, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                             depthFormat_, deps, 2);
}

Image OffscreenTarget::render(const std::array<float, 4>& background,
                              const std::function<void(VkCommandBuffer, VkExtent2D)>& draw,
                              const std::function<void(VkCommandBuffer)>& beforePass) {
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        if (beforePass) beforePass(cmd);
        VkClearValue clears[2];
        std::memcpy(clears[0].color.float32, background.data(), sizeof(float) * 4);
        clears[1].depthStencil = {1.0f, 0};
        auto begin = vkStruct<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
        begin.renderPass = renderPass_;
        begin.framebuffer = framebuffer_;
        begin.renderArea = {{0, 0}, extent()};
        begin.clearValueCount = 2;
        begin.pClearValues = clears;
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        draw(cmd, extent());
        vkCmdEndRenderPass(cmd);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {width_, height_, 1};
        vkCmdCopyImageToBuffer(cmd, color_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer(), 1, &copy);
        auto barrier = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                             nullptr, 0, nullptr);
    });
    Image image{int(width_), int(height_), std::vector<uint8_t>(std::size_t(width_) * height_ * 4)};
    std::memcpy(image.rgba.data(), readback_.map(), image.rgba.size());
    return image;
}

void OffscreenTarget::destroy() noexcept {
    VkDevice device = ctx_.device();
    readback_.reset();
    if (framebuffer_) vkDestroyFramebuffer(device, framebuffer_, nullptr);
    if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
    destroyImageAttachment(device, color_);
    destroyImageAttachment(device, depth_);
    framebuffer_ = VK_NULL_HANDLE, renderPass_ = VK_NULL_HANDLE;
}

}  // namespace quadtri::render
