#include "tools/memory/huge_pages.h"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace quadtri::memory {

namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kSmallPage = 4096;
#if defined(__linux__)
// Linux's MADV_COLLAPSE (6.1: collapse a range into huge pages now), which glibc 2.36's
// <sys/mman.h> does not name yet.
constexpr int kCollapse = 25;
#endif

}  // namespace

std::size_t hugePageCapacity(std::size_t bytes) {
    return (bytes + kSmallPage + kHugePage - 1) / kHugePage * kHugePage - kSmallPage;
}

void adviseHugePages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
    const auto begin = std::uintptr_t(data), end = begin + bytes;
    auto first = (begin + page - 1) / page * page;
    // A huge-page boundary in the page that holds the first byte: that page is mapped with the
    // array, so the advice may start there and take in the whole huge page (4 KiB pages under
    // 2 MiB ones, as on x86-64; other page sizes keep the whole pages inside).
    const bool smallPages = page == kSmallPage;
    const auto hugeBelow = begin / kHugePage * kHugePage;
    const bool fromBoundary = smallPages && begin / page * page == hugeBelow;
    if (fromBoundary) first = hugeBelow;
    // The huge pages that the range fills: a tail past the last one stays small, since a huge
    // page there would make resident the capacity beyond the range.
    const auto last = end / kHugePage * kHugePage;
    // Only a hint: where the kernel refuses it (no transparent huge pages), pages stay small.
    if (last <= first) return;
    (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
    // Linux 6.1 and later; older kernels refuse it, and the first huge page stays small.
    if (fromBoundary && begin > first && last - first >= kHugePage)
        (void)madvise(reinterpret_cast<void*>(first), kHugePage, kCollapse);
#else
    (void)data;
    (void)bytes;
#endif
}

void* allocateAdvised(std::size_t bytes) {
    if (bytes < kHugePageAdviceBytes) return std::malloc(bytes);
    void* data = std::malloc(hugePageCapacity(bytes));
    if (data) adviseHugePages(data, bytes);
    return data;
}

}  // namespace quadtri::memory
