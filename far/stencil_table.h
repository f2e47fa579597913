// Sparse stencil tables in CSR form: refined vertex i = sum_k weights[offsets[i]+k] * src[indices[offsets[i]+k]].
#pragma once

#include <cstddef>
#include <vector>

namespace quadtri {

struct StencilTable {
    int numSourceVertices = 0;  // size of the vertex set the indices point into
    std::vector<int> sizes;     // entries per stencil
    std::vector<int> offsets;   // first entry of each stencil
    std::vector<int> indices;   // source vertex of each entry
    std::vector<float> weights; // weight of each entry

    int numStencils() const { return int(sizes.size()); }
    std::size_t numEntries() const { return indices.size(); }
    // Bytes of the four arrays.
    std::size_t bytes() const {
        return sizes.size() * sizeof(int) + offsets.size() * sizeof(int) + indices.size() * sizeof(int) +
               weights.size() * sizeof(float);
    }
};

// The same table with double weights: how the analyzer builds and composes tables.
struct StencilTableD {
    int numSourceVertices = 0;
    std::vector<int> sizes;
    std::vector<int> offsets;
    std::vector<int> indices;
    std::vector<double> weights;
};

// The float table stored for evaluation, and back.
StencilTable toFloatTable(const StencilTableD& table);
StencilTableD toDoubleTable(const StencilTable& table);

// outer ∘ inner: stencils of `outer` (over inner's stencils) expanded over inner's sources.
StencilTableD composeStencils(const StencilTableD& outer, const StencilTableD& inner);

}  // namespace quadtri
