// The MeshNormals loop, shared by the serial and threaded evaluators (and mirrored in GLSL by
// shaders/mesh_normals.comp): vertex v's normal is the normalised sum of the vector areas of the
// faces around it. A face's vector area (doubled) is sum_k (p_k - p_0) x (p_{k+1} - p_0), the same
// for any planar or non-planar polygon as Newell's formula; for a triangle it is (b-a) x (c-a).
#pragma once

#include <cmath>

namespace quadtri {
inline namespace v0 {
namespace kernels {

struct MeshNormalArrays {
    const int* vertexOffsets;  // numVertices + 1
    const int* vertexFaces;
    const int* faceOffsets;
    const int* faceVerts;
};

// Adds face f's doubled vector area to n.
inline void addFaceArea(const float* src, int stride, const MeshNormalArrays& t, int f, float n[3]) {
    const int* c = t.faceVerts + t.faceOffsets[f];
    const int size = t.faceOffsets[f + 1] - t.faceOffsets[f];
    const float* p0 = src + static_cast<long>(c[0]) * stride;
    const float* p1 = src + static_cast<long>(c[1]) * stride;
    float a[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    for (int k = 2; k < size; ++k) {
        const float* p = src + static_cast<long>(c[k]) * stride;
        const float b[3] = {p[0] - p0[0], p[1] - p0[1], p[2] - p0[2]};
        n[0] += a[1] * b[2] - a[2] * b[1];
        n[1] += a[2] * b[0] - a[0] * b[2];
        n[2] += a[0] * b[1] - a[1] * b[0];
        a[0] = b[0], a[1] = b[1], a[2] = b[2];
    }
}

// n scaled to unit length; (0, 0, 0) stays (0, 0, 0).
inline void normalizeInto(const float n[3], float* d) {
    const float len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const float s = len2 > 0.0f ? 1.0f / std::sqrt(len2) : 0.0f;
    d[0] = n[0] * s, d[1] = n[1] * s, d[2] = n[2] * s;
}

// The unit normal of vertex v into d[0..2]; (0, 0, 0) for a vertex without faces or whose faces
// have no area.
inline void meshNormal(const float* src, int srcStride, const MeshNormalArrays& t, int v, float* d) {
    float n[3] = {0.0f, 0.0f, 0.0f};
    for (int k = t.vertexOffsets[v]; k < t.vertexOffsets[v + 1]; ++k) addFaceArea(src, srcStride, t, t.vertexFaces[k], n);
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
