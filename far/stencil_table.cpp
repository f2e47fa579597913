// Conversion of built (double) tables to stored (float, weight-pooled) ones and back, and
// composition of per-level tables into factorized ones.
#include "far/stencil_table.h"

#include "far/sparse_accumulator.h"
#include "far/weight_pool.h"

namespace quadtri {

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
    out.weights = pool.takeWeights();
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

StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner) {
    StencilTableD result;
    result.numSourceVertices = inner.numSourceVertices;
    const int n = int(outer.sizes.size());
    result.sizes.reserve(n);
    result.offsets.reserve(n);
    SparseAccumulator acc(inner.numSourceVertices);
    for (int i = 0; i < n; ++i) {
        for (int k = outer.offsets[i]; k < outer.offsets[i] + outer.sizes[i]; ++k) {
            const int j = outer.indices[k];
            const double w = outer.weights[k];
            for (int m = inner.offsets[j]; m < inner.offsets[j] + inner.sizes[j]; ++m)
                acc.add(inner.indices[m], w * inner.weights[m]);
        }
        result.offsets.push_back(int(result.indices.size()));
        result.sizes.push_back(acc.flush(result.indices, result.weights));
    }
    return result;
}

}  // namespace quadtri
