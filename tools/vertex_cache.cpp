// meshoptimizer's vertex cache and vertex fetch orders applied to DrawBuffers: the index buffer
// is reordered by meshopt_optimizeVertexCache, then the vertices renumbered by
// meshopt_optimizeVertexFetchRemap; the maps back to the level follow the renumbering.
#include "tools/vertex_cache.h"

#include <vector>

#include <meshoptimizer.h>

namespace quadtri::io {

void optimizeVertexCache(DrawBuffers& b) {
    const std::size_t n = std::size_t(b.numVertices());
    std::vector<unsigned> reordered(b.triangles.size());
    meshopt_optimizeVertexCache(reordered.data(), b.triangles.data(), b.triangles.size(), n);
    std::vector<unsigned> remap(n);
    const std::size_t used = meshopt_optimizeVertexFetchRemap(remap.data(), reordered.data(), reordered.size(), n);
    meshopt_remapIndexBuffer(b.triangles.data(), reordered.data(), reordered.size(), remap.data());
    // Every draw vertex is used by a triangle (buildDrawBuffers makes them from drawn corners),
    // so the remap is a permutation: used == n.
    std::vector<int> vertexOf(used);
    for (std::size_t d = 0; d < n; ++d)
        if (remap[d] != ~0u) vertexOf[remap[d]] = b.vertexOf[d];
    b.vertexOf = std::move(vertexOf);
    for (std::vector<int>& values : b.valueOf) {
        std::vector<int> moved(used);
        for (std::size_t d = 0; d < n; ++d)
            if (remap[d] != ~0u) moved[remap[d]] = values[d];
        values = std::move(moved);
    }
}

double averageCacheMissRatio(const DrawBuffers& b, unsigned cacheSize) {
    return meshopt_analyzeVertexCache(b.triangles.data(), b.triangles.size(), std::size_t(b.numVertices()), cacheSize,
                                      0, 0)
        .acmr;
}

}  // namespace quadtri::io
