// Float arrays seen as the vertices Far::StencilTable::UpdateValues (and LimitStencilTable's
// UpdateDerivs) index: operator[] gives a vertex with Clear and AddWithWeight, which sum in the
// order of every other evaluation path, so the results are bitwise theirs.
#pragma once

#include <cstddef>

namespace quadtri::bench {

template <int Width, class Float>
struct VertexView {
    Float* data;
    struct Vertex {
        Float* p;
        void Clear() {
            for (int c = 0; c < Width; ++c) p[c] = 0.0f;
        }
        template <class Source>
        void AddWithWeight(const Source& src, float weight) {
            for (int c = 0; c < Width; ++c) p[c] += weight * src.p[c];
        }
    };
    Vertex operator[](int i) const { return {data + std::ptrdiff_t(i) * Width}; }
};

}  // namespace quadtri::bench
