// A LimitStencilTable, a MeshNormalTable and a LevelPatchTable uploaded once to device-local
// storage buffers, for VulkanLimitEvaluator (like VulkanStencilTable for VulkanEvaluator).
#pragma once

#include <memory>

#include <vulkan/vulkan.h>

#include <quadtri/export.h>
#include <quadtri/far/level_patch_table.h>
#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/limit_table_update.h>
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
    // `updatable`: the pools get room for what LimitTableUpdate appends (half their size again, at
    // least 16 384 elements each), so that update() can write an edit's changes by range.
    VulkanLimitStencilTable(VulkanContext& ctx, const LimitStencilTable& table, bool updatable = false)
        : VulkanPooledTable(ctx, {table.numSourceVertices, &table.sizes, table.offsets, table.indices,
                                   table.weightOffsets, table.weights, 3, updatable},
                             "LimitStencilTable") {}

    // After `change` = LimitTableUpdate::update(..., table) on the host table this copy was made
    // from (or last updated from), made with `updatable`: the changed stencils' sizes, offsets and
    // weight offsets and the pools' new ends uploaded (waits). False, with nothing changed, where
    // the table must be copied again instead (the pools laid out again or past their room).
    bool update(VulkanContext& ctx, const LimitStencilTable& table, const LimitTableChange& change) {
        if (change.poolsLaidOut) return false;
        return updateStencils(ctx, {table.numSourceVertices, &table.sizes, table.offsets, table.indices,
                                    table.weightOffsets, table.weights, 3, true},
                              change.stencils);
    }

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

// A LevelPatchTable (Refiner::levelPatches; docs/patches.md) uploaded once: its patches' arrays
// for shaders/level_patches.comp (the grid cells two to a 32-bit word, as the host's 16-bit
// array lies in memory; not curveWeights, which the shader computes) and its stencils as a
// VulkanLimitStencilTable.
class QUADTRI_API VulkanLevelPatchTable {
public:
    // Copies the arrays through one staging buffer (waits); std::invalid_argument when they are
    // inconsistent: arrays of the wrong lengths, a patch without 16 (B-spline) or 12 (box-spline)
    // points, a point outside level K, an output outside the grid or the table (the shader would
    // read or write past them).
    VulkanLevelPatchTable(VulkanContext& ctx, const LevelPatchTable& table);
    ~VulkanLevelPatchTable();
    VulkanLevelPatchTable(VulkanLevelPatchTable&&) noexcept;
    VulkanLevelPatchTable& operator=(VulkanLevelPatchTable&&) noexcept;

    int numPoints() const { return numPoints_; }
    int numSourceVertices() const { return numSourceVertices_; }
    int numPatches() const { return numPatches_; }
    int numPatchOutputs() const { return numPatchOutputs_; }
    int rate() const { return rate_; }
    // patchBasis (as int), pointOffsets, patchPoints, outputOffsets, outputCells and
    // boxSplineWeights, as the shader binds them.
    const VkBuffer (&buffers() const)[6] { return handles_; }
    // patchPoints, outputCells and boxSplineWeights as uniform texel buffers (R32_SINT, R32_UINT,
    // R32_SFLOAT), or VK_NULL_HANDLE each where one has more elements than the context's
    // texelBufferLimit().
    const VkBufferView (&texels() const)[3] { return texelHandles_; }
    const VulkanLimitStencilTable& stencils() const { return stencils_; }
    VkDevice device() const { return device_; }

private:
    VkDevice device_;
    int numPoints_ = 0, numSourceVertices_ = 0, numPatches_ = 0, numPatchOutputs_ = 0, rate_ = 1;
    VkBuffer handles_[6] = {};
    VkBufferView texelHandles_[3] = {};
    struct Arrays;  // the buffers behind handles_
    std::unique_ptr<Arrays> arrays_;
    VulkanLimitStencilTable stencils_;
};

}  // namespace v0
}  // namespace quadtri
