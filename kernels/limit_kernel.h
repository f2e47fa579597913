// The limit loop, shared by the serial and threaded evaluators (and mirrored in GLSL by
// shaders/limit_eval.comp): one pass over each stencil's support gathers the limit position and
// both tangents, and the unit normal is their normalised cross product. The tangents are summed
// relative to the stencil's first source s_0, sum_k w_k (s_k - s_0), equal since their weights sum
// to 0: the weights' rounding then multiplies distances within the stencil, not the coordinates
// (docs/limit.md, "Precision"). Where the tangents are
// degenerate (|dU x dV| <= kDegenerateSine |dU| |dV|, e.g. both along one straight boundary at a
// corner) the normal is the level's area-weighted face normal at that vertex (kernels/
// mesh_normal_kernel.h) when a MeshNormalTable is given, else (0, 0, 0); docs/limit_evaluation.md.
#pragma once

#include "kernels/mesh_normal_kernel.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace quadtri {
inline namespace v0 {
namespace kernels {

// Sine of the angle between the tangents below which they are taken as parallel: float rounding
// of a tangent gathered from ~10-30 sources leaves errors of ~1e-6 of its length.
constexpr float kDegenerateSine = 1e-4f;

// LimitStencilTable's arrays: stencil i's support is indices[offsets[i] .. offsets[i] + sizes[i])
// (runs may be shared between stencils, so offsets need not increase), entry k's (position, dU,
// dV) weights are weights[weightOffsets[i] + 3k + 0, 1, 2].
struct LimitStencilArrays {
    const int* sizes;    // numStencils
    const int* offsets;  // numStencils
    const int* indices;
    const int* weightOffsets;
    const float* weights;
};

// One output: element i at data + i * stride (data == nullptr: not written).
struct LimitOutput {
    float* data;
    int stride;
};

struct LimitOutputs {
    LimitOutput position, du, dv, normal;
    const MeshNormalArrays* fallback;  // may be null
};

inline void storeIfWanted(const LimitOutput& out, int i, const float* value, int width) {
    if (!out.data) return;
    float* d = out.data + static_cast<long>(i) * out.stride;
    for (int c = 0; c < width; ++c) d[c] = value[c];
}

// Where the tangents are degenerate: the fallback's mesh normal of vertex i, or (0, 0, 0).
inline void degenerateNormal(const float* src, int srcStride, const LimitOutputs& o, int i, float* d) {
    if (o.fallback) {
        meshNormal(src, srcStride, *o.fallback, i, d);
    } else {
        d[0] = d[1] = d[2] = 0.0f;
    }
}

// The normal of stencil i from its tangents (width 3).
inline void limitNormal(const float* src, int srcStride, const float u[3], const float v[3], const LimitOutputs& o,
                        int i) {
    const float n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const float n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const float u2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    const float v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    float* d = o.normal.data + static_cast<long>(i) * o.normal.stride;
    if (n2 > kDegenerateSine * kDegenerateSine * u2 * v2) {
        normalizeInto(n, d);
    } else {
        degenerateNormal(src, srcStride, o, i, d);
    }
}

// Components [0, Width) of stencils [start, end); src and the outputs point at component 0 of
// element 0. The normal is written only by the width-3 instantiation.
template <int Width>
inline void evalLimitFixed(const float* src, int srcStride, const LimitStencilArrays& t, const LimitOutputs& o,
                           int start, int end) {
    for (int i = start; i < end; ++i) {
        float p[Width] = {}, u[Width] = {}, v[Width] = {};
        const int first = t.offsets[i], n = t.sizes[i];
        const int* idx = t.indices + first;
        const float* w = t.weights + t.weightOffsets[i];
        const float* s0 = n > 0 ? src + static_cast<long>(idx[0]) * srcStride : src;
        for (int k = 0; k < n; ++k, w += 3) {
            const float* s = src + static_cast<long>(idx[k]) * srcStride;
            const float wp = w[0], wu = w[1], wv = w[2];
            for (int c = 0; c < Width; ++c) {
                const float d = s[c] - s0[c];
                p[c] += wp * s[c];
                u[c] += wu * d;
                v[c] += wv * d;
            }
        }
        storeIfWanted(o.position, i, p, Width);
        storeIfWanted(o.du, i, u, Width);
        storeIfWanted(o.dv, i, v, Width);
        if constexpr (Width == 3) {
            if (o.normal.data) limitNormal(src, srcStride, u, v, o, i);
        }
    }
}

#if defined(__SSE2__)
// Width 3 with x, y, z in one SSE register per sum: per entry three multiplies, three adds and a
// subtraction instead of nine, nine and three, and the normal in registers too. Lane by lane these are the scalar
// code's float operations in the same order (SSE2 has no fused multiply-add; sqrt and division
// are IEEE), so the results are bitwise those of the generic loop and limitNormal.
// Elements are only 4-byte aligned: the 8-byte moves are the unaligned-typed ones.
inline __m128 load3(const float* p) {
    const __m128 xy = _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)));
    return _mm_movelh_ps(xy, _mm_load_ss(p + 2));
}

inline void store3(float* d, __m128 v) {
    _mm_storel_epi64(reinterpret_cast<__m128i*>(d), _mm_castps_si128(v));
    _mm_store_ss(d + 2, _mm_movehl_ps(v, v));
}

inline __m128 yzx(__m128 a) { return _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 0, 2, 1)); }

// Lane 0: (x² + y²) + z², as the scalar sums.
inline __m128 dot3(__m128 a) {
    const __m128 m = _mm_mul_ps(a, a);
    return _mm_add_ss(_mm_add_ss(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 1, 1, 1))), _mm_movehl_ps(m, m));
}

inline void limitNormalSse(const float* src, int srcStride, __m128 u, __m128 v, const LimitOutputs& o, int i) {
    const __m128 c = _mm_sub_ps(_mm_mul_ps(u, yzx(v)), _mm_mul_ps(yzx(u), v));
    const __m128 n = yzx(c);  // (u1 v2 - u2 v1, u2 v0 - u0 v2, u0 v1 - u1 v0)
    const float n2 = _mm_cvtss_f32(dot3(n)), u2 = _mm_cvtss_f32(dot3(u)), v2 = _mm_cvtss_f32(dot3(v));
    float* d = o.normal.data + static_cast<long>(i) * o.normal.stride;
    if (n2 > kDegenerateSine * kDegenerateSine * u2 * v2) {
        const __m128 scale = _mm_div_ss(_mm_set_ss(1.0f), _mm_sqrt_ss(_mm_set_ss(n2)));
        store3(d, _mm_mul_ps(n, _mm_shuffle_ps(scale, scale, 0)));
    } else {
        degenerateNormal(src, srcStride, o, i, d);
    }
}

template <>
inline void evalLimitFixed<3>(const float* src, int srcStride, const LimitStencilArrays& t, const LimitOutputs& o,
                              int start, int end) {
    for (int i = start; i < end; ++i) {
        __m128 p = _mm_setzero_ps(), u = _mm_setzero_ps(), v = _mm_setzero_ps();
        const int first = t.offsets[i], n = t.sizes[i];
        const int* idx = t.indices + first;
        const float* w = t.weights + t.weightOffsets[i];
        const __m128 s0 = n > 0 ? load3(src + static_cast<long>(idx[0]) * srcStride) : _mm_setzero_ps();
        for (int k = 0; k < n; ++k, w += 3) {
            const __m128 s = load3(src + static_cast<long>(idx[k]) * srcStride);
            const __m128 d = _mm_sub_ps(s, s0);
            p = _mm_add_ps(p, _mm_mul_ps(_mm_set1_ps(w[0]), s));
            u = _mm_add_ps(u, _mm_mul_ps(_mm_set1_ps(w[1]), d));
            v = _mm_add_ps(v, _mm_mul_ps(_mm_set1_ps(w[2]), d));
        }
        if (o.position.data) store3(o.position.data + static_cast<long>(i) * o.position.stride, p);
        if (o.du.data) store3(o.du.data + static_cast<long>(i) * o.du.stride, u);
        if (o.dv.data) store3(o.dv.data + static_cast<long>(i) * o.dv.stride, v);
        if (o.normal.data) limitNormalSse(src, srcStride, u, v, o, i);
    }
}
#endif

inline LimitOutput shifted(const LimitOutput& out, int by) { return {out.data ? out.data + by : nullptr, out.stride}; }

// The portable loops for any width: widths 1-4 in one pass; wider data in passes of 4 components
// (each component is independent, so the result is the same as one pass). Normals need width 3.
inline void evalLimitPortable(const float* src, int srcStride, int width, const LimitStencilArrays& t,
                              const LimitOutputs& o, int start, int end) {
    switch (width) {
    case 1: evalLimitFixed<1>(src, srcStride, t, o, start, end); return;
    case 2: evalLimitFixed<2>(src, srcStride, t, o, start, end); return;
    case 3: evalLimitFixed<3>(src, srcStride, t, o, start, end); return;
    case 4: evalLimitFixed<4>(src, srcStride, t, o, start, end); return;
    default: break;
    }
    const LimitOutputs rest{shifted(o.position, 4), shifted(o.du, 4), shifted(o.dv, 4), {nullptr, 0}, nullptr};
    evalLimitFixed<4>(src, srcStride, t, o, start, end);
    evalLimitPortable(src + 4, srcStride, width - 4, t, rest, start, end);
}

// Stencils [start, end) of any width (kernels/limit_kernel.cpp). Width 3, the positions every
// engine evaluates, takes the AVX2 + FMA loop (kernels/limit_kernel_avx2.cpp) where the CPU has
// it, decided once per process: fused multiply-adds and two partial sums per output, so its bits
// differ from the portable loop's by float rounding; the serial and threaded evaluators call this
// same function, so they stay bitwise equal to each other on any one machine.
void evalLimitStencils(const float* src, int srcStride, int width, const LimitStencilArrays& t, const LimitOutputs& o,
                       int start, int end);

// Whether evalLimitStencils takes the AVX2 + FMA loop for width 3 on this CPU.
bool limitKernelUsesAvx2();

// The width-3 AVX2 + FMA loop, and the degenerate-normal case it hands back out of line (so that
// file instantiates none of the inline code above with AVX2 code generation).
void evalLimit3Avx2(const float* src, int srcStride, const LimitStencilArrays& t, const LimitOutputs& o, int start,
                    int end);
void degenerateNormalOutOfLine(const float* src, int srcStride, const LimitOutputs& o, int i, float* d);

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
