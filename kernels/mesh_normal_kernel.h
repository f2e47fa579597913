// The MeshNormals loop, shared by the serial and threaded evaluators (and mirrored in GLSL by
// shaders/mesh_normals.comp): vertex v's normal is the normalised sum over its triples (a, b, c)
// of (p_b - p_v) x (p_c - p_a), the doubled vector areas of the faces around it (MeshNormalTable).
#pragma once

#include <cmath>

namespace quadtri {
inline namespace v0 {
namespace kernels {

struct MeshNormalArrays {
    const int* offsets;  // numVertices + 1
    const int* corners;  // 3 per triple
};

// n scaled to unit length; (0, 0, 0) stays (0, 0, 0).
inline void normalizeInto(const float n[3], float* d) {
    const float len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const float s = len2 > 0.0f ? 1.0f / std::sqrt(len2) : 0.0f;
    d[0] = n[0] * s, d[1] = n[1] * s, d[2] = n[2] * s;
}

// The unit normal of vertex v into d[0..2]; (0, 0, 0) for a vertex without faces or whose faces
// have no area.
inline void meshNormal(const float* src, int srcStride, const MeshNormalArrays& t, int v, float* d) {
    const float* p = src + static_cast<long>(v) * srcStride;
    float n[3] = {0.0f, 0.0f, 0.0f};
    for (int k = t.offsets[v]; k < t.offsets[v + 1]; ++k) {
        const int* c = t.corners + 3 * static_cast<long>(k);
        const float* a = src + static_cast<long>(c[0]) * srcStride;
        const float* b = src + static_cast<long>(c[1]) * srcStride;
        const float* e = src + static_cast<long>(c[2]) * srcStride;
        const float x[3] = {b[0] - p[0], b[1] - p[1], b[2] - p[2]};
        const float y[3] = {e[0] - a[0], e[1] - a[1], e[2] - a[2]};
        n[0] += x[1] * y[2] - x[2] * y[1];
        n[1] += x[2] * y[0] - x[0] * y[2];
        n[2] += x[0] * y[1] - x[1] * y[0];
    }
    normalizeInto(n, d);
}

// Vertices [start, end); src and dst point at element 0 (descriptor offsets applied).
inline void evalMeshNormals(const float* src, int srcStride, float* dst, int dstStride, const MeshNormalArrays& t,
                            int start, int end) {
    for (int v = start; v < end; ++v) meshNormal(src, srcStride, t, v, dst + static_cast<long>(v) * dstStride);
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
