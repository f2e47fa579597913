#include <quadtri/osd/vulkan_context.h>

#include "osd/vulkan/vulkan_instance.h"

#include <algorithm>
#include <cstdint>

namespace quadtri {
inline namespace v0 {

namespace shaders {
extern const uint32_t stencil_eval_comp[];
extern const std::size_t stencil_eval_comp_words;
}  // namespace shaders

namespace {

// Storage buffers: offsets, indices, weightOffsets, weights, src, dst; then uniform texel
// buffers: the index pool, the weight pool, src (shaders/stencil_eval.comp).
constexpr uint32_t kNumBindings = 9;
constexpr uint32_t kStorageBindings = 6;
constexpr uint32_t kPushConstantBytes = 4 * sizeof(uint32_t);

}  // namespace

int VulkanContext::totalValidationMessageCount() { return detail::totalValidationMessages(); }

VulkanContext::VulkanContext() {
    try {
        createInstance();
        pickDevice();
        createDevice();
        createShared();
    } catch (...) {
        destroy();
        throw;
    }
}

VulkanContext::VulkanContext(const External& e)
    : instance_(e.instance), physicalDevice_(e.physicalDevice), device_(e.device), queue_(e.queue),
      queueFamily_(e.queueFamilyIndex) {
    if (!e.instance || !e.physicalDevice || !e.device || !e.queue)
        throw std::invalid_argument("VulkanContext: External needs an instance, physical device, device and queue");
    vkGetPhysicalDeviceProperties(physicalDevice_, &properties_);
    vkGetPhysicalDeviceMemoryProperties(physicalDevice_, &memory_);
    try {
        createShared();
    } catch (...) {
        destroy();
        throw;
    }
}

VulkanContext::~VulkanContext() { destroy(); }

void VulkanContext::createInstance() {
    const detail::ValidatedInstance created = detail::createValidatedInstance({}, &validationMessages_);
    instance_ = created.instance;
    messenger_ = created.messenger;
    ownsInstance_ = true;
}

void VulkanContext::createDevice() {
    const float priority = 1.0f;
    auto q = detail::vkStruct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    q.queueFamilyIndex = queueFamily_;
    q.queueCount = 1;
    q.pQueuePriorities = &priority;
    auto info = detail::vkStruct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &q;
    vkCheck(vkCreateDevice(physicalDevice_, &info, nullptr, &device_), "vkCreateDevice");
    ownsDevice_ = true;
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
}

void VulkanContext::createShared() {
    auto pool = detail::vkStruct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool.queueFamilyIndex = queueFamily_;
    vkCheck(vkCreateCommandPool(device_, &pool, nullptr, &commandPool_), "vkCreateCommandPool");

    auto sm = detail::vkStruct<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
    sm.codeSize = shaders::stencil_eval_comp_words * sizeof(uint32_t);
    sm.pCode = shaders::stencil_eval_comp;
    vkCheck(vkCreateShaderModule(device_, &sm, nullptr, &shader_), "vkCreateShaderModule");

    VkDescriptorSetLayoutBinding bindings[kNumBindings];
    for (uint32_t b = 0; b < kNumBindings; ++b)
        bindings[b] = VkDescriptorSetLayoutBinding{
            b, b < kStorageBindings ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 1,
            VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    auto sl = detail::vkStruct<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
    sl.bindingCount = kNumBindings;
    sl.pBindings = bindings;
    vkCheck(vkCreateDescriptorSetLayout(device_, &sl, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");

    VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, kPushConstantBytes};
    auto pl = detail::vkStruct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
    pl.setLayoutCount = 1;
    pl.pSetLayouts = &setLayout_;
    pl.pushConstantRangeCount = 1;
    pl.pPushConstantRanges = &push;
    vkCheck(vkCreatePipelineLayout(device_, &pl, nullptr, &pipelineLayout_), "vkCreatePipelineLayout");
    workgroupSize_ = std::min<uint32_t>(64, properties_.limits.maxComputeWorkGroupSize[0]);
    texelBufferLimit_ = detail::environmentFlag("QUADTRI_VK_NO_TEXEL_BUFFERS")
                            ? 0
                            : std::min<std::size_t>(properties_.limits.maxTexelBufferElements, INT32_MAX);
}

VkPipeline VulkanContext::stencilPipeline(int length, int srcStride, int dstStride) {
    return stencilPipeline(length, srcStride, dstStride, false, false);
}

VkPipeline VulkanContext::stencilPipeline(int length, int srcStride, int dstStride, bool poolTexels, bool sourceTexels) {
    const std::lock_guard<std::mutex> lock(pipelinesMutex_);
    for (const auto& p : pipelines_)
        if (p.length == length && p.srcStride == srcStride && p.dstStride == dstStride && p.poolTexels == poolTexels &&
            p.sourceTexels == sourceTexels)
            return p.pipeline;
    const int32_t values[6] = {int32_t(workgroupSize_), length, srcStride, dstStride, poolTexels, sourceTexels};
    VkSpecializationMapEntry entries[6];
    for (uint32_t i = 0; i < 6; ++i) entries[i] = VkSpecializationMapEntry{i, uint32_t(i * sizeof(int32_t)), sizeof(int32_t)};
    VkSpecializationInfo spec{6, entries, sizeof(values), values};
    auto info = detail::vkStruct<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    info.stage = detail::vkStruct<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = shader_;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = &spec;
    info.layout = pipelineLayout_;
    VkPipeline pipeline = VK_NULL_HANDLE;
    vkCheck(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline), "vkCreateComputePipelines");
    pipelines_.push_back({length, srcStride, dstStride, poolTexels, sourceTexels, pipeline});
    return pipeline;
}

uint32_t VulkanContext::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const {
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & required) == required) return i;
    throw VulkanError("no Vulkan memory type with properties " + std::to_string(required));
}

void VulkanContext::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
    auto ai = detail::vkStruct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    ai.commandPool = commandPool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    vkCheck(vkAllocateCommandBuffers(device_, &ai, &cmd), "vkAllocateCommandBuffers");
    VkFence fence = VK_NULL_HANDLE;
    auto release = [&] {
        if (fence) vkDestroyFence(device_, fence, nullptr);
        vkFreeCommandBuffers(device_, commandPool_, 1, &cmd);
    };
    try {
        auto bi = detail::vkStruct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkCheck(vkBeginCommandBuffer(cmd, &bi), "vkBeginCommandBuffer");
        record(cmd);
        vkCheck(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
        auto fi = detail::vkStruct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
        vkCheck(vkCreateFence(device_, &fi, nullptr, &fence), "vkCreateFence");
        auto si = detail::vkStruct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cmd;
        vkCheck(vkQueueSubmit(queue_, 1, &si, fence), "vkQueueSubmit");
        vkCheck(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    } catch (...) {
        release();
        throw;
    }
    release();
}

void VulkanContext::destroy() noexcept {
    if (device_) {
        for (const auto& p : pipelines_) vkDestroyPipeline(device_, p.pipeline, nullptr);
        pipelines_.clear();
        if (pipelineLayout_) vkDestroyPipelineLayout(device_, pipelineLayout_, nullptr);
        if (setLayout_) vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
        if (shader_) vkDestroyShaderModule(device_, shader_, nullptr);
        if (commandPool_) vkDestroyCommandPool(device_, commandPool_, nullptr);
        pipelineLayout_ = VK_NULL_HANDLE, setLayout_ = VK_NULL_HANDLE, shader_ = VK_NULL_HANDLE, commandPool_ = VK_NULL_HANDLE;
        if (ownsDevice_) vkDestroyDevice(device_, nullptr);
    }
    device_ = VK_NULL_HANDLE;
    if (ownsInstance_) {
        detail::ValidatedInstance owned{instance_, messenger_};
        detail::destroyValidatedInstance(owned);
        messenger_ = VK_NULL_HANDLE;
    }
    instance_ = VK_NULL_HANDLE;
}

}  // namespace v0
}  // namespace quadtri
