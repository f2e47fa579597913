#include "far/internal/fresh_pages.h"

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace quadtri {
inline namespace v0 {

void adviseHugePages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const auto page = std::uintptr_t(sysconf(_SC_PAGESIZE));
    const auto first = (std::uintptr_t(data) + page - 1) / page * page;
    const auto last = (std::uintptr_t(data) + bytes) / page * page;
    // Only a hint: where the kernel refuses it (no transparent huge pages), pages stay small.
    if (last > first) (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
    (void)data;
    (void)bytes;
#endif
}

}  // namespace v0
}  // namespace quadtri
