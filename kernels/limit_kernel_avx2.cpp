// The width-3 limit loop with AVX2 + FMA code generation (this file alone is compiled with
// -mavx2 -mfma; kernels/limit_kernel.cpp calls it only where the CPU has both). It computes what
// the portable loop does (kernels/limit_kernel.h: positions, tangents relative to the first
// source, the unit normal or the degenerate fallback), faster for two reasons:
// - one fused multiply-add per output and entry, the weights broadcast straight from memory;
// - two partial sums per output (even and odd entries), so consecutive entries do not wait on
//   one another's additions: a stencil's 10-16 entries are otherwise one chain of dependent adds.
// Only names local to this file and the struct layouts are used: an inline function of a shared
// header instantiated here would carry AVX2 instructions and could be the copy the linker keeps.
#include <immintrin.h>

#include "kernels/limit_kernel.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {
namespace {

// x, y, z of an element that is only 4-byte aligned; lane 3 is 0.
inline __m128 loadXyz(const float* p) {
    const __m128 xy = _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)));
    return _mm_insert_ps(xy, _mm_load_ss(p + 2), 0x20);
}

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

}  // namespace

void evalLimit3Avx2(const float* src, int srcStride, const LimitStencilArrays& t, const LimitOutputs& o, int start,
                    int end) {
    for (int i = start; i < end; ++i) {
        const int first = t.offsets[i], n = t.sizes[i];
        const int* idx = t.indices + first;
        const float* w = t.weights + t.weightOffsets[i];
        __m128 p0 = _mm_setzero_ps(), u0 = p0, v0 = p0, p1 = p0, u1 = p0, v1 = p0;
        const __m128 s0 = n > 0 ? loadXyz(src + static_cast<long>(idx[0]) * srcStride) : p0;
        int k = 0;
        for (; k + 1 < n; k += 2, w += 6) {
            const __m128 a = loadXyz(src + static_cast<long>(idx[k]) * srcStride);
            const __m128 b = loadXyz(src + static_cast<long>(idx[k + 1]) * srcStride);
            const __m128 da = _mm_sub_ps(a, s0), db = _mm_sub_ps(b, s0);
            p0 = _mm_fmadd_ps(_mm_broadcast_ss(w + 0), a, p0);
            u0 = _mm_fmadd_ps(_mm_broadcast_ss(w + 1), da, u0);
            v0 = _mm_fmadd_ps(_mm_broadcast_ss(w + 2), da, v0);
            p1 = _mm_fmadd_ps(_mm_broadcast_ss(w + 3), b, p1);
            u1 = _mm_fmadd_ps(_mm_broadcast_ss(w + 4), db, u1);
            v1 = _mm_fmadd_ps(_mm_broadcast_ss(w + 5), db, v1);
        }
        if (k < n) {
            const __m128 a = loadXyz(src + static_cast<long>(idx[k]) * srcStride);
            const __m128 da = _mm_sub_ps(a, s0);
            p0 = _mm_fmadd_ps(_mm_broadcast_ss(w + 0), a, p0);
            u0 = _mm_fmadd_ps(_mm_broadcast_ss(w + 1), da, u0);
            v0 = _mm_fmadd_ps(_mm_broadcast_ss(w + 2), da, v0);
        }
        const __m128 p = _mm_add_ps(p0, p1), u = _mm_add_ps(u0, u1), v = _mm_add_ps(v0, v1);
        if (o.position.data) storeXyz(o.position.data + static_cast<long>(i) * o.position.stride, p);
        if (o.du.data) storeXyz(o.du.data + static_cast<long>(i) * o.du.stride, u);
        if (o.dv.data) storeXyz(o.dv.data + static_cast<long>(i) * o.dv.stride, v);
        if (o.normal.data) writeNormal(src, srcStride, u, v, o, i);
    }
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
