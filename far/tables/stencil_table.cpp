// Conversion of built (double) tables to stored (float, weight-pooled) ones and back.
#include <quadtri/far/stencil_table.h>

#include "far/tables/weight_pool.h"
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

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

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
