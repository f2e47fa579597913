// The portable check, or the AVX2 one where the CPU has it (asked once per process).
#include "far/internal/same_sources.h"

#include "kernels/cpu_features.h"

namespace quadtri {
inline namespace v0 {

#if defined(QUADTRI_HAVE_AVX2_KERNELS)
bool sameSourcesAvx2(const int* products, int n, const int* first, int size, const int* pattern, int* sources);
#endif

bool sameSources(const int* products, int n, const int* first, int size, const int* pattern, int* sources) {
#if defined(QUADTRI_HAVE_AVX2_KERNELS)
    if (kernels::cpuRunsAvx2Kernels()) return sameSourcesAvx2(products, n, first, size, pattern, sources);
#endif
    for (int s = 0; s < size; ++s) sources[s] = products[first[s]];
    int mismatches = 0;
    for (int p = 0; p < n; ++p) mismatches += products[p] != sources[pattern[p]];
    return mismatches == 0;
}

}  // namespace v0
}  // namespace quadtri
