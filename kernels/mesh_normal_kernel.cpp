// The whole-level loops of kernels/mesh_normal_kernel.h, in a file of their own: inlined into the
// evaluators' files they ran 25-45 % slower (GCC 12, the bench tori at levels 3-4).
#include "kernels/mesh_normal_kernel.h"

#include <type_traits>

namespace quadtri {
inline namespace v0 {
namespace kernels {

namespace {

// The whole-level loops take `packed`: both strides are 3 (the common layout), known to the
// compiler, which can then vectorise the row loops and share a corner's offset between its
// position and its row.
template <class Body>
void withPackedStrides(int srcStride, int dstStride, Body&& body) {
    if (srcStride == 3 && dstStride == 3)
        body(std::true_type{});
    else
        body(std::false_type{});
}

template <bool packed>
void zeroRowsWith(float* dst, int dstStride, int start, int end) {
    if (packed) dstStride = 3;
    for (long v = start; v < end; ++v) dst[v * dstStride] = dst[v * dstStride + 1] = dst[v * dstStride + 2] = 0.0f;
}

template <bool packed>
void normalizeRowsWith(float* dst, int dstStride, int start, int end) {
    if (packed) dstStride = 3;
    for (long v = start; v < end; ++v) normalizeInto(dst + v * dstStride, dst + v * dstStride);
}

// Asks for the position and the row of a corner that comes soon: the corners' vertices are spread
// over the level (its face, edge and vertex points lie in three ranges), so the loads would
// otherwise wait on memory one after the other.
inline void prefetchCorner(const float* src, int srcStride, const float* dst, int dstStride, int corner) {
#if defined(__GNUC__)
    const long v = corner & MeshNormalTable::kCornerIndexMask;
    __builtin_prefetch(src + v * srcStride);
    __builtin_prefetch(dst + v * dstStride, 1);
#else
    (void)src, (void)srcStride, (void)dst, (void)dstStride, (void)corner;
#endif
}

// How many faces ahead scatterFaces prefetches, and how many of their corners (every face has 3).
constexpr int kPrefetchFaces = 12, kPrefetchCorners = 3;

// Faces [begin, end) added into their corners' rows of dst (zeroed before the first face). With
// skipSeams (a chunk run beside others) a seam vertex's corners are skipped (1-4 % of them, so
// the branch is well predicted).
template <bool packed, bool skipSeams>
void scatterFaces(const float* src, int srcStride, float* dst, int dstStride, const MeshNormalArrays& t,
                      int begin, int end) {
    if (packed) srcStride = dstStride = 3;
    for (int f = begin; f < end; ++f) {
        const int* c = t.faceCorners + t.faceOffsets[f];
        const int n = t.faceOffsets[f + 1] - t.faceOffsets[f];
        if (f + kPrefetchFaces < end) {
            const int* ahead = t.faceCorners + t.faceOffsets[f + kPrefetchFaces];
            for (int k = 0; k < kPrefetchCorners; ++k) prefetchCorner(src, srcStride, dst, dstStride, ahead[k]);
        }
        float a[3];
        faceArea(src, srcStride, c, n, a);
        for (int k = 0; k < n; ++k) {
            if (skipSeams && (c[k] & MeshNormalTable::kSeamCorner)) continue;
            float* d = dst + static_cast<long>(c[k] & MeshNormalTable::kCornerIndexMask) * dstStride;
            d[0] += a[0], d[1] += a[1], d[2] += a[2];
        }
    }
}

}  // namespace

void meshNormalsOfLevel(const float* src, int srcStride, float* dst, int dstStride, const MeshNormalArrays& t,
                        int numVertices, int numFaces) {
    withPackedStrides(srcStride, dstStride, [&](auto packed) {
        constexpr bool p = decltype(packed)::value;
        zeroRowsWith<p>(dst, dstStride, 0, numVertices);
        scatterFaces<p, false>(src, srcStride, dst, dstStride, t, 0, numFaces);
        normalizeRowsWith<p>(dst, dstStride, 0, numVertices);
    });
}

void zeroRows(float* dst, int dstStride, int start, int end) {
    withPackedStrides(3, dstStride,
                      [&](auto packed) { zeroRowsWith<decltype(packed)::value>(dst, dstStride, start, end); });
}

void scatterChunk(const float* src, int srcStride, float* dst, int dstStride, const MeshNormalArrays& t, int begin,
                  int end) {
    withPackedStrides(srcStride, dstStride, [&](auto packed) {
        scatterFaces<decltype(packed)::value, true>(src, srcStride, dst, dstStride, t, begin, end);
    });
}

void normalizeRows(float* dst, int dstStride, int start, int end) {
    withPackedStrides(3, dstStride,
                      [&](auto packed) { normalizeRowsWith<decltype(packed)::value>(dst, dstStride, start, end); });
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
