// Conversion of built (double) tables to stored (float, weight-pooled) ones and back, and
// composition of per-level tables into factorized ones.
#include <quadtri/far/stencil_table.h>

#include <algorithm>
#include <stdexcept>

#include "far/internal/sparse_accumulator.h"
#include "far/internal/weight_pool.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {

StencilTable toFloatTable(const StencilTableD& d) {
    StencilTable out;
    out.numSourceVertices = d.numSourceVertices;
    const int n = int(d.sizes.size());
    out.offsets.reserve(std::size_t(n) + 1);
    out.weightOffsets.reserve(n);
    out.indices.reserve(d.indices.size());
    WeightPool pool;
    std::vector<float> rounded;  // one stencil's weights, reused
    for (int i = 0; i < n; ++i) {
        const auto first = std::size_t(d.offsets[i]), last = first + std::size_t(d.sizes[i]);
        out.indices.insert(out.indices.end(), d.indices.begin() + first, d.indices.begin() + last);
        out.offsets.push_back(int(out.indices.size()));
        rounded.assign(d.weights.begin() + first, d.weights.begin() + last);
        out.weightOffsets.push_back(pool.intern(rounded.data(), d.sizes[i]));
    }
    out.weights = pool.take();
    return out;
}

StencilTableD toDoubleTable(const StencilTable& t) {
    StencilTableD out;
    out.numSourceVertices = t.numSourceVertices;
    const int n = t.numStencils();
    out.sizes.reserve(n);
    out.offsets.assign(t.offsets.begin(), t.offsets.end() - 1);
    out.indices = t.indices;
    out.weights.reserve(t.indices.size());
    for (int i = 0; i < n; ++i) {
        out.sizes.push_back(t.size(i));
        out.weights.insert(out.weights.end(), t.weightsOf(i), t.weightsOf(i) + t.size(i));
    }
    return out;
}

std::size_t bytesOf(const StencilTableD& t) {
    return (t.sizes.size() + t.offsets.size() + t.indices.size()) * sizeof(int) + t.weights.size() * sizeof(double);
}

StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner, std::size_t maxBytes) {
    StencilTableD result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = int(outer.sizes.size());
    constexpr std::size_t kEntryBytes = sizeof(int) + sizeof(double), kStencilBytes = 2 * sizeof(int);
    const std::size_t perStencil = std::size_t(n) * kStencilBytes;
    if (perStencil > maxBytes) throw std::length_error("stencil table over its memory budget");
    // The entries are not known until composed: grow the arrays by doubling, but never past the
    // budget, so that a refusal comes before the allocation that would break it.
    const std::size_t maxEntries = std::min<std::size_t>((maxBytes - perStencil) / kEntryBytes, (1u << 31) - 1);
    result.sizes.reserve(n);
    result.offsets.reserve(n);
    auto reserveEntries = [&](std::size_t count) {
        result.indices.reserve(count);
        result.weights.reserve(count);
    };
    reserveEntries(std::min(maxEntries, outer.indices.size()));
    SparseAccumulator acc(inner.numSourceVertices);
    for (int i = 0; i < n; ++i) {
        for (int k = outer.offsets[i]; k < outer.offsets[i] + outer.sizes[i]; ++k) {
            const int j = outer.indices[k];
            const double w = outer.weights[k];
            for (int m = inner.offsets[j]; m < inner.offsets[j] + inner.sizes[j]; ++m)
                acc.add(inner.indices[m], w * inner.weights[m]);
        }
        const std::size_t needed = result.indices.size() + std::size_t(acc.size());
        if (needed > maxEntries) throw std::length_error("stencil table over its memory budget");
        if (needed > result.indices.capacity()) reserveEntries(std::min(maxEntries, 2 * needed));
        result.offsets.push_back(int(result.indices.size()));
        result.sizes.push_back(acc.flush(result.indices, result.weights));
    }
    return result;
}

}  // namespace v0
}  // namespace quadtri
