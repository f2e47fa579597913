// Large arrays that a level build allocates and then fills: their first touch, one page fault
// per 4 KiB page, was about half the build's time (docs/architecture.md, "First touch of fresh
// pages"). Reserved through reserveFresh, an array of 2 MiB or more is sized to whole huge pages
// and asks the kernel for them before anything touches it, so it faults once per 2 MiB instead;
// resizeFresh and assignFresh, which know the size, also have its pages made resident ahead.
#pragma once

#include <cstddef>
#include <iterator>
#include <vector>

namespace quadtri {
inline namespace v0 {

// Advises the kernel to back the pages of [data, data + bytes) with huge pages when they are
// first touched; nothing where the platform has no such advice. The memory and what it holds
// are unchanged. The range's start moves back to a huge-page boundary where that boundary lies in
// the 4 KiB page of its first byte (a page of the same allocation), forward to a whole page
// otherwise; its end is cut at its last whole huge page, so that the tail stays small and nothing
// past the range becomes resident. A first huge page whose memory is already touched (the
// allocator's header in front of the array) is collapsed into a huge page at once: the kernel
// would otherwise keep the small page it has and fault the rest of those 2 MiB in 4 KiB at a time.
void adviseHugePages(void* data, std::size_t bytes);

// Arrays below this many bytes are left alone: they fill no huge page.
constexpr std::size_t kHugePageAdviceBytes = std::size_t(2) << 20;

// The capacity in bytes reserved for an advised array of `bytes`: a whole number of 2 MiB huge
// pages less one 4 KiB page. An allocator that maps a large block afresh with its header in
// front (glibc: 16 bytes) then asks for exactly whole huge pages, which Linux places on a
// huge-page boundary, so every page of the array can be a huge one; without the rounding the
// block straddles its first and last huge pages and those stay small (one fault per 4 KiB).
std::size_t hugePageCapacity(std::size_t bytes);

// Reserves room for n elements in a vector about to be sized and filled; when that allocates an
// array of kHugePageAdviceBytes or more, its capacity is rounded by hugePageCapacity and its
// first n elements are advised onto huge pages before their first touch (the capacity past them
// is never touched, so it costs address space only). What v holds is kept.
template <class T>
void reserveFresh(std::vector<T>& v, std::size_t n) {
    if (n <= v.capacity()) return;
    // (A size near max_size goes to reserve as it is, which refuses it as it would anyway.)
    if (n > v.max_size() / 2 || n * sizeof(T) < kHugePageAdviceBytes) return v.reserve(n);
    // A new block advised before v's elements are copied into it: a copy made first would touch
    // its pages as small ones.
    std::vector<T> fresh;
    fresh.reserve(hugePageCapacity(n * sizeof(T)) / sizeof(T));
    adviseHugePages(fresh.data(), n * sizeof(T));
    fresh.insert(fresh.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
    v.swap(fresh);
}

// Makes the whole pages of [data, data + bytes) resident before they are written, in parallel,
// each task a stretch of them (Linux 5.14: MADV_POPULATE_WRITE); nothing elsewhere, or where the
// range's last page is resident already (a block the allocator reused). Faulting them in one call
// per stretch saves the trap of a fault per page that the writes would take, and the writes that
// follow (a vector's value-initialisation, on one thread) find them there.
void populatePages(void* data, std::size_t bytes);

// Arrays of fewer bytes are not populated ahead: a handful of faults.
constexpr std::size_t kPopulateBytes = std::size_t(256) << 10;

// resize(n) of a vector about to be filled, through reserveFresh.
template <class T>
void resizeFresh(std::vector<T>& v, std::size_t n) {
    reserveFresh(v, n);
    if (n > v.size() && (n - v.size()) * sizeof(T) >= kPopulateBytes)
        populatePages(v.data() + v.size(), (n - v.size()) * sizeof(T));
    v.resize(n);
}

// assign(n, value) of a vector about to be filled, through reserveFresh.
template <class T, class Value>
void assignFresh(std::vector<T>& v, std::size_t n, Value value) {
    v.clear();
    reserveFresh(v, n);
    if (n * sizeof(T) >= kPopulateBytes) populatePages(v.data(), n * sizeof(T));
    v.assign(n, T(value));
}

}  // namespace v0
}  // namespace quadtri
