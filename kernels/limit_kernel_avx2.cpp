// The width-3 limit loop with AVX2 + FMA code generation (this file alone is compiled with
// -mavx2 -mfma; kernels/limit_kernel.cpp calls it only where the CPU has both). It computes what
// the portable loop does (kernels/limit_kernel.h: positions, tangents relative to the first
// source, the unit normal or the degenerate fallback), faster for two reasons:
// - two partial sums per output (even and odd entries), so consecutive entries do not wait on
//   one another's additions: a stencil's 10-16 entries are otherwise one chain of dependent adds;
//   an even entry and the odd one after it share a 256-bit register (one fused multiply-add per
//   output for both), their six weights one load;
// - normals eight stencils at a time, across the lanes of 256-bit registers (writeNormals8).
// Only names local to this file and the struct layouts are used: an inline function of a shared
// header instantiated here would carry AVX2 instructions and could be the copy the linker keeps.
#include <immintrin.h>

#include "kernels/limit_kernel.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {
namespace {

// x, y, z of an element that is only 4-byte aligned; lane 3 is 0. One masked load, which reads
// nothing past z (a masked-out lane never faults), as the stencil kernel's: fewer instructions
// than two loads and a shuffle, the same bits (docs/limit_evaluation.md has the figures).
inline __m128 loadXyz(const float* p) { return _mm_maskload_ps(p, _mm_setr_epi32(-1, -1, -1, 0)); }

inline void storeXyz(float* d, __m128 v) {
    _mm_storel_epi64(reinterpret_cast<__m128i*>(d), _mm_castps_si128(v));
    _mm_store_ss(d + 2, _mm_movehl_ps(v, v));
}

inline __m128 rotateYzx(__m128 a) { return _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 0, 2, 1)); }

// |a|² of x, y, z in every lane (lane 3 of a is 0).
inline __m128 squaredLength(__m128 a) { return _mm_dp_ps(a, a, 0x7f); }

void writeNormal(const float* src, int srcStride, __m128 u, __m128 v, const LimitOutputs& o, int i) {
    const __m128 n = rotateYzx(_mm_fmsub_ps(u, rotateYzx(v), _mm_mul_ps(rotateYzx(u), v)));
    const float n2 = _mm_cvtss_f32(squaredLength(n));
    const float u2 = _mm_cvtss_f32(squaredLength(u)), v2 = _mm_cvtss_f32(squaredLength(v));
    float* d = o.normal.data + static_cast<long>(i) * o.normal.stride;
    if (n2 > kDegenerateSine * kDegenerateSine * u2 * v2) {
        storeXyz(d, _mm_div_ps(n, _mm_sqrt_ps(_mm_set1_ps(n2))));
    } else {
        degenerateNormalOutOfLine(src, srcStride, o, i, d);
    }
}

// The eight normals of stencils [first, first + 8) from their tangents (lanes 0-2 of u[b] and
// v[b]), eight at a time across the lanes of 256-bit registers: one square root and three
// divisions of 8 lanes where writeNormal takes a square root and a division of 4 lanes per
// stencil, and no dot-product instructions. Lane by lane these are writeNormal's float operations
// in its order (the cross product's fused multiply-subtract, squared lengths summed as
// (x² + y²) + z² as _mm_dp_ps sums them, the same test, IEEE square root and division), so the
// results are its bits (test_limit_evaluator checks it).
inline __m256 pair(__m128 low, __m128 high) { return _mm256_insertf128_ps(_mm256_castps128_ps256(low), high, 1); }

inline __m256 squaredLength8(__m256 x, __m256 y, __m256 z) {
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(x, x), _mm256_mul_ps(y, y)), _mm256_mul_ps(z, z));
}

// Lanes 0-2 of a[0..7] as x, y, z across 8 lanes (lane b = a[b]).
inline void transpose8(const __m128 (&a)[8], __m256& x, __m256& y, __m256& z) {
    const __m256 a0 = pair(a[0], a[4]), a1 = pair(a[1], a[5]), a2 = pair(a[2], a[6]), a3 = pair(a[3], a[7]);
    const __m256 t0 = _mm256_unpacklo_ps(a0, a1), t1 = _mm256_unpackhi_ps(a0, a1);  // x0 x1 y0 y1, z0 z1 . .
    const __m256 t2 = _mm256_unpacklo_ps(a2, a3), t3 = _mm256_unpackhi_ps(a2, a3);
    x = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
    y = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
    z = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
}

void writeNormals8(const float* src, int srcStride, const __m128 (&u)[8], const __m128 (&v)[8], const LimitOutputs& o,
                   int first) {
    __m256 ux, uy, uz, vx, vy, vz;
    transpose8(u, ux, uy, uz);
    transpose8(v, vx, vy, vz);
    const __m256 nx = _mm256_fmsub_ps(uy, vz, _mm256_mul_ps(uz, vy));
    const __m256 ny = _mm256_fmsub_ps(uz, vx, _mm256_mul_ps(ux, vz));
    const __m256 nz = _mm256_fmsub_ps(ux, vy, _mm256_mul_ps(uy, vx));
    const __m256 n2 = squaredLength8(nx, ny, nz);
    const __m256 limit = _mm256_mul_ps(_mm256_mul_ps(_mm256_set1_ps(kDegenerateSine * kDegenerateSine),
                                                     squaredLength8(ux, uy, uz)),
                                       squaredLength8(vx, vy, vz));
    const int regular = _mm256_movemask_ps(_mm256_cmp_ps(n2, limit, _CMP_GT_OQ));
    const __m256 length = _mm256_sqrt_ps(n2);
    const __m256 x = _mm256_div_ps(nx, length), y = _mm256_div_ps(ny, length), z = _mm256_div_ps(nz, length);
    // Back to x, y, z per stencil: r[k] holds stencils k (low half) and k + 4 (high half).
    const __m256 zero = _mm256_setzero_ps();
    const __m256 t0 = _mm256_unpacklo_ps(x, y), t1 = _mm256_unpackhi_ps(x, y);  // x0 y0 x1 y1, x2 y2 x3 y3
    const __m256 t2 = _mm256_unpacklo_ps(z, zero), t3 = _mm256_unpackhi_ps(z, zero);
    const __m256 r[4] = {_mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)), _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2)),
                         _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)), _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2))};
    for (int b = 0; b < 8; ++b) {
        const int i = first + b;
        float* d = o.normal.data + static_cast<long>(i) * o.normal.stride;
        if (regular & (1 << b)) {
            storeXyz(d, b < 4 ? _mm256_castps256_ps128(r[b]) : _mm256_extractf128_ps(r[b - 4], 1));
        } else {
            degenerateNormalOutOfLine(src, srcStride, o, i, d);
        }
    }
}

// Stencil i's sums: the position, dU and dV written where wanted, the tangents kept for the normal.
// Entries k and k + 1 go together in 256-bit registers, entry k in lanes 0-3 and k + 1 in lanes
// 4-7: the low halves are the even entries' sums and the high halves the odd ones', each lane
// doing what two 128-bit sums per output did (so their bits), with one fused multiply-add per
// output and pair of entries. The pair's six weights are one load, each weight put in its half by
// a permute, where broadcasting them took six loads (docs/limit_evaluation.md has the figures).
inline void accumulate(const float* src, int srcStride, const LimitStencilArrays& t, const LimitOutputs& o, int i,
                       __m128& u, __m128& v) {
    const int first = t.offsets[i], n = t.sizes[i];
    const int* idx = t.indices + first;
    const float* w = t.weights + t.weightOffsets[i];
    auto source = [&](int k) { return loadXyz(src + static_cast<long>(idx[k]) * srcStride); };
    const __m128 s0 = n > 0 ? source(0) : _mm_setzero_ps();
    const __m256 s00 = pair(s0, s0);  // the first source in both halves
    // (position, dU, dV) of entry k are w[0..2], of entry k + 1 w[3..5].
    const __m256i positionWeights = _mm256_setr_epi32(0, 0, 0, 0, 3, 3, 3, 3);
    const __m256i duWeights = _mm256_setr_epi32(1, 1, 1, 1, 4, 4, 4, 4);
    const __m256i dvWeights = _mm256_setr_epi32(2, 2, 2, 2, 5, 5, 5, 5);
    const __m256i sixWeights = _mm256_setr_epi32(-1, -1, -1, -1, -1, -1, 0, 0);  // reads nothing past the pair's
    __m256 p = _mm256_setzero_ps(), du = p, dv = p;
    int k = 0;
    for (; k + 1 < n; k += 2, w += 6) {
        const __m256 x = pair(source(k), source(k + 1)), d = _mm256_sub_ps(x, s00);
        const __m256 weights = _mm256_maskload_ps(w, sixWeights);
        p = _mm256_fmadd_ps(_mm256_permutevar8x32_ps(weights, positionWeights), x, p);
        du = _mm256_fmadd_ps(_mm256_permutevar8x32_ps(weights, duWeights), d, du);
        dv = _mm256_fmadd_ps(_mm256_permutevar8x32_ps(weights, dvWeights), d, dv);
    }
    __m128 p0 = _mm256_castps256_ps128(p), u0 = _mm256_castps256_ps128(du), v0 = _mm256_castps256_ps128(dv);
    if (k < n) {  // an odd last entry, with the even ones
        const __m128 a = source(k), da = _mm_sub_ps(a, s0);
        p0 = _mm_fmadd_ps(_mm_broadcast_ss(w + 0), a, p0);
        u0 = _mm_fmadd_ps(_mm_broadcast_ss(w + 1), da, u0);
        v0 = _mm_fmadd_ps(_mm_broadcast_ss(w + 2), da, v0);
    }
    const __m128 position = _mm_add_ps(p0, _mm256_extractf128_ps(p, 1));
    u = _mm_add_ps(u0, _mm256_extractf128_ps(du, 1));
    v = _mm_add_ps(v0, _mm256_extractf128_ps(dv, 1));
    if (o.position.data) storeXyz(o.position.data + static_cast<long>(i) * o.position.stride, position);
    if (o.du.data) storeXyz(o.du.data + static_cast<long>(i) * o.du.stride, u);
    if (o.dv.data) storeXyz(o.dv.data + static_cast<long>(i) * o.dv.stride, v);
}

}  // namespace

void evalLimit3Avx2(const float* src, int srcStride, const LimitStencilArrays& t, const LimitOutputs& o, int start,
                    int end) {
    int i = start;
    if (o.normal.data) {
        __m128 u[8], v[8];
        for (; i + 8 <= end; i += 8) {
            for (int b = 0; b < 8; ++b) accumulate(src, srcStride, t, o, i + b, u[b], v[b]);
            writeNormals8(src, srcStride, u, v, o, i);
        }
    }
    for (; i < end; ++i) {  // the rest, and every stencil when no normal is wanted
        __m128 u, v;
        accumulate(src, srcStride, t, o, i, u, v);
        if (o.normal.data) writeNormal(src, srcStride, u, v, o, i);
    }
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
