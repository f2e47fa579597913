// Huge pages for the tools' large arrays (tools/memory/huge_page_new.cpp installs them as the
// CLI's and the bench's operator new): an array's first touch, one page fault per 4 KiB page, was
// about half of a level build's time (docs/decisions/). The library itself allocates through
// plain std::vector and leaves this policy to the application.
#pragma once

#include <cstddef>

namespace quadtri::memory {

// Advises the kernel to back the pages of [data, data + bytes) with huge pages when they are
// first touched; nothing where the platform has no such advice. The memory and what it holds
// are unchanged. The range's start moves back to a huge-page boundary where that boundary lies in
// the 4 KiB page of its first byte (a page of the same allocation), forward to a whole page
// otherwise; its end is cut at its last whole huge page, so that the tail stays small and nothing
// past the range becomes resident. A first huge page whose memory is already touched (the
// allocator's header in front of the array) is collapsed into a huge page at once: the kernel
// would otherwise keep the small page it has and fault the rest of those 2 MiB in 4 KiB at a time.
void adviseHugePages(void* data, std::size_t bytes);

// Blocks below this many bytes are left alone: they fill no huge page.
constexpr std::size_t kHugePageAdviceBytes = std::size_t(2) << 20;

// The bytes to allocate for an advised block of `bytes`: a whole number of 2 MiB huge pages less
// one 4 KiB page. An allocator that maps a large block afresh with its header in front (glibc: 16
// bytes) then asks for exactly whole huge pages, which Linux places on a huge-page boundary, so
// every page of the block can be a huge one; without the rounding the block straddles its first
// and last huge pages and those stay small (one fault per 4 KiB).
std::size_t hugePageCapacity(std::size_t bytes);

// A block of `bytes` from malloc, of hugePageCapacity(bytes) and advised when it is
// kHugePageAdviceBytes or more; release it with free().
void* allocateAdvised(std::size_t bytes);

}  // namespace quadtri::memory
