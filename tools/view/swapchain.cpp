#include "tools/view/swapchain.h"

#include <algorithm>
#include <cstring>

#include "tools/render/attachment.h"

namespace quadtri::view {

using detail::vkStruct;

namespace {

// UNORM, not sRGB: the same colours as the offscreen renderer's RGBA8 target.
VkSurfaceFormatKHR pickFormat(VkPhysicalDevice pd, VkSurfaceKHR surface) {
    uint32_t n = 0;
    vkCheck(vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface, &n, nullptr), "vkGetPhysicalDeviceSurfaceFormatsKHR");
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkCheck(vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface, &n, formats.data()), "vkGetPhysicalDeviceSurfaceFormatsKHR");
    if (formats.empty()) throw VulkanError("the window's surface offers no image format");
    for (const VkSurfaceFormatKHR& f : formats)
        if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) return f;
    return formats[0];
}

}  // namespace

Swapchain::Swapchain(VulkanContext& ctx, VkSurfaceKHR surface) : ctx_(ctx), surface_(surface) {
    try {
        format_ = pickFormat(ctx.physicalDevice(), surface);
        depthFormat_ = render::pickDepthFormat(ctx.physicalDevice());
        createRenderPass();
        auto si = vkStruct<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
        vkCheck(vkCreateSemaphore(ctx.device(), &si, nullptr, &acquired_), "vkCreateSemaphore");
        auto fi = vkStruct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
        fi.flags = VK_FENCE_CREATE_SIGNALED_BIT;
        vkCheck(vkCreateFence(ctx.device(), &fi, nullptr, &done_), "vkCreateFence");
        auto pi = vkStruct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
        pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pi.queueFamilyIndex = ctx.queueFamilyIndex();
        vkCheck(vkCreateCommandPool(ctx.device(), &pi, nullptr, &pool_), "vkCreateCommandPool");
        auto ai = vkStruct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
        ai.commandPool = pool_;
        ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        ai.commandBufferCount = 1;
        vkCheck(vkAllocateCommandBuffers(ctx.device(), &ai, &cmd_), "vkAllocateCommandBuffers");
    } catch (...) {
        destroy();
        throw;
    }
}

Swapchain::~Swapchain() { destroy(); }

void Swapchain::createRenderPass() {
    // The acquire semaphore is waited on at colour output: the layout change waits for it too;
    // the depth image is reused each frame.
    VkSubpassDependency dependency{};
    dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
    dependency.dstSubpass = 0;
    dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT;
    dependency.srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    renderPass_ = render::createColorDepthRenderPass(ctx_.device(), format_.format, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                                                     depthFormat_, &dependency, 1);
}

void Swapchain::createSwapchain(VkExtent2D size) {
    VkDevice device = ctx_.device();
    VkSurfaceCapabilitiesKHR caps;
    vkCheck(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physicalDevice(), surface_, &caps),
            "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT))
        throw VulkanError("the window's swapchain images cannot be copied from (no screenshots)");
    extent_ = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : size;
    extent_.width = std::clamp(extent_.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height = std::clamp(extent_.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    minImages_ = std::max(caps.minImageCount, 2u);
    if (caps.maxImageCount) minImages_ = std::min(minImages_, caps.maxImageCount);

    auto info = vkStruct<VkSwapchainCreateInfoKHR>(VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR);
    info.surface = surface_;
    info.minImageCount = minImages_;
    info.imageFormat = format_.format;
    info.imageColorSpace = format_.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & info.compositeAlpha))
        info.compositeAlpha = VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always available
    info.clipped = VK_TRUE;
    vkCheck(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain_), "vkCreateSwapchainKHR");
    uint32_t n = 0;
    vkCheck(vkGetSwapchainImagesKHR(device, swapchain_, &n, nullptr), "vkGetSwapchainImagesKHR");
    images_.resize(n);
    vkCheck(vkGetSwapchainImagesKHR(device, swapchain_, &n, images_.data()), "vkGetSwapchainImagesKHR");

    depth_ = render::createImageAttachment(ctx_, extent_, depthFormat_, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                           VK_IMAGE_ASPECT_DEPTH_BIT);
    auto vi = vkStruct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format_.format;
    vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    for (VkImage image : images_) {
        vi.image = image;
        views_.push_back(VK_NULL_HANDLE);
        vkCheck(vkCreateImageView(device, &vi, nullptr, &views_.back()), "vkCreateImageView");
        const VkImageView attachments[2] = {views_.back(), depth_.view};
        auto fb = vkStruct<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
        fb.renderPass = renderPass_;
        fb.attachmentCount = 2;
        fb.pAttachments = attachments;
        fb.width = extent_.width;
        fb.height = extent_.height;
        fb.layers = 1;
        framebuffers_.push_back(VK_NULL_HANDLE);
        vkCheck(vkCreateFramebuffer(device, &fb, nullptr, &framebuffers_.back()), "vkCreateFramebuffer");
        auto si = vkStruct<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
        renderDone_.push_back(VK_NULL_HANDLE);
        vkCheck(vkCreateSemaphore(device, &si, nullptr, &renderDone_.back()), "vkCreateSemaphore");
    }
    readback_ = detail::DeviceBuffer(ctx_, VkDeviceSize(extent_.width) * extent_.height * 4,
                                     VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                     VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    stale_ = false;
}

void Swapchain::destroySwapchain() noexcept {
    VkDevice device = ctx_.device();
    for (VkFramebuffer fb : framebuffers_) vkDestroyFramebuffer(device, fb, nullptr);
    for (VkImageView v : views_) vkDestroyImageView(device, v, nullptr);
    for (VkSemaphore s : renderDone_) vkDestroySemaphore(device, s, nullptr);
    framebuffers_.clear(), views_.clear(), renderDone_.clear(), images_.clear();
    render::destroyImageAttachment(device, depth_);
    if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
    readback_ = detail::DeviceBuffer();
}

void Swapchain::destroy() noexcept {
    VkDevice device = ctx_.device();
    vkDeviceWaitIdle(device);
    destroySwapchain();
    if (pool_) vkDestroyCommandPool(device, pool_, nullptr);
    if (done_) vkDestroyFence(device, done_, nullptr);
    if (acquired_) vkDestroySemaphore(device, acquired_, nullptr);
    if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
    pool_ = VK_NULL_HANDLE, done_ = VK_NULL_HANDLE, acquired_ = VK_NULL_HANDLE, renderPass_ = VK_NULL_HANDLE;
}

bool Swapchain::beginFrame(VkExtent2D size) {
    VkDevice device = ctx_.device();
    vkCheck(vkWaitForFences(device, 1, &done_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    if (size.width == 0 || size.height == 0) return false;
    if (stale_ || size.width != extent_.width || size.height != extent_.height) {
        vkCheck(vkDeviceWaitIdle(device), "vkDeviceWaitIdle");
        destroySwapchain();
        createSwapchain(size);
    }
    const VkResult r = vkAcquireNextImageKHR(device, swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &image_);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        stale_ = true;
        return false;
    }
    if (r != VK_SUBOPTIMAL_KHR) vkCheck(r, "vkAcquireNextImageKHR");
    vkCheck(vkResetFences(device, 1, &done_), "vkResetFences");
    vkCheck(vkResetCommandBuffer(cmd_, 0), "vkResetCommandBuffer");
    auto bi = vkStruct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkCheck(vkBeginCommandBuffer(cmd_, &bi), "vkBeginCommandBuffer");
    return true;
}

void Swapchain::beginRenderPass(const std::array<float, 4>& background) {
    VkClearValue clears[2]{};
    std::memcpy(clears[0].color.float32, background.data(), sizeof(float) * 4);
    clears[1].depthStencil = {1.0f, 0};
    auto rp = vkStruct<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
    rp.renderPass = renderPass_;
    rp.framebuffer = framebuffers_[image_];
    rp.renderArea = {{0, 0}, extent_};
    rp.clearValueCount = 2;
    rp.pClearValues = clears;
    vkCmdBeginRenderPass(cmd_, &rp, VK_SUBPASS_CONTENTS_INLINE);
}

void Swapchain::endFrame(render::Image* screenshot) {
    vkCmdEndRenderPass(cmd_);
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    if (screenshot) {
        auto barrier = vkStruct<VkImageMemoryBarrier>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER);
        barrier.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        barrier.oldLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        barrier.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = images_[image_];
        barrier.subresourceRange = range;
        vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0,
                             nullptr, 0, nullptr, 1, &barrier);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {extent_.width, extent_.height, 1};
        vkCmdCopyImageToBuffer(cmd_, images_[image_], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer(), 1, &copy);
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
        barrier.dstAccessMask = 0;
        barrier.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        barrier.newLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
        vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0, 0, nullptr,
                             0, nullptr, 1, &barrier);
        auto host = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
        host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, nullptr,
                             0, nullptr);
    }
    vkCheck(vkEndCommandBuffer(cmd_), "vkEndCommandBuffer");
    const VkPipelineStageFlags wait = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    auto submit = vkStruct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &acquired_;
    submit.pWaitDstStageMask = &wait;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd_;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &renderDone_[image_];
    vkCheck(vkQueueSubmit(ctx_.queue(), 1, &submit, done_), "vkQueueSubmit");
    auto present = vkStruct<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &renderDone_[image_];
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain_;
    present.pImageIndices = &image_;
    const VkResult r = vkQueuePresentKHR(ctx_.queue(), &present);
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR)
        stale_ = true;
    else
        vkCheck(r, "vkQueuePresentKHR");
    vkCheck(vkWaitForFences(ctx_.device(), 1, &done_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    if (screenshot) copyImage(*screenshot);
}

void Swapchain::copyImage(render::Image& out) {
    out.width = int(extent_.width);
    out.height = int(extent_.height);
    out.rgba.resize(std::size_t(out.width) * std::size_t(out.height) * 4);
    std::memcpy(out.rgba.data(), readback_.map(), out.rgba.size());
    const bool bgra = format_.format == VK_FORMAT_B8G8R8A8_UNORM || format_.format == VK_FORMAT_B8G8R8A8_SRGB;
    for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
        if (bgra) std::swap(out.rgba[i], out.rgba[i + 2]);
        out.rgba[i + 3] = 255;
    }
}

}  // namespace quadtri::view
