// Limit positions, tangents and normals (shaders/limit_eval.comp), area-weighted mesh normals
// (shaders/mesh_normals.comp) and a level's limit from patches (shaders/level_patches.comp) on a
// Vulkan device, with the contracts, argument checks and
// messages of CpuEvaluator::EvalLimitStencils and EvalMeshNormals, and VulkanEvaluator's
// recording rules (barrier after each dispatch, descriptor sets kept until
// resetDescriptorSets()).
#pragma once

#include <vulkan/vulkan.h>

#include <memory>

#include <quadtri/export.h>
#include <quadtri/osd/buffer_descriptor.h>
#include <quadtri/osd/vulkan_buffer.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_evaluator.h>
#include <quadtri/osd/vulkan_limit_tables.h>

namespace quadtri {
inline namespace v0 {

class QUADTRI_API VulkanLimitEvaluator {
public:
    explicit VulkanLimitEvaluator(VulkanContext& ctx);
    ~VulkanLimitEvaluator();
    VulkanLimitEvaluator(const VulkanLimitEvaluator&) = delete;
    VulkanLimitEvaluator& operator=(const VulkanLimitEvaluator&) = delete;

    // Records limit stencils [start, end) of `table` (end < 0: all) into `cmd`. An output whose
    // buffer is VK_NULL_HANDLE is not written (its descriptor is not read). Same rules as
    // CpuEvaluator::EvalLimitStencils; the outputs may share one buffer when their elements do
    // not overlap.
    void EvalLimitStencils(VkCommandBuffer cmd, const VulkanBufferRef& src, const BufferDescriptor& srcDesc,
                           const VulkanBufferRef& position, const BufferDescriptor& positionDesc,
                           const VulkanBufferRef& du, const BufferDescriptor& duDesc, const VulkanBufferRef& dv,
                           const BufferDescriptor& dvDesc, const VulkanBufferRef& normal,
                           const BufferDescriptor& normalDesc, const VulkanLimitStencilTable& table,
                           const VulkanMeshNormalTable* fallback = nullptr, int start = 0, int end = -1);
    // The same over VulkanVertexBuffers (null: not written), sizes checked; submits and waits.
    void EvalLimitStencilsAndWait(const VulkanVertexBuffer& src, const BufferDescriptor& srcDesc,
                                  const VulkanVertexBuffer* position, const BufferDescriptor& positionDesc,
                                  const VulkanVertexBuffer* du, const BufferDescriptor& duDesc,
                                  const VulkanVertexBuffer* dv, const BufferDescriptor& dvDesc,
                                  const VulkanVertexBuffer* normal, const BufferDescriptor& normalDesc,
                                  const VulkanLimitStencilTable& table, const VulkanMeshNormalTable* fallback = nullptr,
                                  int start = 0, int end = -1);

    // Records the mesh normals of vertices [start, end) (end < 0: all) into `cmd`; the
    // CpuEvaluator::EvalMeshNormals contract.
    void EvalMeshNormals(VkCommandBuffer cmd, const VulkanBufferRef& src, const BufferDescriptor& srcDesc,
                         const VulkanBufferRef& dst, const BufferDescriptor& dstDesc, const VulkanMeshNormalTable& table,
                         int start = 0, int end = -1);
    void EvalMeshNormalsAndWait(const VulkanVertexBuffer& src, const BufferDescriptor& srcDesc,
                                const VulkanVertexBuffer& dst, const BufferDescriptor& dstDesc,
                                const VulkanMeshNormalTable& table, int start = 0, int end = -1);

    // Records level L's limit positions and unit normals from level K's positions (src) through
    // `table`: its patches, then its stencils (two dispatches); point k written at element k of
    // each output given (an output whose buffer is VK_NULL_HANDLE is not written; not both).
    // CpuEvaluator::EvalLevelPatches' contract, within float rounding of its results.
    void EvalLevelPatches(VkCommandBuffer cmd, const VulkanBufferRef& src, const BufferDescriptor& srcDesc,
                          const VulkanBufferRef& position, const BufferDescriptor& positionDesc,
                          const VulkanBufferRef& normal, const BufferDescriptor& normalDesc,
                          const VulkanLevelPatchTable& table);
    // The same over VulkanVertexBuffers (null: not written), sizes checked; submits and waits.
    void EvalLevelPatchesAndWait(const VulkanVertexBuffer& src, const BufferDescriptor& srcDesc,
                                 const VulkanVertexBuffer* position, const BufferDescriptor& positionDesc,
                                 const VulkanVertexBuffer* normal, const BufferDescriptor& normalDesc,
                                 const VulkanLevelPatchTable& table);

    // Frees the descriptor sets of every evaluation recorded so far, once the device has
    // finished the command buffers recorded with this evaluator.
    void resetDescriptorSets();

private:
    void recordLimit(VkCommandBuffer cmd, bool waited, const VulkanBufferRef& src, const BufferDescriptor& srcDesc,
                     const VulkanBufferRef (&outputs)[4], const BufferDescriptor* const (&descs)[4],
                     const VulkanLimitStencilTable& table, const VulkanMeshNormalTable* fallback, int start, int end);
    void recordNormals(VkCommandBuffer cmd, bool waited, const VulkanBufferRef& src, const BufferDescriptor& srcDesc,
                       const VulkanBufferRef& dst, const BufferDescriptor& dstDesc, const VulkanMeshNormalTable& table,
                       int start, int end);
    void recordPatches(VkCommandBuffer cmd, bool waited, const VulkanBufferRef& src, const BufferDescriptor& srcDesc,
                       const VulkanBufferRef& position, const BufferDescriptor& positionDesc,
                       const VulkanBufferRef& normal, const BufferDescriptor& normalDesc,
                       const VulkanLevelPatchTable& table);
    void resetWaited();

    VulkanContext& ctx_;
    struct Kernels;  // the limit, normal and patch kernels, and what is bound where an evaluation has nothing
    std::unique_ptr<Kernels> kernels_;
};

}  // namespace v0
}  // namespace quadtri
