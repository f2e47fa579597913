// A StencilTable uploaded once to device-local storage buffers, for VulkanEvaluator.
#pragma once

#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include <quadtri/export.h>
#include <quadtri/far/stencil_table.h>
#include <quadtri/osd/vulkan_context.h>

namespace quadtri {
inline namespace v0 {

// The arrays of a pooled stencil table in device-local storage buffers, as the shaders bind
// them: StencilTable's four (offsets, numStencils + 1 of them; indices; per-stencil weight
// offsets; the weight pool), or LimitStencilTable's five (one size and one offset per stencil,
// since runs of sources are shared; the pool of runs; weight offsets; the pool of weight triples).
// What VulkanStencilTable and VulkanLimitStencilTable share; the buffers themselves are private.
class QUADTRI_API VulkanPooledTable {
public:
    ~VulkanPooledTable();
    VulkanPooledTable(VulkanPooledTable&&) noexcept;
    VulkanPooledTable& operator=(VulkanPooledTable&&) noexcept;

    int numStencils() const;
    int numSourceVertices() const;
    VkBuffer offsets() const;
    VkBuffer indices() const;
    VkBuffer weightOffsets() const;
    VkBuffer weights() const;
    // The index and weight pools as uniform texel buffers (R32_SINT, R32_SFLOAT); VK_NULL_HANDLE
    // where a pool has more elements than the context's texelBufferLimit().
    VkBufferView indexTexels() const;
    VkBufferView weightTexels() const;
    VkDevice device() const;

protected:
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
        // Room in the pools' buffers for what updateStencils appends: half their size again, at
        // least 16 384 elements each (a CSR table's weights; its entries are no pool).
        bool roomToGrow = false;
    };
    // Copies the arrays through one staging buffer (waits); std::invalid_argument naming `table`
    // ("StencilTable") when they are inconsistent: arrays of the wrong lengths, or a stencil whose
    // entries or weights reach outside their arrays (the shader would read past them).
    VulkanPooledTable(VulkanContext& ctx, const HostArrays& arrays, const char* table);
    // The per-stencil sizes (VK_NULL_HANDLE for a CSR table).
    VkBuffer sizes() const;
    // For a table made with roomToGrow: `stencils` (sorted) written again from `arrays`, the host
    // table as changed since this copy was made or last updated, its pools only grown at their
    // ends (a CSR table's entries where they were); and the pools' new ends (waits). False, with
    // nothing changed, where that is not so (the pools shrank or outgrew their room, the entries
    // moved, the stencil count changed): make a new copy then. std::invalid_argument where a
    // written stencil reaches outside the arrays.
    bool updateStencils(VulkanContext& ctx, const HostArrays& arrays, const std::vector<int>& stencils);

private:
    struct Buffers;
    std::unique_ptr<Buffers> buffers_;
};

class QUADTRI_API VulkanStencilTable : public VulkanPooledTable {
public:
    // `updatable`: the weight pool gets room for what an edit appends (half its size again, at
    // least 16 384 floats), so that update() can write an edit's changes by range.
    VulkanStencilTable(VulkanContext& ctx, const StencilTable& table, bool updatable = false)
        : VulkanPooledTable(ctx, {table.numSourceVertices, nullptr, table.offsets, table.indices, table.weightOffsets,
                                  table.weights, 1, updatable},
                            "StencilTable") {}

    // After an edit changed `stencils` of the host table this copy was made (or last updated)
    // from without moving its entries (EditedLevel::tableResized and poolLaidOut false, as
    // Refiner::applyEdits reports them for a per-level table; likewise StencilTableChange): their
    // indices and weight offsets and the pool's new end uploaded (waits). False, with nothing
    // changed, where it cannot be: copy the table again then.
    bool update(VulkanContext& ctx, const StencilTable& table, const std::vector<int>& stencils, bool resized,
                bool poolLaidOut) {
        if (resized || poolLaidOut) return false;
        return updateStencils(ctx, {table.numSourceVertices, nullptr, table.offsets, table.indices, table.weightOffsets,
                                    table.weights, 1, true},
                              stencils);
    }
};

}  // namespace v0
}  // namespace quadtri
