// Composition of stencil tables: a table over another table's stencils expanded over that
// table's sources, in double, one stencil at a time through a dense scatter row. The last
// composition of a factorized table can go straight to the stored float table.
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "far/internal/scatter_row.h"
#include "far/internal/stencil_table_double.h"
#include "far/internal/weight_pool.h"

namespace quadtri {
inline namespace v0 {

namespace {

// Bytes of the double result: an index and a weight per entry, a size and an offset per stencil.
constexpr std::size_t kEntryBytes = sizeof(int) + sizeof(double), kStencilBytes = 2 * sizeof(int);

// Entries a double result of n stencils may hold within maxBytes, and within its int offsets.
std::size_t entryLimit(int n, std::size_t maxBytes) {
    const std::size_t perStencil = std::size_t(n) * kStencilBytes;
    if (perStencil > maxBytes) throw std::length_error("stencil table over its memory budget");
    return std::min<std::size_t>((maxBytes - perStencil) / kEntryBytes, (1u << 31) - 1);
}

// Stencil i of outer ∘ inner into `row`: each outer entry's inner stencil, scaled by its weight,
// in entry order, so every sum is added up in the same order whatever the row's layout.
void composeOne(const StencilTableD& outer, const StencilTableD& inner, int i, ScatterRow& row) {
    const int end = outer.offsets[i] + outer.sizes[i];
    for (int k = outer.offsets[i]; k < end; ++k) {
        const int j = outer.indices[k];
        const double w = outer.weights[k];
        const int first = inner.offsets[j];
        row.addScaled(inner.indices.data() + first, inner.weights.data() + first, inner.sizes[j], w);
    }
}

// Grows `v` by doubling up to `limit` elements, so that a refusal comes before the allocation
// that would pass the budget.
template <class V>
void reserveFor(V& v, std::size_t needed, std::size_t limit) {
    if (needed > v.capacity()) v.reserve(std::min(limit, 2 * needed));
}

}  // namespace

StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes) {
    StencilTableD result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = int(outer.sizes.size());
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.sizes.reserve(n);
    result.offsets.reserve(n);
    result.indices.reserve(std::min(maxEntries, outer.indices.size()));
    result.weights.reserve(std::min(maxEntries, outer.indices.size()));
    ScatterRow row(inner.numSourceVertices);
    for (int i = 0; i < n; ++i) {
        composeOne(outer, inner, i, row);
        const std::size_t at = result.indices.size(), needed = at + std::size_t(row.size());
        if (needed > maxEntries) throw std::length_error("stencil table over its memory budget");
        reserveFor(result.indices, needed, maxEntries);
        reserveFor(result.weights, needed, maxEntries);
        result.offsets.push_back(int(at));
        result.sizes.push_back(row.size());
        result.indices.insert(result.indices.end(), row.indices(), row.indices() + row.size());
        result.weights.insert(result.weights.end(), row.weights(), row.weights() + row.size());
        row.clear();
    }
    return result;
}

StencilTable composeStencilsToFloat(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes) {
    StencilTable result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = int(outer.sizes.size());
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.offsets.reserve(std::size_t(n) + 1);
    result.weightOffsets.reserve(n);
    result.indices.reserve(std::min(maxEntries, outer.indices.size()));
    ScatterRow row(inner.numSourceVertices);
    WeightPool pool;
    std::vector<float> rounded;  // one stencil's weights, reused
    for (int i = 0; i < n; ++i) {
        composeOne(outer, inner, i, row);
        const int size = row.size();
        const std::size_t needed = result.indices.size() + std::size_t(size);
        if (needed > maxEntries) throw std::length_error("stencil table over its memory budget");
        reserveFor(result.indices, needed, maxEntries);
        result.indices.insert(result.indices.end(), row.indices(), row.indices() + size);
        result.offsets.push_back(int(needed));
        rounded.assign(row.weights(), row.weights() + size);
        result.weightOffsets.push_back(pool.intern(rounded.data(), size));
        row.clear();
    }
    result.weights = pool.take();
    return result;
}

}  // namespace v0
}  // namespace quadtri
