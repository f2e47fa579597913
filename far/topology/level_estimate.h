// The memory guard's estimate of one refinement step (docs/architecture.md, "Memory guard").
#pragma once

#include <cstddef>

#include "far/schemes/scheme.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// Edges of a level, or a bound when it holds its faces only (one per corner: an open mesh's
// count).
std::size_t edgeCountBound(const Topology& level);

// Bytes of `count` more entries of a per-level table as the estimate counts them (an index
// each, twice over: the parts built by other threads are copied into the table).
inline std::size_t tableEntryBytes(std::size_t count) { return 2 * count * sizeof(int); }

// Bytes of refining `parent` one level under `rules`: the child topology, the per-level table
// with its parts, a 3-float output, per-thread accumulators, and the scheme's own extra
// (SchemeRules::extraLevelBytes). `parent` may hold its faces only (a looser bound then).
std::size_t estimateLevelBytes(const Topology& parent, const SchemeRules& rules);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
