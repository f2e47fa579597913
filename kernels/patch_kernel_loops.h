// The level-patch loops (kernels/patch_kernel.h), compiled twice: for the baseline CPU in
// patch_kernel.cpp and with AVX2 + FMA in patch_kernel_avx2.cpp. Include only there, and in
// test_level_patches, which defines QUADTRI_PORTABLE_PATCH_LOOPS to check the portable loops.
#pragma once

#include <algorithm>
#include <cmath>

#include "kernels/limit_kernel.h"
#include "kernels/patch_kernel.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {
namespace {

#if defined(__SSE2__) && !defined(QUADTRI_PORTABLE_PATCH_LOOPS)
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

// Patches [start, end).
inline void levelPatchLoop(const float* src, int srcStride, const LevelPatchArrays& a, float* position,
                           int positionStride, float* normal, int normalStride, int start, int end) {
    for (int patch = start; patch < end; ++patch) {
        if (a.patchBasis[patch] == 0)
            bSplinePatch(src, srcStride, a, patch, position, positionStride, normal, normalStride);
        else
            boxSplinePatch(src, srcStride, a, patch, position, positionStride, normal, normalStride);
    }
}

}  // namespace
}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
