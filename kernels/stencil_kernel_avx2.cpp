// The stencil loops of width 3 and 4 with AVX2 + FMA code generation (this file alone is compiled
// with -mavx2 -mfma; kernels/stencil_kernel.cpp calls them only where the CPU has both). They
// compute what the portable loops of kernels/stencil_kernel.h do, with fewer instructions per
// entry (docs/stencil_kernel.md has the counts):
// - an element is one 128-bit register (x, y, z and a zero or the padding's w), the weight
//   broadcast straight from the pool, one fused multiply-add per entry for all components;
// - two partial sums (even and odd entries), so consecutive entries do not wait on one another;
// - stencils taken in runs that share one pooled weight sequence (after a level or two nearly
//   every stencil is one of a handful of regular masks, in long runs: face points, then edge
//   points, then vertex points): the run's weights sit in registers, and the loop is unrolled
//   to the mask sizes of 3 to 12 entries, so a run costs one branch. Given a StencilRuns' run
//   list, the loop reads neither offsets nor weightOffsets inside its runs;
// - inside a run, two stencils at a time in the two halves of a 256-bit register, one fused
//   multiply-add for both, each half doing exactly what a stencil alone does.
// Width 3 and width 4 do the same float operations on lanes 0-2, so padded positions give the
// same bits as packed ones. Only names local to this file and the struct layouts are used: an
// inline function of a shared header instantiated here would carry AVX2 instructions and could
// be the copy the linker keeps.
#include <immintrin.h>

#include "kernels/stencil_kernel.h"

namespace quadtri {
inline namespace v0 {
namespace kernels {
namespace {

// x, y, z of an element that is only 4-byte aligned; lane 3 is 0. A masked load: the bytes past z
// are not read (a masked-out lane never faults), and it is one load where two loads and a shuffle
// were 10-15 % slower per 3-float level (docs/stencil_kernel.md).
struct Xyz {
    static __m128 load(const float* p) { return _mm_maskload_ps(p, _mm_setr_epi32(-1, -1, -1, 0)); }
    static void store(float* d, __m128 v) {
        _mm_storel_epi64(reinterpret_cast<__m128i*>(d), _mm_castps_si128(v));
        _mm_store_ss(d + 2, _mm_movehl_ps(v, v));
    }
    // Element p in lanes 0-3 and element q in lanes 4-7.
    static __m256 loadPair(const float* p, const float* q) {
        return _mm256_insertf128_ps(_mm256_castps128_ps256(load(p)), load(q), 1);
    }
};

// Four floats, only 4-byte aligned.
struct Xyzw {
    static __m128 load(const float* p) { return _mm_loadu_ps(p); }
    static void store(float* d, __m128 v) { _mm_storeu_ps(d, v); }
    static __m256 loadPair(const float* p, const float* q) { return _mm256_loadu2_m128(q, p); }
};

// The weighted sum of one stencil's n entries, w[k] being weight k broadcast to every lane.
// Inlined with a constant n it unrolls completely.
template <class Element, class Weight>
[[gnu::always_inline]] inline __m128 weightedSum(const float* src, long srcStride, const int* idx, Weight w, int n) {
    __m128 even = _mm_setzero_ps(), odd = _mm_setzero_ps();
    int k = 0;
    for (; k + 1 < n; k += 2) {
        even = _mm_fmadd_ps(w(k), Element::load(src + idx[k] * srcStride), even);
        odd = _mm_fmadd_ps(w(k + 1), Element::load(src + idx[k + 1] * srcStride), odd);
    }
    if (k < n) even = _mm_fmadd_ps(w(k), Element::load(src + idx[k] * srcStride), even);
    return _mm_add_ps(even, odd);
}

// Two stencils of n entries with the same weights at once, stencil a in lanes 0-3 of one 256-bit
// register and stencil b in lanes 4-7: each lane does what weightedSum does (the same fused
// multiply-adds into the same even and odd sums), so the results are its bits, with one fused
// multiply-add per pair of entries instead of two (docs/stencil_kernel.md has what it gains).
// w(k) is weight k broadcast to all eight lanes.
template <class Element, class Weight>
[[gnu::always_inline]] inline __m256 weightedSumPair(const float* src, long srcStride, const int* a, const int* b,
                                                     Weight w, int n) {
    __m256 even = _mm256_setzero_ps(), odd = _mm256_setzero_ps();
    int k = 0;
    for (; k + 1 < n; k += 2) {
        even = _mm256_fmadd_ps(w(k), Element::loadPair(src + a[k] * srcStride, src + b[k] * srcStride), even);
        odd = _mm256_fmadd_ps(w(k + 1), Element::loadPair(src + a[k + 1] * srcStride, src + b[k + 1] * srcStride), odd);
    }
    if (k < n) even = _mm256_fmadd_ps(w(k), Element::loadPair(src + a[k] * srcStride, src + b[k] * srcStride), even);
    return _mm256_add_ps(even, odd);
}

// Stores a pair's two results at rows i and i + 1.
template <class Element>
[[gnu::always_inline]] inline void storePair(float* dst, long dstStride, long i, __m256 sums) {
    Element::store(dst + i * dstStride, _mm256_castps256_ps128(sums));
    Element::store(dst + (i + 1) * dstStride, _mm256_extractf128_ps(sums, 1));
}

// Stencils [i, runEnd) of N entries each, consecutive in the index array from idx, all with the
// pooled weights w: the weights are broadcast into registers once for the whole run, and the
// stencils taken two at a time (an odd last one alone). The groups of a stretch (evalGroup) stay
// one at a time: their pairs, at scattered rows, measured no faster.
template <class Element, int N>
void evalRun(const float* src, long srcStride, float* dst, long dstStride, const int* idx, const float* w, int i,
             int runEnd) {
    __m256 weight[N];
    for (int k = 0; k < N; ++k) weight[k] = _mm256_broadcast_ss(w + k);
    const auto inRegisters = [&](int k) { return weight[k]; };
    for (; i + 1 < runEnd; i += 2, idx += 2 * N)
        storePair<Element>(dst, dstStride, i, weightedSumPair<Element>(src, srcStride, idx, idx + N, inRegisters, N));
    const auto inRegister = [&](int k) { return _mm256_castps256_ps128(weight[k]); };
    if (i < runEnd) Element::store(dst + i * dstStride, weightedSum<Element>(src, srcStride, idx, inRegister, N));
}

// Any size: the weights broadcast from the pool entry by entry, the same operations as evalRun's.
template <class Element>
void evalRunAnySize(const float* src, long srcStride, float* dst, long dstStride, const int* idx, const float* w, int n,
                    int i, int runEnd) {
    const auto fromPool = [w](int k) { return _mm_broadcast_ss(w + k); };
    for (; i < runEnd; ++i, idx += n)
        Element::store(dst + i * dstStride, weightedSum<Element>(src, srcStride, idx, fromPool, n));
}

// The stencils ids[0, count) of a group, N entries each with the pooled weights w: as evalRun,
// each stencil's indices found through offsets and its output written at its own row.
template <class Element, int N>
void evalGroup(const float* src, long srcStride, float* dst, long dstStride, const int* offsets, const int* indices,
               const int* ids, int count, const float* w) {
    __m128 weight[N];
    for (int k = 0; k < N; ++k) weight[k] = _mm_broadcast_ss(w + k);
    const auto inRegister = [&](int k) { return weight[k]; };
    for (int q = 0; q < count; ++q) {
        const long i = ids[q];
        Element::store(dst + i * dstStride, weightedSum<Element>(src, srcStride, indices + offsets[i], inRegister, N));
    }
}

template <class Element>
void evalGroupAnySize(const float* src, long srcStride, float* dst, long dstStride, const int* offsets,
                      const int* indices, const int* ids, int count, const float* w, int n) {
    const auto fromPool = [w](int k) { return _mm_broadcast_ss(w + k); };
    for (int q = 0; q < count; ++q) {
        const long i = ids[q];
        Element::store(dst + i * dstStride, weightedSum<Element>(src, srcStride, indices + offsets[i], fromPool, n));
    }
}

template <class Element>
void evalGroupOfSize(const float* src, long srcStride, float* dst, long dstStride, const StencilArrays& t,
                     const int* ids, const StencilGroup& g) {
    const int *offsets = t.offsets, *indices = t.indices;
    const float* w = t.weights + g.weightOffset;
    switch (g.size) {
    case 3: evalGroup<Element, 3>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    case 4: evalGroup<Element, 4>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    case 5: evalGroup<Element, 5>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    case 6: evalGroup<Element, 6>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    case 7: evalGroup<Element, 7>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    case 8: evalGroup<Element, 8>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    case 9: evalGroup<Element, 9>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    case 10: evalGroup<Element, 10>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    case 11: evalGroup<Element, 11>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    case 12: evalGroup<Element, 12>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w); break;
    default:
        evalGroupAnySize<Element>(src, srcStride, dst, dstStride, offsets, indices, ids, g.count, w, g.size);
        break;
    }
}

// Stencils [i, runEnd) of n entries each sharing the weights w, their indices consecutive from idx:
// unrolled for every size of the schemes' regular and near-regular masks.
template <class Element>
void evalRunOfSize(const float* src, long srcStride, float* dst, long dstStride, const int* idx, const float* w, int n,
                   int i, int runEnd) {
    switch (n) {
    case 3: evalRun<Element, 3>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    case 4: evalRun<Element, 4>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    case 5: evalRun<Element, 5>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    case 6: evalRun<Element, 6>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    case 7: evalRun<Element, 7>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    case 8: evalRun<Element, 8>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    case 9: evalRun<Element, 9>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    case 10: evalRun<Element, 10>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    case 11: evalRun<Element, 11>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    case 12: evalRun<Element, 12>(src, srcStride, dst, dstStride, idx, w, i, runEnd); break;
    default: evalRunAnySize<Element>(src, srcStride, dst, dstStride, idx, w, n, i, runEnd); break;
    }
}

template <class Element>
void evalStencilsSimd(const float* src, int srcStride, float* dst, int dstStride, const StencilArrays& t, int start,
                      int end) {
    // The arrays in locals: the stores through dst could otherwise alias t, and its members would
    // be read again for every stencil.
    const int *offsets = t.offsets, *indices = t.indices, *weightOffsets = t.weightOffsets;
    const float* weights = t.weights;
    for (int i = start; i < end;) {
        // A run: consecutive stencils of one size sharing one pooled weight sequence (the pool
        // stores each distinct sequence once, so equal offsets mean equal weights).
        const int first = offsets[i], n = offsets[i + 1] - first, weightOffset = weightOffsets[i];
        int runEnd = i + 1;
        while (runEnd < end && weightOffsets[runEnd] == weightOffset && offsets[runEnd + 1] - offsets[runEnd] == n)
            ++runEnd;
        evalRunOfSize<Element>(src, srcStride, dst, dstStride, indices + first, weights + weightOffset, n, i, runEnd);
        i = runEnd;
    }
}

// The index of the run holding stencil i (runs in stencil order, the first starting at 0).
int runHolding(const StencilRun* runs, int numRuns, int i) {
    int lo = 0, hi = numRuns - 1;
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (runs[mid].firstStencil <= i)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

// The same runs as evalStencilsSimd finds, but taken from the run list: inside a run no per-stencil
// array is read. A chunk of a stretch of short runs goes group by group where [start, end) covers
// it whole, else (its part in range) through evalStencilsSimd.
template <class Element>
void evalStencilRunsSimd(const float* src, int srcStride, float* dst, int dstStride, const StencilRunArrays& r,
                         int start, int end) {
    const StencilArrays t = r.table;
    const StencilRun* runs = r.runs;
    for (int k = runHolding(runs, r.numRuns, start), i = start; i < end; ++k) {
        const StencilRun run = runs[k];
        const int runEnd = run.firstStencil + run.numStencils < end ? run.firstStencil + run.numStencils : end;
        if (run.firstGroup >= 0 && i == run.firstStencil && runEnd == run.firstStencil + run.numStencils)
            for (int g = run.firstGroup, done = 0; done < run.numStencils; done += r.groups[g].count, ++g)
                evalGroupOfSize<Element>(src, srcStride, dst, dstStride, t, r.order + r.groups[g].first, r.groups[g]);
        else if (run.firstGroup >= 0)
            evalStencilsSimd<Element>(src, srcStride, dst, dstStride, t, i, runEnd);
        else
            evalRunOfSize<Element>(src, srcStride, dst, dstStride,
                                   t.indices + t.offsets[run.firstStencil] + long(i - run.firstStencil) * run.size,
                                   t.weights + run.weightOffset, run.size, i, runEnd);
        i = runEnd;
    }
}

}  // namespace

void evalStencils3Avx2(const float* src, int srcStride, float* dst, int dstStride, const StencilArrays& t, int start,
                       int end) {
    evalStencilsSimd<Xyz>(src, srcStride, dst, dstStride, t, start, end);
}

void evalStencils4Avx2(const float* src, int srcStride, float* dst, int dstStride, const StencilArrays& t, int start,
                       int end) {
    evalStencilsSimd<Xyzw>(src, srcStride, dst, dstStride, t, start, end);
}

void evalStencilRuns3Avx2(const float* src, int srcStride, float* dst, int dstStride, const StencilRunArrays& r,
                          int start, int end) {
    evalStencilRunsSimd<Xyz>(src, srcStride, dst, dstStride, r, start, end);
}

void evalStencilRuns4Avx2(const float* src, int srcStride, float* dst, int dstStride, const StencilRunArrays& r,
                          int start, int end) {
    evalStencilRunsSimd<Xyzw>(src, srcStride, dst, dstStride, r, start, end);
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
