// The one place far/ meets oneTBB: loops whose items write only their own entries, two calls
// side by side, per-thread scratch, and how many threads may run. Built without oneTBB
// (QUADTRI_WITH_TBB off), each runs on the calling thread; no table depends on the thread count,
// so both builds make the same bits.
#pragma once

#include <utility>

#ifdef QUADTRI_HAVE_TBB
#include <algorithm>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#else
#include <optional>
#endif

namespace quadtri {
inline namespace v0 {
namespace internal {
namespace parallel {

#ifdef QUADTRI_HAVE_TBB

// Threads of the calling oneTBB arena.
inline int arenaThreads() { return tbb::this_task_arena::max_concurrency(); }

// The arena's threads, unless a tbb::global_control allows fewer.
inline int allowedThreads() {
    return int(std::min<std::size_t>(std::size_t(arenaThreads()),
                                     tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
}

// body(i) for every i in [begin, end), one task each (a few large parts).
template <typename Body>
void forEachPart(int begin, int end, const Body& body) {
    if (end - begin == 1) return body(begin);  // one part: no task (local refinement builds many tiny tables)
    tbb::parallel_for(begin, end, body);
}

// body(first, last) over sub-ranges of [begin, end) of about `grain` items.
template <typename Index, typename Body>
void forEachRange(Index begin, Index end, Index grain, const Body& body) {
    if (end - begin <= grain) {  // one range: no task (local refinement runs many tiny loops)
        if (begin < end) body(begin, end);
        return;
    }
    tbb::parallel_for(tbb::blocked_range<Index>(begin, end, grain),
                      [&](const tbb::blocked_range<Index>& r) { body(r.begin(), r.end()); });
}

// a() and b() side by side.
template <typename A, typename B>
void invoke(const A& a, const B& b) {
    tbb::parallel_invoke(a, b);
}

// A T per thread, made by `make` on the thread's first local().
template <typename T>
class ThreadLocal {
public:
    template <typename Make>
    explicit ThreadLocal(Make make) : values_(std::move(make)) {}
    T& local() { return values_.local(); }

private:
    tbb::enumerable_thread_specific<T> values_;
};

#else

inline int arenaThreads() { return 1; }
inline int allowedThreads() { return 1; }

template <typename Body>
void forEachPart(int begin, int end, const Body& body) {
    for (int i = begin; i < end; ++i) body(i);
}

template <typename Index, typename Body>
void forEachRange(Index begin, Index end, Index, const Body& body) {
    if (begin < end) body(begin, end);
}

template <typename A, typename B>
void invoke(const A& a, const B& b) {
    a();
    b();
}

template <typename T>
class ThreadLocal {
public:
    template <typename Make>
    explicit ThreadLocal(Make make) : value_(make()) {}
    T& local() { return value_; }

private:
    T value_;
};

#endif

}  // namespace parallel
}  // namespace internal
}  // namespace v0
}  // namespace quadtri
