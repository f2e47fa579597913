// A StencilTable uploaded once to device-local storage buffers, for VulkanEvaluator.
#pragma once

#include <vector>

#include <vulkan/vulkan.h>

#include <quadtri/export.h>
#include <quadtri/far/stencil_table.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_memory.h>

namespace quadtri {
inline namespace v0 {

namespace detail {

// The arrays of a pooled stencil table in device-local storage buffers: StencilTable's four
// (offsets, numStencils + 1 of them; indices; per-stencil weight offsets; the weight pool), or
// LimitStencilTable's five (one size and one offset per stencil, since runs of sources are
// shared; the pool of runs; weight offsets; the pool of weight triples).
class QUADTRI_API PooledTableBuffers {
public:
    int numStencils() const { return numStencils_; }
    int numSourceVertices() const { return numSourceVertices_; }
    VkBuffer offsets() const { return offsets_.buffer(); }
    VkBuffer indices() const { return indices_.buffer(); }
    VkBuffer weightOffsets() const { return weightOffsets_.buffer(); }
    VkBuffer weights() const { return weights_.buffer(); }
    // The index and weight pools as uniform texel buffers (R32_SINT, R32_SFLOAT); VK_NULL_HANDLE
    // where a pool has more elements than the context's texelBufferLimit().
    VkBufferView indexTexels() const { return indexTexels_.view(); }
    VkBufferView weightTexels() const { return weightTexels_.view(); }
    VkDevice device() const { return device_; }

    // A table's arrays as the constructor reads them. sizes null: CSR, stencil i's entries
    // [offsets[i], offsets[i + 1]); else stencil i's are [offsets[i], offsets[i] + sizes[i]).
    // weightsPerEntry: how many weights each entry has in the pool (1, or 3 for a limit table).
    struct HostArrays {
        int numSourceVertices;
        const std::vector<int>* sizes;
        const std::vector<int>& offsets;
        const std::vector<int>& indices;
        const std::vector<int>& weightOffsets;
        const std::vector<float>& weights;
        int weightsPerEntry;
    };

protected:
    // Copies the arrays through one staging buffer (waits); std::invalid_argument naming `table`
    // ("StencilTable") when they are inconsistent: arrays of the wrong lengths, or a stencil whose
    // entries or weights reach outside their arrays (the shader would read past them).
    PooledTableBuffers(VulkanContext& ctx, const HostArrays& arrays, const char* table);

    // The per-stencil sizes (VK_NULL_HANDLE for a CSR table).
    VkBuffer sizes() const { return sizes_.buffer(); }

private:
    VkDevice device_;
    int numStencils_ = 0, numSourceVertices_ = 0;
    DeviceBuffer sizes_, offsets_, indices_, weightOffsets_, weights_;
    TexelView indexTexels_, weightTexels_;
};

}  // namespace detail

class QUADTRI_API VulkanStencilTable : public detail::PooledTableBuffers {
public:
    VulkanStencilTable(VulkanContext& ctx, const StencilTable& table)
        : PooledTableBuffers(ctx, {table.numSourceVertices, nullptr, table.offsets, table.indices, table.weightOffsets,
                                   table.weights, 1},
                             "StencilTable") {}
};

}  // namespace v0
}  // namespace quadtri
