// Sparse stencil tables: refined vertex i = sum_k w_i[k] * src[indices[offsets[i] + k]] for
// k < size(i), with w_i = weightsOf(i).
#pragma once

#include <cstddef>
#include <vector>

namespace quadtri {
inline namespace v0 {

// What the evaluators read. Indices are CSR; the weights live in a pool in which identical
// sequences are stored once (WeightPool), each stencil pointing at its own. After a level or two
// nearly every stencil is one of a handful of regular masks, so the pool stays a few cache lines
// and the table costs 4 bytes per entry and 8 per stencil instead of 8 and 8 (OpenSubdiv's layout).
struct StencilTable {
    int numSourceVertices = 0;       // size of the vertex set the indices point into
    std::vector<int> offsets{0};     // numStencils() + 1: stencil i's entries are [offsets[i], offsets[i+1])
    std::vector<int> indices;        // source vertex of each entry
    std::vector<int> weightOffsets;  // per stencil: its size(i) weights start at weights[weightOffsets[i]]
    std::vector<float> weights;      // the pool, shared by stencils with bitwise-equal weights

    int numStencils() const { return int(weightOffsets.size()); }
    int size(int i) const { return offsets[i + 1] - offsets[i]; }
    const float* weightsOf(int i) const { return weights.data() + weightOffsets[i]; }
    std::size_t numEntries() const { return indices.size(); }
    // Bytes of the four arrays.
    std::size_t bytes() const {
        return (offsets.size() + indices.size() + weightOffsets.size()) * sizeof(int) + weights.size() * sizeof(float);
    }
};

}  // namespace v0
}  // namespace quadtri
