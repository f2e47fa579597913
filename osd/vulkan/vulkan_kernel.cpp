#include "osd/vulkan/vulkan_kernel.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace quadtri {
inline namespace v0 {
namespace detail {

namespace {
constexpr uint32_t kSetsPerPool = 64;
}  // namespace

VulkanKernel::VulkanKernel(VulkanContext& ctx, const uint32_t* spirv, std::size_t words,
                           const std::vector<VkDescriptorType>& types, uint32_t pushWords)
    : ctx_(ctx), types_(types), bindings_(uint32_t(types.size())), pushWords_(pushWords) {
    const uint32_t bindings = bindings_;
    const VkDevice device = ctx.device();
    try {
        auto sm = vkStruct<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
        sm.codeSize = words * sizeof(uint32_t);
        sm.pCode = spirv;
        vkCheck(vkCreateShaderModule(device, &sm, nullptr, &shader_), "vkCreateShaderModule");
        std::vector<VkDescriptorSetLayoutBinding> b(bindings);
        for (uint32_t i = 0; i < bindings; ++i)
            b[i] = VkDescriptorSetLayoutBinding{i, types_[i], 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
        auto sl = vkStruct<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
        sl.bindingCount = bindings;
        sl.pBindings = b.data();
        vkCheck(vkCreateDescriptorSetLayout(device, &sl, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");
        const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushWords * uint32_t(sizeof(uint32_t))};
        auto pl = vkStruct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
        pl.setLayoutCount = 1;
        pl.pSetLayouts = &setLayout_;
        pl.pushConstantRangeCount = 1;
        pl.pPushConstantRanges = &push;
        vkCheck(vkCreatePipelineLayout(device, &pl, nullptr, &pipelineLayout_), "vkCreatePipelineLayout");
    } catch (...) {
        destroy();
        throw;
    }
}

VulkanKernel::~VulkanKernel() { destroy(); }

void VulkanKernel::destroy() noexcept {
    const VkDevice device = ctx_.device();
    for (Pools* p : {&recorded_, &waited_}) {
        for (VkDescriptorPool pool : p->pools) vkDestroyDescriptorPool(device, pool, nullptr);
        p->pools.clear();
    }
    for (const auto& p : pipelines_) vkDestroyPipeline(device, p.second, nullptr);
    pipelines_.clear();
    if (pipelineLayout_) vkDestroyPipelineLayout(device, pipelineLayout_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
    if (shader_) vkDestroyShaderModule(device, shader_, nullptr);
    pipelineLayout_ = VK_NULL_HANDLE, setLayout_ = VK_NULL_HANDLE, shader_ = VK_NULL_HANDLE;
}

VkPipeline VulkanKernel::pipeline(const std::vector<int32_t>& constants) {
    for (const auto& p : pipelines_)
        if (p.first == constants) return p.second;
    std::vector<int32_t> values{int32_t(ctx_.workgroupSize())};
    values.insert(values.end(), constants.begin(), constants.end());
    std::vector<VkSpecializationMapEntry> entries(values.size());
    for (uint32_t i = 0; i < entries.size(); ++i)
        entries[i] = VkSpecializationMapEntry{i, uint32_t(i * sizeof(int32_t)), sizeof(int32_t)};
    const VkSpecializationInfo spec{uint32_t(entries.size()), entries.data(), values.size() * sizeof(int32_t),
                                    values.data()};
    auto info = vkStruct<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    info.stage = vkStruct<VkPipelineShaderStageCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = shader_;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = &spec;
    info.layout = pipelineLayout_;
    VkPipeline p = VK_NULL_HANDLE;
    vkCheck(vkCreateComputePipelines(ctx_.device(), VK_NULL_HANDLE, 1, &info, nullptr, &p), "vkCreateComputePipelines");
    pipelines_.emplace_back(constants, p);
    return p;
}

VkDescriptorSet VulkanKernel::allocateSet(Pools& arena) {
    for (;; ++arena.current) {
        if (arena.current == arena.pools.size()) {
            std::vector<VkDescriptorPoolSize> sizes;
            for (VkDescriptorType t : types_) {
                auto same = [t](const VkDescriptorPoolSize& s) { return s.type == t; };
                auto it = std::find_if(sizes.begin(), sizes.end(), same);
                if (it == sizes.end()) it = sizes.insert(sizes.end(), VkDescriptorPoolSize{t, 0});
                it->descriptorCount += kSetsPerPool;
            }
            auto pi = vkStruct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
            pi.maxSets = kSetsPerPool;
            pi.poolSizeCount = uint32_t(sizes.size());
            pi.pPoolSizes = sizes.data();
            VkDescriptorPool pool = VK_NULL_HANDLE;
            vkCheck(vkCreateDescriptorPool(ctx_.device(), &pi, nullptr, &pool), "vkCreateDescriptorPool");
            arena.pools.push_back(pool);
        }
        auto ai = vkStruct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
        ai.descriptorPool = arena.pools[arena.current];
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &setLayout_;
        VkDescriptorSet set = VK_NULL_HANDLE;
        const VkResult r = vkAllocateDescriptorSets(ctx_.device(), &ai, &set);
        if (r == VK_SUCCESS) return set;
        if (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL) vkCheck(r, "vkAllocateDescriptorSets");
    }
}

void VulkanKernel::resetSets(Arena which) {
    Pools& arena = which == Arena::Recorded ? recorded_ : waited_;
    for (VkDescriptorPool p : arena.pools) vkCheck(vkResetDescriptorPool(ctx_.device(), p, 0), "vkResetDescriptorPool");
    arena.current = 0;
}

void VulkanKernel::record(VkCommandBuffer cmd, Arena which, const std::vector<VkDescriptorBufferInfo>& buffers,
                          const std::vector<int32_t>& constants, const std::vector<uint32_t>& words, int start,
                          int end, const std::vector<VkBufferView>& texels) {
    const VkDescriptorSet set = allocateSet(which == Arena::Recorded ? recorded_ : waited_);
    std::vector<VkWriteDescriptorSet> writes(bindings_);
    for (uint32_t b = 0; b < bindings_; ++b) {
        writes[b] = vkStruct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[b].dstSet = set;
        writes[b].dstBinding = b;
        writes[b].descriptorCount = 1;
        writes[b].descriptorType = types_[b];
        if (types_[b] == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER)
            writes[b].pTexelBufferView = &texels.at(b);
        else
            writes[b].pBufferInfo = &buffers.at(b);
    }
    vkUpdateDescriptorSets(ctx_.device(), bindings_, writes.data(), 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(constants));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelineLayout_, 0, 1, &set, 0, nullptr);
    const uint32_t group = ctx_.workgroupSize();
    const uint64_t perDispatch = uint64_t(ctx_.properties().limits.maxComputeWorkGroupCount[0]) * group;
    std::vector<uint32_t> push(words);
    push.resize(pushWords_);
    for (uint64_t first = uint64_t(start); first < uint64_t(end); first += perDispatch) {
        const uint64_t last = std::min<uint64_t>(uint64_t(end), first + perDispatch);
        push[pushWords_ - 2] = uint32_t(first);
        push[pushWords_ - 1] = uint32_t(last);
        vkCmdPushConstants(cmd, pipelineLayout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushWords_ * sizeof(uint32_t),
                           push.data());
        vkCmdDispatch(cmd, uint32_t((last - first + group - 1) / group), 1, 1);
    }
    auto barrier = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                            VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                         0, 1, &barrier, 0, nullptr, 0, nullptr);
}

BoundBuffer bindAligned(const VulkanContext& ctx, VkBuffer buffer, VkDeviceSize byteOffset,
                        const BufferDescriptor& desc, const char* call) {
    if (byteOffset % 4)
        throw std::invalid_argument(std::string(call) + ": VulkanBufferRef::byteOffset must be a multiple of 4");
    const VkDeviceSize align = std::max<VkDeviceSize>(4, ctx.properties().limits.minStorageBufferOffsetAlignment);
    const VkDeviceSize base = byteOffset - byteOffset % align;
    const std::size_t floats = (byteOffset - base) / 4 + std::size_t(desc.offset);
    if (floats > std::numeric_limits<uint32_t>::max())
        throw std::invalid_argument(std::string(call) + ": offset past 2^32 floats");
    return {{buffer, base, VK_WHOLE_SIZE}, uint32_t(floats)};
}

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
