// sameSources() eight at a time: gathers of the output entries' sources, then of the products'
// output entries' sources against the products' own, the differences or-ed together (built with -mavx2, run only where the CPU has it).
#include <immintrin.h>

namespace quadtri {
inline namespace v0 {

bool sameSourcesAvx2(const int* products, int n, const int* first, int size, const int* pattern, int* sources) {
    int s = 0;
    for (; s + 8 <= size; s += 8) {
        const __m256i at = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(first + s));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(sources + s), _mm256_i32gather_epi32(products, at, 4));
    }
    for (; s < size; ++s) sources[s] = products[first[s]];
    __m256i differ = _mm256_setzero_si256();
    int p = 0;
    for (; p + 8 <= n; p += 8) {
        const __m256i at = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(pattern + p));
        const __m256i want = _mm256_i32gather_epi32(sources, at, 4);
        const __m256i have = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(products + p));
        differ = _mm256_or_si256(differ, _mm256_xor_si256(want, have));
    }
    int rest = 0;
    for (; p < n; ++p) rest |= products[p] ^ sources[pattern[p]];
    return rest == 0 && _mm256_testz_si256(differ, differ);
}

}  // namespace v0
}  // namespace quadtri
