// Stencil evaluation on a Vulkan device: the compute shader shaders/stencil_eval.comp applied to
// float data in storage buffers, with the CpuEvaluator contract (stencil i writes destination
// element i; same argument checks, std::invalid_argument).
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <memory>
#include <vector>

#include <quadtri/export.h>
#include <quadtri/osd/buffer_descriptor.h>
#include <quadtri/osd/vulkan_buffer.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_stencil_table.h>

namespace quadtri {
inline namespace v0 {

// Any storage buffer of the caller: the descriptor's float 0 lies `byteOffset` bytes into it
// (a multiple of 4; need not meet minStorageBufferOffsetAlignment). The buffer needs
// VK_BUFFER_USAGE_STORAGE_BUFFER_BIT.
struct VulkanBufferRef {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize byteOffset = 0;
    // Optional, for a source: an R32_SFLOAT uniform texel view of the whole buffer (texel 0 at its
    // byte 0; VulkanVertexBuffer::texels()), read instead of the storage buffer where the shader
    // supports it (faster on lavapipe: docs/decisions/0003-vulkan-on-lavapipe.md).
    VkBufferView texels = VK_NULL_HANDLE;
};

class QUADTRI_API VulkanEvaluator {
public:
    explicit VulkanEvaluator(VulkanContext& ctx);
    ~VulkanEvaluator();
    VulkanEvaluator(const VulkanEvaluator&) = delete;
    VulkanEvaluator& operator=(const VulkanEvaluator&) = delete;

    // Records stencils [start, end) of `table` (end < 0: all) into `cmd` (a primary command
    // buffer of the context's device, in the recording state, on a compute-capable queue
    // family), followed by a barrier making dst's writes visible to later compute-shader,
    // transfer and host reads (add your own barrier for other stages, e.g. vertex input).
    // Writes to src/dst before this call must be made visible by the caller. src and dst may be
    // the same buffer when the evaluated elements do not overlap the read ones. The descriptor
    // set it allocates lives until resetDescriptorSets().
    void EvalStencils(VkCommandBuffer cmd, const VulkanBufferRef& src, const BufferDescriptor& srcDesc,
                      const VulkanBufferRef& dst, const BufferDescriptor& dstDesc, const VulkanStencilTable& table,
                      int start = 0, int end = -1);
    // The same over VulkanVertexBuffers, whose sizes are also checked against the table.
    void EvalStencils(VkCommandBuffer cmd, const VulkanVertexBuffer& src, const BufferDescriptor& srcDesc,
                      const VulkanVertexBuffer& dst, const BufferDescriptor& dstDesc, const VulkanStencilTable& table,
                      int start = 0, int end = -1);
    // Records into a command buffer of its own, submits it to the context's queue and waits.
    void EvalStencilsAndWait(const VulkanVertexBuffer& src, const BufferDescriptor& srcDesc,
                             const VulkanVertexBuffer& dst, const BufferDescriptor& dstDesc,
                             const VulkanStencilTable& table, int start = 0, int end = -1);

    // Per-level tables through one buffer holding every level: level 0 is described by
    // `level0` (its `numSourceVertices` elements come first), level L's elements follow level
    // L-1's with the same stride. One dispatch per level, a barrier after each.
    void EvalLevels(VkCommandBuffer cmd, const VulkanBufferRef& buffer, const BufferDescriptor& level0,
                    const std::vector<const VulkanStencilTable*>& tables);
    void EvalLevelsAndWait(VulkanVertexBuffer& buffer, const BufferDescriptor& level0,
                           const std::vector<const VulkanStencilTable*>& tables);
    // First element of each level (levels 0 .. tables.size()) in EvalLevels' layout, and the
    // total element count at the end.
    static std::vector<int> levelFirstElements(const std::vector<const VulkanStencilTable*>& tables);

    // Frees the descriptor sets of every evaluation recorded so far: call once the device has
    // finished all command buffers recorded with this evaluator (e.g. after a frame's fence).
    void resetDescriptorSets();

private:
    struct DescriptorArena {
        std::vector<VkDescriptorPool> pools;
        std::size_t current = 0;
    };
    VkDescriptorSet allocateSet(DescriptorArena& arena);
    void reset(DescriptorArena& arena);
    void record(VkCommandBuffer cmd, DescriptorArena& arena, const VulkanBufferRef& src,
                const BufferDescriptor& srcDesc, const VulkanBufferRef& dst, const BufferDescriptor& dstDesc,
                const VulkanStencilTable& table, int start, int end);

    VulkanContext& ctx_;
    struct Unused;                  // bound where a table or source has no texel view
    std::unique_ptr<Unused> unused_;
    DescriptorArena recorded_;  // sets of EvalStencils / EvalLevels (caller's command buffers)
    DescriptorArena waited_;    // sets of the *AndWait calls, reset after each
};

}  // namespace v0
}  // namespace quadtri
