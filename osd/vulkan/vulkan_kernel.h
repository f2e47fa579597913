// One compute shader of the limit and mesh-normal evaluators with everything needed to record
// it: its descriptor set layout (storage or uniform texel buffers at bindings 0..n-1), pipeline layout (push
// constants of 32-bit words whose last two are the [start, end) range), a pipeline per set of
// specialization constants (cached), and descriptor pools in two arenas (sets recorded into the
// caller's command buffers, sets of the waiting calls), as VulkanEvaluator keeps them.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <quadtri/osd/buffer_descriptor.h>
#include <quadtri/osd/vulkan_context.h>

namespace quadtri {
inline namespace v0 {
namespace detail {

enum class Arena { Recorded, Waited };

class VulkanKernel {
public:
    // `types`: the descriptor type of each binding (storage buffers, uniform texel buffers).
    VulkanKernel(VulkanContext& ctx, const uint32_t* spirv, std::size_t words, const std::vector<VkDescriptorType>& types,
                 uint32_t pushWords);
    ~VulkanKernel();
    VulkanKernel(const VulkanKernel&) = delete;
    VulkanKernel& operator=(const VulkanKernel&) = delete;

    // Binds `buffers` (one per binding; at a texel-buffer binding, the view of `texels` at that
    // binding instead) and the pipeline of `constants` (constant_id 1, 2, ...;
    // id 0 is the workgroup size), then dispatches [start, end) with push = words + {start, end},
    // split at maxComputeWorkGroupCount, and a barrier making the writes visible to later
    // compute, transfer and host reads.
    void record(VkCommandBuffer cmd, Arena arena, const std::vector<VkDescriptorBufferInfo>& buffers,
                const std::vector<int32_t>& constants, const std::vector<uint32_t>& words, int start, int end,
                const std::vector<VkBufferView>& texels = {});
    void resetSets(Arena arena);

private:
    struct Pools {
        std::vector<VkDescriptorPool> pools;
        std::size_t current = 0;
    };
    VkDescriptorSet allocateSet(Pools& pools);
    VkPipeline pipeline(const std::vector<int32_t>& constants);
    void destroy() noexcept;

    VulkanContext& ctx_;
    std::vector<VkDescriptorType> types_;
    uint32_t bindings_, pushWords_;
    VkShaderModule shader_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
    std::vector<std::pair<std::vector<int32_t>, VkPipeline>> pipelines_;
    Pools recorded_, waited_;
};

// Where a caller's buffer is bound: at an offset meeting minStorageBufferOffsetAlignment, the
// rest of its byte offset and the descriptor's offset passed as floats.
struct BoundBuffer {
    VkDescriptorBufferInfo info;
    uint32_t floatOffset;
};
BoundBuffer bindAligned(const VulkanContext& ctx, VkBuffer buffer, VkDeviceSize byteOffset,
                        const BufferDescriptor& desc, const char* call);

}  // namespace detail
}  // namespace v0
}  // namespace quadtri
