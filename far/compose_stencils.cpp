// Composition of stencil tables: a table over another table's stencils expanded over that
// table's sources, in double, one stencil at a time through a dense scatter row. The outer table
// is read as it is stored (a float table's weights widen to double exactly), and the last
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

// The outer table's stencil i: entries [begin(i), end(i)), entry k's parent and weight.
struct DoubleOuter {
    const StencilTableD& t;
    int numStencils() const { return int(t.sizes.size()); }
    int begin(int i) const { return t.offsets[i]; }
    int end(int i) const { return t.offsets[i] + t.sizes[i]; }
    double weight(int, int k) const { return t.weights[k]; }
    const int* parents() const { return t.indices.data(); }
};

struct FloatOuter {
    const StencilTable& t;
    int numStencils() const { return t.numStencils(); }
    int begin(int i) const { return t.offsets[i]; }
    int end(int i) const { return t.offsets[i + 1]; }
    double weight(int i, int k) const { return double(t.weights[std::size_t(t.weightOffsets[i] + k - t.offsets[i])]); }
    const int* parents() const { return t.indices.data(); }
};

// Entries a double result of n stencils may hold within maxBytes, and within its int offsets.
std::size_t entryLimit(int n, std::size_t maxBytes) {
    const std::size_t perStencil = std::size_t(n) * kStencilBytes;
    if (perStencil > maxBytes) throw std::length_error("stencil table over its memory budget");
    return std::min<std::size_t>((maxBytes - perStencil) / kEntryBytes, (1u << 31) - 1);
}

// Entries to reserve for the result: at least its largest inner stencil per outer stencil (nearly
// all of it a level or two down, where a vertex point's own parent's stencil covers the others),
// and an eighth more, so that the arrays are seldom grown and copied, within `limit`.
template <class Outer>
std::size_t expectedEntries(const Outer& outer, const StencilTableD& inner, std::size_t limit) {
    std::size_t atLeast = 0;
    const int* parents = outer.parents();
    for (int i = 0; i < outer.numStencils(); ++i) {
        int largest = 0;
        for (int k = outer.begin(i); k < outer.end(i); ++k) largest = std::max(largest, inner.sizes[parents[k]]);
        atLeast += std::size_t(largest);
    }
    return std::min(limit, atLeast + atLeast / 8);
}

// Stencil i of outer ∘ inner into `row`: each outer entry's inner stencil, scaled by its weight,
// in entry order, so every sum is added up in the same order whatever the row's layout.
template <class Outer>
void composeOne(const Outer& outer, const StencilTableD& inner, int i, ScatterRow& row) {
    const int begin = outer.begin(i), end = outer.end(i);
    const int* parents = outer.parents();
    const int *sizes = inner.sizes.data(), *offsets = inner.offsets.data();
    int terms = 0;
    for (int k = begin; k < end; ++k) terms += sizes[parents[k]];
    row.reserve(terms);
    for (int k = begin; k < end; ++k) {
        const int j = parents[k];
        row.addScaled(inner.indices.data() + offsets[j], inner.weights.data() + offsets[j], sizes[j], outer.weight(i, k));
    }
}

// Grows `v` to hold `needed` (half as much again), never past `limit` elements, so that a
// refusal comes before the allocation that would pass the budget.
template <class V>
void reserveFor(V& v, std::size_t needed, std::size_t limit) {
    if (needed > v.capacity()) v.reserve(std::min(limit, needed + needed / 2));
}

template <class Outer>
StencilTableD composeDouble(const Outer& outer, const StencilTableD& inner, std::size_t maxBytes) {
    StencilTableD result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = outer.numStencils();
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.sizes.reserve(n);
    result.offsets.reserve(n);
    const std::size_t expected = expectedEntries(outer, inner, maxEntries);
    result.indices.reserve(expected);
    result.weights.reserve(expected);
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

template <class Outer>
StencilTable composeFloat(const Outer& outer, const StencilTableD& inner, std::size_t maxBytes) {
    StencilTable result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = outer.numStencils();
    const std::size_t maxEntries = entryLimit(n, maxBytes);
    result.offsets.reserve(std::size_t(n) + 1);
    result.weightOffsets.reserve(n);
    result.indices.reserve(expectedEntries(outer, inner, maxEntries));
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

}  // namespace

StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes) {
    return composeDouble(DoubleOuter{outer}, inner, maxBytes);
}

StencilTableD composeStencils(const StencilTable& outer, const StencilTableD& inner, std::size_t maxBytes) {
    return composeDouble(FloatOuter{outer}, inner, maxBytes);
}

StencilTable composeStencilsToFloat(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes) {
    return composeFloat(DoubleOuter{outer}, inner, maxBytes);
}

StencilTable composeStencilsToFloat(const StencilTable& outer, const StencilTableD& inner, std::size_t maxBytes) {
    return composeFloat(FloatOuter{outer}, inner, maxBytes);
}

}  // namespace v0
}  // namespace quadtri
