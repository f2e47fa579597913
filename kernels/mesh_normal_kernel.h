// The MeshNormals loops, shared by the serial and threaded evaluators (and, through the table's
// corner triples, mirrored in GLSL by shaders/mesh_normals.comp): vertex v's normal is the
// normalised sum of the vector areas of the facets of its faces (MeshNormalTable), a facet
// (p, q, r, s) having (r - p) x (s - q). Two ways to the same bits: per vertex, each facet's
// area computed at every corner that needs it (meshNormal: the limit kernel's fallback and short
// ranges), or each facet's area once into a scratch and then per-vertex sums of them.
#pragma once

#include <cmath>

namespace quadtri {
inline namespace v0 {
namespace kernels {

struct MeshNormalArrays {
    const int* facets;        // 4 corners per facet
    const int* facetOffsets;  // numVertices + 1
    const int* vertexFacets;  // vertex v's facets: [facetOffsets[v], facetOffsets[v + 1])
};

// n scaled to unit length; (0, 0, 0) stays (0, 0, 0).
inline void normalizeInto(const float n[3], float* d) {
    const float len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const float s = len2 > 0.0f ? 1.0f / std::sqrt(len2) : 0.0f;
    d[0] = n[0] * s, d[1] = n[1] * s, d[2] = n[2] * s;
}

// The vector area (r - p) x (s - q) of facet f = (p, q, r, s) into a[0..2]. The AVX2 loop
// (mesh_normal_kernel_avx2.cpp) rounds each lane exactly as this does.
inline void facetArea(const float* src, int srcStride, const int* f, float* a) {
    const float* p = src + static_cast<long>(f[0]) * srcStride;
    const float* q = src + static_cast<long>(f[1]) * srcStride;
    const float* r = src + static_cast<long>(f[2]) * srcStride;
    const float* s = src + static_cast<long>(f[3]) * srcStride;
    const float x[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const float y[3] = {s[0] - q[0], s[1] - q[1], s[2] - q[2]};
    a[0] = x[1] * y[2] - x[2] * y[1];
    a[1] = x[2] * y[0] - x[0] * y[2];
    a[2] = x[0] * y[1] - x[1] * y[0];
}

// The unit normal of vertex v into d[0..2]; (0, 0, 0) for a vertex without faces or whose faces
// have no area.
inline void meshNormal(const float* src, int srcStride, const MeshNormalArrays& t, int v, float* d) {
    float n[3] = {0.0f, 0.0f, 0.0f};
    for (int k = t.facetOffsets[v]; k < t.facetOffsets[v + 1]; ++k) {
        float a[3];
        facetArea(src, srcStride, t.facets + 4 * static_cast<long>(t.vertexFacets[k]), a);
        n[0] += a[0], n[1] += a[1], n[2] += a[2];
    }
    normalizeInto(n, d);
}

// Vertices [start, end) in one pass; src and dst point at element 0 (descriptor offsets applied).
inline void evalMeshNormals(const float* src, int srcStride, float* dst, int dstStride, const MeshNormalArrays& t,
                            int start, int end) {
    for (int v = start; v < end; ++v) meshNormal(src, srcStride, t, v, dst + static_cast<long>(v) * dstStride);
}

// The first of the two passes: the areas of facets [begin, end) into areas[3 f .. 3 f + 2].
void evalFacetAreas(const float* src, int srcStride, const int* facets, int begin, int end, float* areas);

// The second: vertices [start, end)'s normals from the facets' areas, summed in the order
// meshNormal sums them.
inline void sumFacetAreas(const float* areas, const MeshNormalArrays& t, float* dst, int dstStride, int start,
                          int end) {
    for (int v = start; v < end; ++v) {
        float n[3] = {0.0f, 0.0f, 0.0f};
        for (int k = t.facetOffsets[v]; k < t.facetOffsets[v + 1]; ++k) {
            const float* a = areas + 3 * static_cast<long>(t.vertexFacets[k]);
            n[0] += a[0], n[1] += a[1], n[2] += a[2];
        }
        normalizeInto(n, dst + static_cast<long>(v) * dstStride);
    }
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
