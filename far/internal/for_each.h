// The analyzer's parallel loop over items that each write only their own entries (a child
// level's arrays, level 0's tags): the result is the same on any number of threads.
#pragma once

#include "far/internal/parallel.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// Items per task: enough work to amortise a task, few enough that both cores get a share of a
// small level.
constexpr int kForEachGrain = 4096;

// body(i) for every i in [0, count), on the arena's threads.
template <typename Body>
void forEach(int count, const Body& body) {
    parallel::forEachRange(0, count, kForEachGrain, [&](int first, int last) {
        for (int i = first; i != last; ++i) body(i);
    });
}

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
