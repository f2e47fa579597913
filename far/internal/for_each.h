// The analyzer's parallel loop over items that each write only their own entries (a child
// level's arrays, level 0's tags): the result is the same on any number of threads.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace quadtri {
inline namespace v0 {

// Items per task: enough work to amortise a task, few enough that both cores get a share of a
// small level.
constexpr int kForEachGrain = 4096;

// body(i) for every i in [0, count), on oneTBB's threads.
template <typename Body>
void forEach(int count, const Body& body) {
    tbb::parallel_for(tbb::blocked_range<int>(0, count, kForEachGrain), [&](const tbb::blocked_range<int>& r) {
        for (int i = r.begin(); i != r.end(); ++i) body(i);
    });
}

}  // namespace v0
}  // namespace quadtri
