// The MeshNormals loops, shared by the serial and threaded evaluators (the GLSL shaders sum the
// table's corner triples instead): vertex v's normal is the normalised sum, in face order, of the
// vector areas of its faces (MeshNormalTable). Two ways to the same bits: per vertex, gathering
// its faces (meshNormal: ranges, seam vertices, the limit kernel's fallback), or for a whole
// level face by face, adding each face's area into its corners' rows (kernels/mesh_normal_kernel.cpp:
// the faces' order keeps the corners' positions and rows in cache, where the vertices' order
// scatters them).
#pragma once

#include <cmath>

#include <quadtri/far/mesh_normal_table.h>

namespace quadtri {
inline namespace v0 {
namespace kernels {

struct MeshNormalArrays {
    const int* faceOffsets;        // drawn faces + 1
    const int* faceCorners;        // flagged (MeshNormalTable::kSeamCorner)
    const int* vertexFaceOffsets;  // numVertices + 1
    const int* vertexFaces;
};

// n scaled to unit length; (0, 0, 0) stays (0, 0, 0). d may be n.
inline void normalizeInto(const float n[3], float* d) {
    const float len2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const float s = len2 > 0.0f ? 1.0f / std::sqrt(len2) : 0.0f;
    d[0] = n[0] * s, d[1] = n[1] * s, d[2] = n[2] * s;
}

inline const float* cornerPosition(const float* src, int srcStride, int corner) {
    return src + static_cast<long>(corner & MeshNormalTable::kCornerIndexMask) * srcStride;
}

// a = (r - p) x (s - q) for corners (p, q, r, s): twice the vector area of a quad.
inline void addFacet(const float* src, int srcStride, int p, int q, int r, int s, float* a, bool first) {
    const float* P = cornerPosition(src, srcStride, p);
    const float* Q = cornerPosition(src, srcStride, q);
    const float* R = cornerPosition(src, srcStride, r);
    const float* S = cornerPosition(src, srcStride, s);
    const float x[3] = {R[0] - P[0], R[1] - P[1], R[2] - P[2]};
    const float y[3] = {S[0] - Q[0], S[1] - Q[1], S[2] - Q[2]};
    const float c[3] = {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    if (first) {
        a[0] = c[0], a[1] = c[1], a[2] = c[2];
    } else {
        a[0] += c[0], a[1] += c[1], a[2] += c[2];
    }
}

// Twice the vector area of the face with corners c[0..n) into a: a triangle as the quad
// (c0, c1, c2, c2), a larger face as a fan of quads (c0, ck, ck+1, ck+2) closed by such a triangle
// when n is odd (docs/limit_evaluation.md).
inline void faceArea(const float* src, int srcStride, const int* c, int n, float* a) {
    if (n == 3) {
        addFacet(src, srcStride, c[0], c[1], c[2], c[2], a, true);
        return;
    }
    addFacet(src, srcStride, c[0], c[1], c[2], c[3], a, true);
    int k = 3;
    for (; k + 2 < n; k += 2) addFacet(src, srcStride, c[0], c[k], c[k + 1], c[k + 2], a, false);
    if (k + 1 < n) addFacet(src, srcStride, c[0], c[k], c[k + 1], c[k + 1], a, false);
}

// The sum of vertex v's faces' areas into n[0..2].
inline void sumOfFaces(const float* src, int srcStride, const MeshNormalArrays& t, int v, float* n) {
    n[0] = n[1] = n[2] = 0.0f;
    for (int k = t.vertexFaceOffsets[v]; k < t.vertexFaceOffsets[v + 1]; ++k) {
        const int f = t.vertexFaces[k];
        float a[3];
        faceArea(src, srcStride, t.faceCorners + t.faceOffsets[f], t.faceOffsets[f + 1] - t.faceOffsets[f], a);
        n[0] += a[0], n[1] += a[1], n[2] += a[2];
    }
}

// The unit normal of vertex v into d[0..2]; (0, 0, 0) for a vertex without faces or whose faces
// have no area.
inline void meshNormal(const float* src, int srcStride, const MeshNormalArrays& t, int v, float* d) {
    float n[3];
    sumOfFaces(src, srcStride, t, v, n);
    normalizeInto(n, d);
}

// Vertices [start, end) one at a time; src and dst point at element 0 (descriptor offsets applied).
inline void evalMeshNormals(const float* src, int srcStride, float* dst, int dstStride, const MeshNormalArrays& t,
                            int start, int end) {
    for (int v = start; v < end; ++v) meshNormal(src, srcStride, t, v, dst + static_cast<long>(v) * dstStride);
}

// A whole level, serially: rows [0, numVertices) zeroed, every face added into its corners' rows
// in face order, the rows normalised (kernels/mesh_normal_kernel.cpp).
void meshNormalsOfLevel(const float* src, int srcStride, float* dst, int dstStride, const MeshNormalArrays& t,
                        int numVertices, int numFaces);

// The same in parallel pieces: zeroRows over all rows; scatterChunk over the table's chunks of
// faces (seam vertices' corners left out, so chunks write disjoint rows); sumOfFaces into each
// seam vertex's row; normalizeRows over all rows.
void zeroRows(float* dst, int dstStride, int start, int end);
void scatterChunk(const float* src, int srcStride, float* dst, int dstStride, const MeshNormalArrays& t, int begin,
                  int end);
void normalizeRows(float* dst, int dstStride, int start, int end);

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
