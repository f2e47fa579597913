// A LimitStencilTable and a MeshNormalTable uploaded once to device-local storage buffers, for
// VulkanLimitEvaluator (like VulkanStencilTable for VulkanEvaluator).
#pragma once

#include <memory>

#include <vulkan/vulkan.h>

#include <quadtri/export.h>
#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/mesh_normal_table.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_stencil_table.h>

namespace quadtri {
inline namespace v0 {

// A LimitStencilTable uploaded once to device-local storage buffers, for VulkanLimitEvaluator.
class QUADTRI_API VulkanLimitStencilTable : public VulkanPooledTable {
public:
    // Copies the table's five arrays through one staging buffer (waits); std::invalid_argument
    // when they are inconsistent (a run or a weight triple outside its pool included).
    VulkanLimitStencilTable(VulkanContext& ctx, const LimitStencilTable& table)
        : VulkanPooledTable(ctx, {table.numSourceVertices, &table.sizes, table.offsets, table.indices,
                                   table.weightOffsets, table.weights, 3},
                             "LimitStencilTable") {}

    using VulkanPooledTable::sizes;
};

class QUADTRI_API VulkanMeshNormalTable {
public:
    // Copies the table's faces and each vertex's faces (faceOffsets, faceCorners, vertexFaceOffsets,
    // vertexFaces) through one staging buffer (waits); std::invalid_argument when they are
    // inconsistent. The chunks and seams are the host's only.
    VulkanMeshNormalTable(VulkanContext& ctx, const MeshNormalTable& table);
    ~VulkanMeshNormalTable();
    VulkanMeshNormalTable(VulkanMeshNormalTable&&) noexcept;
    VulkanMeshNormalTable& operator=(VulkanMeshNormalTable&&) noexcept;

    int numVertices() const { return numVertices_; }
    // The four arrays in that order, as the shaders bind them.
    const VkBuffer (&buffers() const)[4] { return handles_; }
    VkDevice device() const { return device_; }

private:
    VkDevice device_;
    int numVertices_ = 0;
    VkBuffer handles_[4] = {};
    struct Arrays;  // the buffers behind handles_
    std::unique_ptr<Arrays> arrays_;
};

}  // namespace v0
}  // namespace quadtri
