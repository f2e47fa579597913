// Whether the kernels' AVX2 + FMA loops may run: built in (QUADTRI_HAVE_AVX2_KERNELS, x86-64 with
// a compiler that takes -mavx2 -mfma for those files) and the CPU has both (asked once per
// process). The rest of the library is built for the baseline CPU, so it runs anywhere.
#pragma once

namespace quadtri {
inline namespace v0 {
namespace kernels {

inline bool cpuRunsAvx2Kernels() {
#if defined(QUADTRI_HAVE_AVX2_KERNELS)
    static const bool available = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return available;
#else
    return false;
#endif
}

}  // namespace kernels
}  // namespace v0
}  // namespace quadtri
