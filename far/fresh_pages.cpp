#include "far/internal/fresh_pages.h"

#include <algorithm>
#include <cstdint>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace quadtri {
inline namespace v0 {

namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kSmallPage = 4096;
#if defined(__linux__)
// Linux's MADV_COLLAPSE (6.1: collapse a range into huge pages now), which glibc 2.36's
// <sys/mman.h> does not name yet.
constexpr int kCollapse = 25;
// MADV_POPULATE_WRITE (5.14), likewise.
constexpr int kPopulateWrite = 23;
// Bytes a task populates: enough to amortise the call and the task.
constexpr std::size_t kPopulateGrain = std::size_t(1) << 20;
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

void populatePages(void* data, std::size_t bytes) {
#if defined(__linux__)
    const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
    // The whole pages of the range: a page shared with the memory before or after it is faulted
    // by the write as before.
    const auto first = (std::uintptr_t(data) + page - 1) / page * page;
    const auto last = (std::uintptr_t(data) + bytes) / page * page;
    if (last <= first) return;
    // Memory the allocator hands back from its own (a freed block reused) is mostly resident
    // already, and populating it would only walk its page tables: its last page tells (a fresh
    // block's first pages may hold the allocator's header, or a huge page collapsed at once).
    unsigned char resident = 0;
    if (mincore(reinterpret_cast<void*>(last - page), page, &resident) == 0 && (resident & 1)) return;
    const std::size_t chunks = (last - first + kPopulateGrain - 1) / kPopulateGrain;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks), [&](const tbb::blocked_range<std::size_t>& r) {
        const auto begin = first + r.begin() * kPopulateGrain;
        const auto end = std::min<std::uintptr_t>(last, first + r.end() * kPopulateGrain);
        // A hint like the others: a kernel without it refuses, and the writes fault as before.
        (void)madvise(reinterpret_cast<void*>(begin), end - begin, kPopulateWrite);
    });
#else
    (void)data;
    (void)bytes;
#endif
}

}  // namespace v0
}  // namespace quadtri
