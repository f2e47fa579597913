#include "tools/render/attachment.h"

namespace quadtri::render {

using detail::vkStruct;

VkFormat pickDepthFormat(VkPhysicalDevice physicalDevice) {
    for (VkFormat f : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D16_UNORM}) {
        VkFormatProperties props;
        vkGetPhysicalDeviceFormatProperties(physicalDevice, f, &props);
        if (props.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return f;
    }
    throw VulkanError("the Vulkan device has no depth attachment format");
}

ImageAttachment createImageAttachment(VulkanContext& ctx, VkExtent2D extent, VkFormat format, VkImageUsageFlags usage,
                                      VkImageAspectFlags aspect) {
    ImageAttachment a;
    VkDevice device = ctx.device();
    auto ii = vkStruct<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
    ii.imageType = VK_IMAGE_TYPE_2D;
    ii.format = format;
    ii.extent = {extent.width, extent.height, 1};
    ii.mipLevels = 1;
    ii.arrayLayers = 1;
    ii.samples = VK_SAMPLE_COUNT_1_BIT;
    ii.tiling = VK_IMAGE_TILING_OPTIMAL;
    ii.usage = usage;
    ii.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    try {
        vkCheck(vkCreateImage(device, &ii, nullptr, &a.image), "vkCreateImage");
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, a.image, &req);
        auto ai = vkStruct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = ctx.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        vkCheck(vkAllocateMemory(device, &ai, nullptr, &a.memory), "vkAllocateMemory");
        vkCheck(vkBindImageMemory(device, a.image, a.memory, 0), "vkBindImageMemory");
        auto vi = vkStruct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
        vi.image = a.image;
        vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vi.format = format;
        vi.subresourceRange = {aspect, 0, 1, 0, 1};
        vkCheck(vkCreateImageView(device, &vi, nullptr, &a.view), "vkCreateImageView");
    } catch (...) {
        destroyImageAttachment(device, a);
        throw;
    }
    return a;
}

void destroyImageAttachment(VkDevice device, ImageAttachment& a) noexcept {
    if (a.view) vkDestroyImageView(device, a.view, nullptr);
    if (a.image) vkDestroyImage(device, a.image, nullptr);
    if (a.memory) vkFreeMemory(device, a.memory, nullptr);
    a = ImageAttachment{};
}

VkRenderPass createColorDepthRenderPass(VkDevice device, VkFormat colorFormat, VkImageLayout colorFinalLayout,
                                        VkFormat depthFormat, const VkSubpassDependency* dependencies,
                                        uint32_t numDependencies) {
    VkAttachmentDescription attachments[2] = {};
    attachments[0].format = colorFormat;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[0].finalLayout = colorFinalLayout;
    attachments[1] = attachments[0];
    attachments[1].format = depthFormat;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    const VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colorRef;
    subpass.pDepthStencilAttachment = &depthRef;
    auto info = vkStruct<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
    info.attachmentCount = 2;
    info.pAttachments = attachments;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = numDependencies;
    info.pDependencies = dependencies;
    VkRenderPass pass = VK_NULL_HANDLE;
    vkCheck(vkCreateRenderPass(device, &info, nullptr, &pass), "vkCreateRenderPass");
    return pass;
}

}  // namespace quadtri::render
