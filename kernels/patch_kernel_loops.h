// The level-patch loops (kernels/patch_kernel.h), compiled twice: for the baseline CPU in
// patch_kernel.cpp and with AVX2 + FMA in patch_kernel_avx2.cpp. Include only there, and in
// test_level_patches, which defines QUADTRI_PORTABLE_PATCH_LOOPS to check the portable loops.
#pragma once

#include <algorithm>
#include <cmath>

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include "kernels/limit_kernel.h"
#include "kernels/patch_kernel.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {
namespace {

#if defined(__AVX2__) && defined(__FMA__) && !defined(QUADTRI_PORTABLE_PATCH_LOOPS)
#define QUADTRI_PATCH_LOOPS_8
#endif

#if defined(QUADTRI_PATCH_LOOPS_8)
// The AVX2 + FMA build: the 8-wide loops below.
#elif defined(__SSE2__) && !defined(QUADTRI_PORTABLE_PATCH_LOOPS)
// The unit normal of tangents u, v at d, (0, 0, 0) where they are parallel: lane by lane the
// scalar unitNormals' arithmetic.
inline void storeNormal(float* d, __m128 u, __m128 v) {
    const __m128 n = yzx(_mm_sub_ps(_mm_mul_ps(u, yzx(v)), _mm_mul_ps(yzx(u), v)));
    const float n2 = _mm_cvtss_f32(dot3(n)), u2 = _mm_cvtss_f32(dot3(u)), v2 = _mm_cvtss_f32(dot3(v));
    const float scale = n2 > kDegenerateSine * kDegenerateSine * u2 * v2 ? 1.0f / std::sqrt(n2) : 0.0f;
    store3(d, _mm_mul_ps(n, _mm_set1_ps(scale)));
}

// A B-spline patch as a tensor product: the rows' curves Q_r(i) = sum_c B_c(i) P_rc and their
// derivatives at every grid line i first, then each output from four of them, x y z in one
// register.
void bSplinePatch(const float* src, int srcStride, const LevelPatchArrays& a, int patch, float* position,
                  int positionStride, float* normal, int normalStride) {
    const int n = a.rate;
    const int* ids = a.patchPoints + a.pointOffsets[patch];
    const __m128 p0 = load3(src + static_cast<long>(ids[0]) * srcStride);
    __m128 q[4][kMaxRate + 1], dq[4][kMaxRate + 1];
    for (int r = 0; r < 4; ++r) {
        __m128 row[4];
        for (int k = 0; k < 4; ++k) row[k] = _mm_sub_ps(load3(src + static_cast<long>(ids[4 * r + k]) * srcStride), p0);
        for (int i = 0; i <= n; ++i) {
            const float* w = a.curveWeights + 8 * i;
            q[r][i] = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(w[0]), row[0]), _mm_mul_ps(_mm_set1_ps(w[1]), row[1])),
                                 _mm_add_ps(_mm_mul_ps(_mm_set1_ps(w[2]), row[2]), _mm_mul_ps(_mm_set1_ps(w[3]), row[3])));
            dq[r][i] = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_set1_ps(w[4]), row[0]), _mm_mul_ps(_mm_set1_ps(w[5]), row[1])),
                                  _mm_add_ps(_mm_mul_ps(_mm_set1_ps(w[6]), row[2]), _mm_mul_ps(_mm_set1_ps(w[7]), row[3])));
        }
    }
    const int first = a.outputOffsets[patch], last = a.outputOffsets[patch + 1];
    int j = -1;
    __m128 w[8] = {};
    for (int o = first; o < last; ++o) {
        const int cell = a.outputCells[o], i = cell & 0xff;
        if ((cell >> 8) != j) {  // outputs come row by row: a row's weights once
            j = cell >> 8;
            for (int k = 0; k < 8; ++k) w[k] = _mm_set1_ps(a.curveWeights[8 * j + k]);
        }
        if (position) {
            const __m128 p = _mm_add_ps(_mm_add_ps(_mm_mul_ps(w[0], q[0][i]), _mm_mul_ps(w[1], q[1][i])),
                                        _mm_add_ps(_mm_mul_ps(w[2], q[2][i]), _mm_mul_ps(w[3], q[3][i])));
            store3(position + static_cast<long>(o) * positionStride, _mm_add_ps(p0, p));
        }
        if (normal) {
            const __m128 u = _mm_add_ps(_mm_add_ps(_mm_mul_ps(w[0], dq[0][i]), _mm_mul_ps(w[1], dq[1][i])),
                                        _mm_add_ps(_mm_mul_ps(w[2], dq[2][i]), _mm_mul_ps(w[3], dq[3][i])));
            const __m128 v = _mm_add_ps(_mm_add_ps(_mm_mul_ps(w[4], q[0][i]), _mm_mul_ps(w[5], q[1][i])),
                                        _mm_add_ps(_mm_mul_ps(w[6], q[2][i]), _mm_mul_ps(w[7], q[3][i])));
            storeNormal(normal + static_cast<long>(o) * normalStride, u, v);
        }
    }
}

// A box-spline patch: each output from its cell's 12 weights (three per point), x y z in one
// register.
void boxSplinePatch(const float* src, int srcStride, const LevelPatchArrays& a, int patch, float* position,
                    int positionStride, float* normal, int normalStride) {
    const int* ids = a.patchPoints + a.pointOffsets[patch];
    __m128 points[12], offsets[12];
    for (int k = 0; k < 12; ++k) points[k] = load3(src + static_cast<long>(ids[k]) * srcStride);
    for (int k = 0; k < 12; ++k) offsets[k] = _mm_sub_ps(points[k], points[0]);
    for (int o = a.outputOffsets[patch]; o < a.outputOffsets[patch + 1]; ++o) {
        const int cell = a.outputCells[o];
        const float* w = a.boxSplineWeights + static_cast<long>((cell >> 8) * (a.rate + 1) + (cell & 0xff)) * 36;
        __m128 p = _mm_setzero_ps(), u = _mm_setzero_ps(), v = _mm_setzero_ps();
        for (int k = 0; k < 12; ++k, w += 3) {
            p = _mm_add_ps(p, _mm_mul_ps(_mm_set1_ps(w[0]), points[k]));
            u = _mm_add_ps(u, _mm_mul_ps(_mm_set1_ps(w[1]), offsets[k]));
            v = _mm_add_ps(v, _mm_mul_ps(_mm_set1_ps(w[2]), offsets[k]));
        }
        if (position) store3(position + static_cast<long>(o) * positionStride, p);
        if (normal) storeNormal(normal + static_cast<long>(o) * normalStride, u, v);
    }
}
#else
// The unit normals of `count` tangent pairs (u, v), (0, 0, 0) where they are parallel, written
// over v: a loop over arrays, which the compiler vectorizes.
void unitNormals(const float* ux, const float* uy, const float* uz, float* vx, float* vy, float* vz, int count) {
    for (int k = 0; k < count; ++k) {
        const float nx = uy[k] * vz[k] - uz[k] * vy[k], ny = uz[k] * vx[k] - ux[k] * vz[k],
                    nz = ux[k] * vy[k] - uy[k] * vx[k];
        const float n2 = nx * nx + ny * ny + nz * nz;
        const float u2 = ux[k] * ux[k] + uy[k] * uy[k] + uz[k] * uz[k], v2 = vx[k] * vx[k] + vy[k] * vy[k] + vz[k] * vz[k];
        const float scale = n2 > kDegenerateSine * kDegenerateSine * u2 * v2 ? 1.0f / std::sqrt(n2) : 0.0f;
        vx[k] = nx * scale, vy[k] = ny * scale, vz[k] = nz * scale;
    }
}

// Box-spline outputs computed before their normals are taken together.
constexpr int kBatch = 64;

struct Batch {
    float p[3][kBatch], u[3][kBatch], v[3][kBatch];
};

// The batch's positions and unit normals, written from output `first` on.
void storeBatch(Batch& b, int count, int first, float* position, int positionStride, float* normal, int normalStride) {
    if (position)
        for (int k = 0; k < count; ++k) {
            float* d = position + static_cast<long>(first + k) * positionStride;
            d[0] = b.p[0][k], d[1] = b.p[1][k], d[2] = b.p[2][k];
        }
    if (!normal) return;
    unitNormals(b.u[0], b.u[1], b.u[2], b.v[0], b.v[1], b.v[2], count);
    for (int k = 0; k < count; ++k) {
        float* d = normal + static_cast<long>(first + k) * normalStride;
        d[0] = b.v[0][k], d[1] = b.v[1][k], d[2] = b.v[2][k];
    }
}

// A B-spline patch as a tensor product: the rows' curves Q_r(i) = sum_c B_c(i) P_rc and their
// derivatives at every grid line i first, then each output from four of them.
void bSplinePatch(const float* src, int srcStride, const LevelPatchArrays& a, int patch, float* position,
                  int positionStride, float* normal, int normalStride) {
    const int n = a.rate;
    const int* ids = a.patchPoints + a.pointOffsets[patch];
    float p0[3];
    for (int c = 0; c < 3; ++c) p0[c] = src[static_cast<long>(ids[0]) * srcStride + c];
    float q[4][3][kMaxRate + 1], dq[4][3][kMaxRate + 1];
    for (int r = 0; r < 4; ++r) {
        float row[4][3];
        for (int k = 0; k < 4; ++k)
            for (int c = 0; c < 3; ++c) row[k][c] = src[static_cast<long>(ids[4 * r + k]) * srcStride + c] - p0[c];
        for (int i = 0; i <= n; ++i) {
            const float* w = a.curveWeights + 8 * i;
            for (int c = 0; c < 3; ++c) {
                q[r][c][i] = w[0] * row[0][c] + w[1] * row[1][c] + w[2] * row[2][c] + w[3] * row[3][c];
                dq[r][c][i] = w[4] * row[0][c] + w[5] * row[1][c] + w[6] * row[2][c] + w[7] * row[3][c];
            }
        }
    }
    // Row by row (a patch's outputs come sorted by cell): every grid point of the row, then
    // its outputs picked from them.
    float row[9][kMaxRate + 1];  // p, u, v, then the normal, x y z each
    const int first = a.outputOffsets[patch], last = a.outputOffsets[patch + 1];
    for (int o = first; o < last;) {
        const int j = a.outputCells[o] >> 8;
        const float* w = a.curveWeights + 8 * j;
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i <= n; ++i) {
                row[c][i] = p0[c] + (w[0] * q[0][c][i] + w[1] * q[1][c][i] + w[2] * q[2][c][i] + w[3] * q[3][c][i]);
                row[3 + c][i] = w[0] * dq[0][c][i] + w[1] * dq[1][c][i] + w[2] * dq[2][c][i] + w[3] * dq[3][c][i];
                row[6 + c][i] = w[4] * q[0][c][i] + w[5] * q[1][c][i] + w[6] * q[2][c][i] + w[7] * q[3][c][i];
            }
        if (normal) unitNormals(row[3], row[4], row[5], row[6], row[7], row[8], n + 1);
        for (; o < last && (a.outputCells[o] >> 8) == j; ++o) {
            const int i = a.outputCells[o] & 0xff;
            if (position) {
                float* d = position + static_cast<long>(o) * positionStride;
                d[0] = row[0][i], d[1] = row[1][i], d[2] = row[2][i];
            }
            if (normal) {
                float* d = normal + static_cast<long>(o) * normalStride;
                d[0] = row[6][i], d[1] = row[7][i], d[2] = row[8][i];
            }
        }
    }
}

// A box-spline patch: each output from its cell's 12 weights (three per point).
void boxSplinePatch(const float* src, int srcStride, const LevelPatchArrays& a, int patch, float* position,
                    int positionStride, float* normal, int normalStride) {
    const int* ids = a.patchPoints + a.pointOffsets[patch];
    float points[12][3], offsets[12][3];
    for (int k = 0; k < 12; ++k)
        for (int c = 0; c < 3; ++c) points[k][c] = src[static_cast<long>(ids[k]) * srcStride + c];
    for (int k = 0; k < 12; ++k)
        for (int c = 0; c < 3; ++c) offsets[k][c] = points[k][c] - points[0][c];
    Batch b;
    const int first = a.outputOffsets[patch], last = a.outputOffsets[patch + 1];
    for (int o = first; o < last; o += kBatch) {
        const int count = std::min(kBatch, last - o);
        for (int k = 0; k < count; ++k) {
            const int cell = a.outputCells[o + k];
            const float* w = a.boxSplineWeights + static_cast<long>((cell >> 8) * (a.rate + 1) + (cell & 0xff)) * 36;
            float p[3] = {}, u[3] = {}, v[3] = {};
            for (int j = 0; j < 12; ++j, w += 3)
                for (int c = 0; c < 3; ++c) {
                    p[c] += w[0] * points[j][c];
                    u[c] += w[1] * offsets[j][c];
                    v[c] += w[2] * offsets[j][c];
                }
            for (int c = 0; c < 3; ++c) b.p[c][k] = p[c], b.u[c][k] = u[c], b.v[c][k] = v[c];
        }
        storeBatch(b, count, o, position, positionStride, normal, normalStride);
    }
}
#endif

#ifdef QUADTRI_PATCH_LOOPS_8
// The AVX2 build evaluates 8 cells of a row at once, lane k at grid line i0 + k, the weights
// read as runs over the grid lines (LevelPatchTable's *Lines arrays): arithmetic rather than
// the shuffles the one-point-a-register SSE loops spend their time on.

// The unit normals of tangents u, v lane by lane, (0, 0, 0) where they are parallel.
inline void unitNormals8(const __m256 u[3], const __m256 v[3], __m256 n[3]) {
    n[0] = _mm256_fmsub_ps(u[1], v[2], _mm256_mul_ps(u[2], v[1]));
    n[1] = _mm256_fmsub_ps(u[2], v[0], _mm256_mul_ps(u[0], v[2]));
    n[2] = _mm256_fmsub_ps(u[0], v[1], _mm256_mul_ps(u[1], v[0]));
    auto dot = [](const __m256 a[3]) {
        return _mm256_fmadd_ps(a[2], a[2], _mm256_fmadd_ps(a[1], a[1], _mm256_mul_ps(a[0], a[0])));
    };
    const __m256 n2 = dot(n), floor = _mm256_mul_ps(_mm256_set1_ps(kDegenerateSine * kDegenerateSine),
                                                    _mm256_mul_ps(dot(u), dot(v)));
    // 1 / sqrt(n2): the estimate and one Newton step (within 2e-7 of it, where a division and a
    // square root would keep the loop waiting).
    const __m256 y = _mm256_rsqrt_ps(n2);
    const __m256 refined = _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(0.5f), y),
                                         _mm256_fnmadd_ps(_mm256_mul_ps(n2, y), y, _mm256_set1_ps(3.0f)));
    const __m256 scale = _mm256_and_ps(_mm256_cmp_ps(n2, floor, _CMP_GT_OQ), refined);
    for (int c = 0; c < 3; ++c) n[c] = _mm256_mul_ps(n[c], scale);
}

// Eight packed 3-float items x y z from d on: each lane moved to its place in the 24 floats by
// one permute per coordinate, then the three 8-float stores blended from them.
inline void storePacked8(float* d, const __m256 v[3]) {
    const __m256 x = _mm256_permutevar8x32_ps(v[0], _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5));
    const __m256 y = _mm256_permutevar8x32_ps(v[1], _mm256_setr_epi32(5, 0, 3, 6, 1, 4, 7, 2));
    const __m256 z = _mm256_permutevar8x32_ps(v[2], _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7));
    _mm256_storeu_ps(d, _mm256_blend_ps(_mm256_blend_ps(x, y, 0x92), z, 0x24));
    _mm256_storeu_ps(d + 8, _mm256_blend_ps(_mm256_blend_ps(x, y, 0x24), z, 0x49));
    _mm256_storeu_ps(d + 16, _mm256_blend_ps(_mm256_blend_ps(x, y, 0x49), z, 0x92));
}

// The lanes of x, y, z as 8 items x y z _.
inline void items8(const __m256 v[3], __m128 item[8]) {
    const __m256 zero = _mm256_setzero_ps();
    const __m256 xy0 = _mm256_unpacklo_ps(v[0], v[1]), xy1 = _mm256_unpackhi_ps(v[0], v[1]);
    const __m256 z0 = _mm256_unpacklo_ps(v[2], zero), z1 = _mm256_unpackhi_ps(v[2], zero);
    const __m256 a0 = _mm256_shuffle_ps(xy0, z0, _MM_SHUFFLE(1, 0, 1, 0));
    const __m256 a1 = _mm256_shuffle_ps(xy0, z0, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 a2 = _mm256_shuffle_ps(xy1, z1, _MM_SHUFFLE(1, 0, 1, 0));
    const __m256 a3 = _mm256_shuffle_ps(xy1, z1, _MM_SHUFFLE(3, 2, 3, 2));
    item[0] = _mm256_castps256_ps128(a0), item[1] = _mm256_castps256_ps128(a1);
    item[2] = _mm256_castps256_ps128(a2), item[3] = _mm256_castps256_ps128(a3);
    item[4] = _mm256_extractf128_ps(a0, 1), item[5] = _mm256_extractf128_ps(a1, 1);
    item[6] = _mm256_extractf128_ps(a2, 1), item[7] = _mm256_extractf128_ps(a3, 1);
}

// Lanes [0, count) of x, y, z as count 3-float items from d on, `stride` floats apart.
inline void store8(float* d, int stride, const __m256 v[3], int count) {
    if (stride == 3 && count == 8) return storePacked8(d, v);
    __m128 item[8];
    items8(v, item);
    // Packed items: each 4-float store's last float is the next item's first, written next.
    if (stride == 3)
        for (int k = 0; k + 1 < count; ++k) _mm_storeu_ps(d + 3 * k, item[k]);
    else
        for (int k = 0; k + 1 < count; ++k) store3(d + static_cast<long>(k) * stride, item[k]);
    store3(d + static_cast<long>(count - 1) * stride, item[count - 1]);
}

// Lanes [0, count) as the items outputs[0 .. count) of d, `stride` floats apart.
inline void storeScattered8(float* d, int stride, const __m256 v[3], const int* outputs, int count) {
    __m128 item[8];
    items8(v, item);
    for (int k = 0; k < count; ++k) store3(d + static_cast<long>(outputs[k]) * stride, item[k]);
}

// Outputs [o, o + count): positions p and the unit normals of tangents u, v (either output may
// be null).
inline void storeOutputs8(const __m256 p[3], const __m256 u[3], const __m256 v[3], int o, int count, float* position,
                          int positionStride, float* normal, int normalStride) {
    if (position) store8(position + static_cast<long>(o) * positionStride, positionStride, p, count);
    if (normal) {
        __m256 n[3];
        unitNormals8(u, v, n);
        store8(normal + static_cast<long>(o) * normalStride, normalStride, n, count);
    }
}

// The same for the outputs outputs[0 .. count).
inline void storeOutputs8(const __m256 p[3], const __m256 u[3], const __m256 v[3], const int* outputs, int count,
                          float* position, int positionStride, float* normal, int normalStride) {
    if (position) storeScattered8(position, positionStride, p, outputs, count);
    if (normal) {
        __m256 n[3];
        unitNormals8(u, v, n);
        storeScattered8(normal, normalStride, n, outputs, count);
    }
}

// Calls each(o, j, i, count) for every 8 or fewer outputs [o, o + count) of the patch at grid
// lines i .. i + count - 1 of row j, and eachColumn(outputs, i, j, count) for the outputs
// outputs[0 .. count) at grid line i of rows j .. j + count - 1. A row's outputs are a run of
// grid lines as the table builds them (a patch misses at most a row's ends, which its
// neighbours write), taken 8 at a time; a last single output that continues a column of them
// (rows of rate + 1 outputs end so, row after row) goes into that column, which would
// otherwise cost a register of 8 each. A row that is not a run is taken an output at a time,
// one outside the grid not at all.
template <class Each, class EachColumn>
void forEachRowChunk(const LevelPatchArrays& a, int patch, Each&& each, EachColumn&& eachColumn) {
    const int n = a.rate, last = a.outputOffsets[patch + 1];
    const std::uint16_t* cells = a.outputCells;
    int column[8], columnLine = -1, columnRow = 0, columnCount = 0;
    auto flush = [&] {
        if (columnCount > 0) eachColumn(column, columnLine, columnRow, columnCount);
        columnCount = 0;
    };
    for (int o = a.outputOffsets[patch]; o < last;) {
        const int j = cells[o] >> 8, i = cells[o] & 0xff;
        int end = std::min(last, o + std::max(1, n + 1 - i));  // a full run's end, at most
        while ((cells[end - 1] >> 8) != j) --end;
        const int lastLine = cells[end - 1] & 0xff;
        if (j <= n && lastLine <= n) {
            if (lastLine - i == end - 1 - o) {
                int k = o;
                for (; end - k >= 8; k += 8) each(k, j, i + (k - o), 8);
                if (end - k == 1) {
                    if (columnCount > 0 && (columnLine != lastLine || columnRow + columnCount != j)) flush();
                    if (columnCount == 0) columnLine = lastLine, columnRow = j;
                    column[columnCount++] = k;
                    if (columnCount == 8) flush();
                } else if (k < end) {
                    each(k, j, i + (k - o), end - k);
                }
            } else {
                for (int k = o; k < end; ++k) each(k, j, cells[k] & 0xff, 1);
            }
        }
        o = end;
    }
    flush();
}

// A B-spline patch as a tensor product, 8 grid lines a register: the rows' curves
// Q_r(i) = sum_c B_c(i) P_rc and their derivatives first, then each row of outputs from them.
void bSplinePatch8(const float* src, int srcStride, const LevelPatchArrays& a, int patch, float* position,
                   int positionStride, float* normal, int normalStride) {
    const int n = a.rate, width = a.lineWidth;
    const int* ids = a.patchPoints + a.pointOffsets[patch];
    const __m128 first = load3(src + static_cast<long>(ids[0]) * srcStride);
    alignas(16) float p0[4], points[16][4];
    _mm_store_ps(p0, first);
    for (int k = 0; k < 16; ++k) _mm_store_ps(points[k], _mm_sub_ps(load3(src + static_cast<long>(ids[k]) * srcStride), first));
    alignas(32) float q[4][3][kMaxRate + 8], dq[4][3][kMaxRate + 8];
    for (int i = 0; i < n + 8; i += 8) {  // every line a row's 8 lanes may read
        __m256 w[8];
        for (int k = 0; k < 8; ++k) w[k] = _mm256_loadu_ps(a.curveWeightLines + k * width + i);
#pragma GCC unroll 4
        for (int r = 0; r < 4; ++r)
#pragma GCC unroll 3
            for (int c = 0; c < 3; ++c) {
                const float* p = &points[4 * r][c];
                __m256 sum = _mm256_mul_ps(w[0], _mm256_set1_ps(p[0])), dsum = _mm256_mul_ps(w[4], _mm256_set1_ps(p[0]));
                for (int k = 1; k < 4; ++k) {
                    sum = _mm256_fmadd_ps(w[k], _mm256_set1_ps(p[4 * k]), sum);
                    dsum = _mm256_fmadd_ps(w[4 + k], _mm256_set1_ps(p[4 * k]), dsum);
                }
                _mm256_store_ps(&q[r][c][i], sum);
                _mm256_store_ps(&dq[r][c][i], dsum);
            }
    }
    forEachRowChunk(a, patch, [&](int o, int j, int i, int count) __attribute__((always_inline)) {
        const float* w = a.curveWeights + 8 * j;
        __m256 wr[4], dwr[4], p[3];
#pragma GCC unroll 4
        for (int r = 0; r < 4; ++r) wr[r] = _mm256_set1_ps(w[r]), dwr[r] = _mm256_set1_ps(w[4 + r]);
        // The positions first and out, then the tangents: 8 weights and 6 sums fit the registers.
#pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) {
            p[c] = _mm256_set1_ps(p0[c]);
#pragma GCC unroll 4
            for (int r = 0; r < 4; ++r) p[c] = _mm256_fmadd_ps(wr[r], _mm256_loadu_ps(&q[r][c][i]), p[c]);
        }
        if (position) store8(position + static_cast<long>(o) * positionStride, positionStride, p, count);
        if (!normal) return;
        // The curves again from memory (L1) rather than kept from the positions' sums: 12 more
        // loads where the compiler would otherwise spill and reload 24 registers.
        asm volatile("" ::: "memory");
        __m256 u[3], v[3];
#pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) {
            u[c] = v[c] = _mm256_setzero_ps();
#pragma GCC unroll 4
            for (int r = 0; r < 4; ++r) {
                u[c] = _mm256_fmadd_ps(wr[r], _mm256_loadu_ps(&dq[r][c][i]), u[c]);
                v[c] = _mm256_fmadd_ps(dwr[r], _mm256_loadu_ps(&q[r][c][i]), v[c]);
            }
        }
        __m256 n[3];
        unitNormals8(u, v, n);
        store8(normal + static_cast<long>(o) * normalStride, normalStride, n, count);
    }, [&](const int* outputs, int i, int j, int count) __attribute__((always_inline)) {
        // Lane k at row j + k: the rows' weights per lane, the curves' values at line i for all.
        const float* w = a.curveWeightLines + j;
        __m256 p[3], u[3], v[3];
#pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) p[c] = _mm256_set1_ps(p0[c]), u[c] = v[c] = _mm256_setzero_ps();
#pragma GCC unroll 4
        for (int r = 0; r < 4; ++r) {
            const __m256 wr = _mm256_loadu_ps(w + r * width), dwr = _mm256_loadu_ps(w + (4 + r) * width);
#pragma GCC unroll 3
            for (int c = 0; c < 3; ++c) {
                const __m256 qr = _mm256_set1_ps(q[r][c][i]);
                p[c] = _mm256_fmadd_ps(wr, qr, p[c]);
                u[c] = _mm256_fmadd_ps(wr, _mm256_set1_ps(dq[r][c][i]), u[c]);
                v[c] = _mm256_fmadd_ps(dwr, qr, v[c]);
            }
        }
        storeOutputs8(p, u, v, outputs, count, position, positionStride, normal, normalStride);
    });
}

// A box-spline patch, 8 cells of a row a register: each from its 12 points' weights, read as
// runs over the row's grid lines.
void boxSplinePatch8(const float* src, int srcStride, const LevelPatchArrays& a, int patch, float* position,
                     int positionStride, float* normal, int normalStride) {
    const int* ids = a.patchPoints + a.pointOffsets[patch];
    // The position too is summed relative to the first point (as the Vulkan kernel sums it), so
    // that one broadcast of each offset serves the position and both tangents.
    alignas(16) float p0[4], offsets[12][4];
    const __m128 first = load3(src + static_cast<long>(ids[0]) * srcStride);
    _mm_store_ps(p0, first);
    for (int k = 0; k < 12; ++k)
        _mm_store_ps(offsets[k], _mm_sub_ps(load3(src + static_cast<long>(ids[k]) * srcStride), first));
    const long width = a.lineWidth;
    auto row = [&](int o, int j, int i, int count) __attribute__((always_inline)) {
        const float* w = a.boxSplineWeightLines + 36 * j * width + i;
        __m256 p[3], u[3], v[3];
#pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) p[c] = u[c] = v[c] = _mm256_setzero_ps();
#pragma GCC unroll 4
        for (int k = 0; k < 12; ++k, w += 3 * width) {
            const __m256 wp = _mm256_loadu_ps(w), ws = _mm256_loadu_ps(w + width), wt = _mm256_loadu_ps(w + 2 * width);
#pragma GCC unroll 3
            for (int c = 0; c < 3; ++c) {
                const __m256 d = _mm256_set1_ps(offsets[k][c]);
                p[c] = _mm256_fmadd_ps(wp, d, p[c]);
                u[c] = _mm256_fmadd_ps(ws, d, u[c]);
                v[c] = _mm256_fmadd_ps(wt, d, v[c]);
            }
        }
#pragma GCC unroll 3
        for (int c = 0; c < 3; ++c) p[c] = _mm256_add_ps(p[c], _mm256_set1_ps(p0[c]));
        storeOutputs8(p, u, v, o, count, position, positionStride, normal, normalStride);
    };
    // The box spline's weights are runs over a row's lines only: a column's cells one by one.
    forEachRowChunk(a, patch, row, [&](const int* outputs, int i, int j, int count) {
        for (int k = 0; k < count; ++k) row(outputs[k], j + k, i, 1);
    });
}
#endif

// Patches [start, end).
inline void levelPatchLoop(const float* src, int srcStride, const LevelPatchArrays& a, float* position,
                           int positionStride, float* normal, int normalStride, int start, int end) {
    for (int patch = start; patch < end; ++patch) {
        const bool bSpline = a.patchBasis[patch] == 0;
#ifdef QUADTRI_PATCH_LOOPS_8
        if (bSpline) bSplinePatch8(src, srcStride, a, patch, position, positionStride, normal, normalStride);
        else boxSplinePatch8(src, srcStride, a, patch, position, positionStride, normal, normalStride);
#else
        if (bSpline) bSplinePatch(src, srcStride, a, patch, position, positionStride, normal, normalStride);
        else boxSplinePatch(src, srcStride, a, patch, position, positionStride, normal, normalStride);
#endif
    }
}

}  // namespace
}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
