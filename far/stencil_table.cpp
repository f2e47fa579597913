// Conversion of built (double) tables to stored (float) ones, and composition of per-level
// tables into factorized ones.
#include "far/stencil_table.h"

#include "far/sparse_accumulator.h"

namespace quadtri {

namespace {

// The same CSR arrays with the weights converted.
template <typename Out, typename In>
Out convertWeights(const In& in) {
    Out out;
    out.numSourceVertices = in.numSourceVertices;
    out.sizes = in.sizes;
    out.offsets = in.offsets;
    out.indices = in.indices;
    out.weights.assign(in.weights.begin(), in.weights.end());
    return out;
}

}  // namespace

StencilTable toFloatTable(const StencilTableD& d) { return convertWeights<StencilTable>(d); }

StencilTableD toDoubleTable(const StencilTable& t) { return convertWeights<StencilTableD>(t); }

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
