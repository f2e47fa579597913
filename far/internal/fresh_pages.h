// Large arrays that a level build allocates and then fills: their first touch, one page fault
// per 4 KiB page, was about half the build's time (docs/architecture.md, "First touch of fresh
// pages"). Reserved through reserveFresh, an array of several MiB asks the kernel for huge pages
// before anything touches it, so it faults once per 2 MiB instead.
#pragma once

#include <cstddef>
#include <vector>

namespace quadtri {
inline namespace v0 {

// Advises the kernel to back the whole pages inside [data, data + bytes) with huge pages when
// they are first touched; nothing where the platform has no such advice. The memory and what it
// holds are unchanged.
void adviseHugePages(void* data, std::size_t bytes);

// Arrays below this many bytes are left alone: they would not fill a huge page of their own.
constexpr std::size_t kHugePageAdviceBytes = std::size_t(4) << 20;

// Reserves room for n elements in a vector about to be sized and filled; when that allocates an
// array of kHugePageAdviceBytes or more, it is advised onto huge pages before its first touch.
// What v holds is kept.
template <class T>
void reserveFresh(std::vector<T>& v, std::size_t n) {
    if (n <= v.capacity()) return;
    v.reserve(n);
    if (n * sizeof(T) >= kHugePageAdviceBytes)
        adviseHugePages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(T));
}

// resize(n) of a vector about to be filled, through reserveFresh.
template <class T>
void resizeFresh(std::vector<T>& v, std::size_t n) {
    reserveFresh(v, n);
    v.resize(n);
}

// assign(n, value) of a vector about to be filled, through reserveFresh.
template <class T, class Value>
void assignFresh(std::vector<T>& v, std::size_t n, Value value) {
    v.clear();
    reserveFresh(v, n);
    v.assign(n, T(value));
}

}  // namespace v0
}  // namespace quadtri
