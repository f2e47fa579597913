#include <quadtri/osd/vulkan_evaluator.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "osd/internal/eval_arguments.h"
#include "osd/vulkan/vulkan_memory.h"

namespace quadtri {
inline namespace v0 {

namespace {

constexpr uint32_t kSetsPerPool = 64;
constexpr uint32_t kStorageBindings = 6;  // the context's layout (shaders/stencil_eval.comp)
constexpr uint32_t kTexelBindings = 3;
constexpr uint32_t kBindings = kStorageBindings + kTexelBindings;

// Floats needed to hold `count` elements of `d` (0 when count is 0).
std::size_t floatsNeeded(const BufferDescriptor& d, int count) {
    return count <= 0 ? 0 : std::size_t(d.offset) + std::size_t(count - 1) * std::size_t(d.stride) + std::size_t(d.length);
}

void checkFits(const char* which, const VulkanVertexBuffer& b, const BufferDescriptor& d, int count) {
    if (floatsNeeded(d, count) > b.numFloats())
        throw std::invalid_argument(std::string("EvalStencils: ") + which + " buffer of " + std::to_string(b.numFloats()) +
                                    " floats too small for " + std::to_string(count) + " elements");
}

uint32_t toU32(std::size_t v, const char* what) {
    if (v > std::numeric_limits<uint32_t>::max())
        throw std::invalid_argument(std::string("EvalStencils: ") + what + " past 2^32 floats");
    return uint32_t(v);
}

}  // namespace

struct VulkanEvaluator::Unused : detail::UnusedBindings {
    using UnusedBindings::UnusedBindings;
};

VulkanEvaluator::VulkanEvaluator(VulkanContext& ctx) : ctx_(ctx), unused_(std::make_unique<Unused>(ctx, 0)) {}

VulkanEvaluator::~VulkanEvaluator() {
    for (DescriptorArena* a : {&recorded_, &waited_})
        for (VkDescriptorPool p : a->pools) vkDestroyDescriptorPool(ctx_.device(), p, nullptr);
}

VkDescriptorSet VulkanEvaluator::allocateSet(DescriptorArena& arena) {
    const VkDescriptorSetLayout layout = ctx_.descriptorSetLayout();
    for (;; ++arena.current) {
        if (arena.current == arena.pools.size()) {
            const VkDescriptorPoolSize sizes[2] = {
                {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kSetsPerPool * kStorageBindings},
                {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, kSetsPerPool * kTexelBindings}};
            auto pi = detail::vkStruct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
            pi.maxSets = kSetsPerPool;
            pi.poolSizeCount = 2;
            pi.pPoolSizes = sizes;
            VkDescriptorPool pool = VK_NULL_HANDLE;
            vkCheck(vkCreateDescriptorPool(ctx_.device(), &pi, nullptr, &pool), "vkCreateDescriptorPool");
            arena.pools.push_back(pool);
        }
        auto ai = detail::vkStruct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
        ai.descriptorPool = arena.pools[arena.current];
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &layout;
        VkDescriptorSet set = VK_NULL_HANDLE;
        const VkResult r = vkAllocateDescriptorSets(ctx_.device(), &ai, &set);
        if (r == VK_SUCCESS) return set;
        if (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL) vkCheck(r, "vkAllocateDescriptorSets");
    }
}

void VulkanEvaluator::reset(DescriptorArena& arena) {
    for (VkDescriptorPool p : arena.pools) vkCheck(vkResetDescriptorPool(ctx_.device(), p, 0), "vkResetDescriptorPool");
    arena.current = 0;
}

void VulkanEvaluator::resetDescriptorSets() { reset(recorded_); }

void VulkanEvaluator::record(VkCommandBuffer cmd, DescriptorArena& arena, const VulkanBufferRef& src,
                             const BufferDescriptor& srcDesc, const VulkanBufferRef& dst,
                             const BufferDescriptor& dstDesc, const VulkanStencilTable& table, int start, int end) {
    if (!detail::checkEvalArguments(src.buffer != VK_NULL_HANDLE, srcDesc, dst.buffer != VK_NULL_HANDLE, dstDesc,
                                    table.numStencils(), start, end))
        return;
    if (!cmd) throw std::invalid_argument("EvalStencils: null command buffer");
    if (table.device() != ctx_.device())
        throw std::invalid_argument("EvalStencils: the stencil table belongs to another VkDevice");
    if (src.byteOffset % 4 || dst.byteOffset % 4)
        throw std::invalid_argument("EvalStencils: VulkanBufferRef::byteOffset must be a multiple of 4");

    // Bind at an offset meeting minStorageBufferOffsetAlignment, push the rest as floats.
    const VkDeviceSize align = std::max<VkDeviceSize>(4, ctx_.properties().limits.minStorageBufferOffsetAlignment);
    const VkDeviceSize srcBase = src.byteOffset - src.byteOffset % align;
    const VkDeviceSize dstBase = dst.byteOffset - dst.byteOffset % align;
    // The source's texel view (when given) starts at the buffer's byte 0, its storage binding at srcBase.
    const std::size_t texelOffset = src.byteOffset / 4 + std::size_t(srcDesc.offset);
    const bool sourceTexels = src.texels != VK_NULL_HANDLE && texelOffset <= std::size_t(INT32_MAX);
    const bool poolTexels = table.indexTexels() != VK_NULL_HANDLE;
    const uint32_t srcOffset = sourceTexels ? uint32_t(texelOffset)
                                            : toU32((src.byteOffset - srcBase) / 4 + std::size_t(srcDesc.offset), "source offset");
    const uint32_t dstOffset = toU32((dst.byteOffset - dstBase) / 4 + std::size_t(dstDesc.offset), "destination offset");

    const VkDescriptorSet set = allocateSet(arena);
    const VkDescriptorBufferInfo infos[kStorageBindings] = {
        {table.offsets(), 0, VK_WHOLE_SIZE},       {table.indices(), 0, VK_WHOLE_SIZE},
        {table.weightOffsets(), 0, VK_WHOLE_SIZE}, {table.weights(), 0, VK_WHOLE_SIZE},
        {src.buffer, srcBase, VK_WHOLE_SIZE},      {dst.buffer, dstBase, VK_WHOLE_SIZE},
    };
    const VkBufferView texels[kTexelBindings] = {
        poolTexels ? table.indexTexels() : unused_->indexTexels.view(),
        poolTexels ? table.weightTexels() : unused_->floatTexels.view(),
        sourceTexels ? src.texels : unused_->floatTexels.view(),
    };
    VkWriteDescriptorSet writes[kBindings];
    for (uint32_t b = 0; b < kBindings; ++b) {
        writes[b] = detail::vkStruct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[b].dstSet = set;
        writes[b].dstBinding = b;
        writes[b].descriptorCount = 1;
        if (b < kStorageBindings) {
            writes[b].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            writes[b].pBufferInfo = &infos[b];
        } else {
            writes[b].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
            writes[b].pTexelBufferView = &texels[b - kStorageBindings];
        }
    }
    vkUpdateDescriptorSets(ctx_.device(), kBindings, writes, 0, nullptr);

    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                      ctx_.stencilPipeline(srcDesc.length, srcDesc.stride, dstDesc.stride, poolTexels, sourceTexels));
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, ctx_.pipelineLayout(), 0, 1, &set, 0, nullptr);
    // At most maxComputeWorkGroupCount[0] workgroups per dispatch: split long ranges.
    const uint32_t group = ctx_.workgroupSize();
    const uint64_t perDispatch = uint64_t(ctx_.properties().limits.maxComputeWorkGroupCount[0]) * group;
    for (uint64_t first = uint64_t(start); first < uint64_t(end); first += perDispatch) {
        const uint64_t last = std::min<uint64_t>(uint64_t(end), first + perDispatch);
        const uint32_t push[4] = {srcOffset, dstOffset, uint32_t(first), uint32_t(last)};
        vkCmdPushConstants(cmd, ctx_.pipelineLayout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), push);
        vkCmdDispatch(cmd, uint32_t((last - first + group - 1) / group), 1, 1);
    }
    auto barrier = detail::vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                            VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                         0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void VulkanEvaluator::EvalStencils(VkCommandBuffer cmd, const VulkanBufferRef& src, const BufferDescriptor& srcDesc,
                                   const VulkanBufferRef& dst, const BufferDescriptor& dstDesc,
                                   const VulkanStencilTable& table, int start, int end) {
    record(cmd, recorded_, src, srcDesc, dst, dstDesc, table, start, end);
}

void VulkanEvaluator::EvalStencils(VkCommandBuffer cmd, const VulkanVertexBuffer& src,
                                   const BufferDescriptor& srcDesc, const VulkanVertexBuffer& dst,
                                   const BufferDescriptor& dstDesc, const VulkanStencilTable& table, int start,
                                   int end) {
    int last = end;
    if (!detail::checkEvalArguments(true, srcDesc, true, dstDesc, table.numStencils(), start, last)) return;
    checkFits("source", src, srcDesc, table.numSourceVertices());
    checkFits("destination", dst, dstDesc, last);
    record(cmd, recorded_, {src.buffer(), 0, src.texels()}, srcDesc, {dst.buffer(), 0}, dstDesc, table, start, end);
}

void VulkanEvaluator::EvalStencilsAndWait(const VulkanVertexBuffer& src, const BufferDescriptor& srcDesc,
                                          const VulkanVertexBuffer& dst, const BufferDescriptor& dstDesc,
                                          const VulkanStencilTable& table, int start, int end) {
    int last = end;
    if (!detail::checkEvalArguments(true, srcDesc, true, dstDesc, table.numStencils(), start, last)) return;
    checkFits("source", src, srcDesc, table.numSourceVertices());
    checkFits("destination", dst, dstDesc, last);
    try {
        ctx_.submitAndWait([&](VkCommandBuffer cmd) {
            record(cmd, waited_, {src.buffer(), 0, src.texels()}, srcDesc, {dst.buffer(), 0}, dstDesc, table, start, end);
        });
    } catch (...) {
        reset(waited_);
        throw;
    }
    reset(waited_);
}

std::vector<int> VulkanEvaluator::levelFirstElements(const std::vector<const VulkanStencilTable*>& tables) {
    std::vector<int> first{0};
    if (tables.empty()) return first;
    if (!tables[0]) throw std::invalid_argument("EvalLevels: null table");
    first.push_back(tables[0]->numSourceVertices());
    for (std::size_t L = 0; L < tables.size(); ++L) {
        if (!tables[L]) throw std::invalid_argument("EvalLevels: null table");
        const int previous = first[L + 1] - first[L];
        if (tables[L]->numSourceVertices() != previous)
            throw std::invalid_argument("EvalLevels: table " + std::to_string(L + 1) + " reads " +
                                        std::to_string(tables[L]->numSourceVertices()) + " vertices, level " +
                                        std::to_string(L) + " has " + std::to_string(previous));
        first.push_back(first.back() + tables[L]->numStencils());
    }
    return first;
}

void VulkanEvaluator::EvalLevels(VkCommandBuffer cmd, const VulkanBufferRef& buffer, const BufferDescriptor& level0,
                                 const std::vector<const VulkanStencilTable*>& tables) {
    const std::vector<int> first = levelFirstElements(tables);
    for (std::size_t L = 0; L < tables.size(); ++L) {
        const BufferDescriptor src(level0.offset + first[L] * level0.stride, level0.length, level0.stride);
        const BufferDescriptor dst(level0.offset + first[L + 1] * level0.stride, level0.length, level0.stride);
        record(cmd, recorded_, buffer, src, buffer, dst, *tables[L], 0, -1);
    }
}

void VulkanEvaluator::EvalLevelsAndWait(VulkanVertexBuffer& buffer, const BufferDescriptor& level0,
                                        const std::vector<const VulkanStencilTable*>& tables) {
    const std::vector<int> first = levelFirstElements(tables);
    if (!level0.isValid()) throw std::invalid_argument("EvalLevels: invalid BufferDescriptor");
    checkFits("level", buffer, level0, first.back());
    try {
        ctx_.submitAndWait([&](VkCommandBuffer cmd) {
            for (std::size_t L = 0; L < tables.size(); ++L) {
                const BufferDescriptor src(level0.offset + first[L] * level0.stride, level0.length, level0.stride);
                const BufferDescriptor dst(level0.offset + first[L + 1] * level0.stride, level0.length, level0.stride);
                record(cmd, waited_, {buffer.buffer(), 0, buffer.texels()}, src, {buffer.buffer(), 0}, dst, *tables[L], 0,
                       -1);
            }
        });
    } catch (...) {
        reset(waited_);
        throw;
    }
    reset(waited_);
}

}  // namespace v0
}  // namespace quadtri
