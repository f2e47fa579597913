// Building limit stencil tables (docs/limit.md): one LimitMask per vertex of a level from the
// scheme's hook (SchemeRules::limitMask), in double; composition over the control vertices; the
// float table with pooled runs of sources and pooled weight triples.
#pragma once

#include <cstddef>
#include <vector>

#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/options.h>
#include <quadtri/far/topology.h>
#include "far/internal/stencil_table_double.h"

namespace quadtri {
inline namespace v0 {
namespace internal {

// Plain CSR with three double weights per entry, interleaved (position, dU, dV) as in
// LimitStencilTable, but nothing pooled: stencil i's entries are [offsets[i], offsets[i] + sizes[i]),
// in the order they were built, entry k's weights at weights[3k .. 3k + 3).
struct LimitStencilTableD {
    int numSourceVertices = 0;
    std::vector<int> sizes;
    std::vector<int> offsets;
    std::vector<int> indices;
    std::vector<double> weights;
    int numStencils() const { return int(sizes.size()); }
};

class RingStarts;
class LimitMaskCache;

// The limit masks of every vertex of `level` (full topology) over its own vertices. `starts`
// says where interior rings start (as OpenSubdiv does after refining, far/limit/limit_ring.h);
// null: at each vertex's lowest-numbered face, as OpenSubdiv does at level 0.
LimitStencilTableD buildLimitStencils(const Topology& level, const Options& options, const RingStarts* starts);

// The limit masks of `vertices` alone, stencil k that of vertices[k], each as buildLimitStencils
// makes it, bit for bit; `cache` may be kept between calls (its answers do not depend on what it
// holds). One thread.
LimitStencilTableD buildLimitStencilsOf(const Topology& level, const Options& options, const RingStarts* starts,
                                        const std::vector<int>& vertices, LimitMaskCache& cache);

// toFloatTable(buildLimitStencils(level, options, starts)), bit for bit, without the double table:
// the masks made, sorted and rounded in parts on the threads, interned in vertex order on one.
// Throws std::length_error once its entries, counted as if none were pooled, would pass
// `maxBytes`.
LimitStencilTable buildLimitStencilsToFloat(const Topology& level, const Options& options, const RingStarts* starts,
                                            std::size_t maxBytes = ~std::size_t(0));

// limit ∘ inner: the limit stencils expanded over inner's sources, in double, on one thread. The
// reference composeLimitStencilsToFloat is tested against (the Refiner composes to float).
LimitStencilTableD composeLimitStencils(const LimitStencilTableD& limit, const StencilTableD& inner);

// toFloatTable(composeLimitStencils(limit, inner)), bit for bit, without the double table between
// them (an index and three doubles an entry, hundreds of MB at the demo's level 3, first touched
// as new pages): parts of stencils composed, sorted and rounded on the threads, interned in stencil
// order on one. Throws std::length_error once its entries, counted as if none were pooled, would
// pass `maxBytes`.
LimitStencilTable composeLimitStencilsToFloat(const LimitStencilTableD& limit, const StencilTableD& inner,
                                              std::size_t maxBytes = ~std::size_t(0));

// Rounded to float: each stencil's entries sorted by source (a source listed twice becomes one
// entry, its weights added in double), its run of sources and its weight triples each interned in
// their pool. Sorted in parts on the threads, interned on one in stencil order, so the table is the
// same whoever built `table` and on any number of threads.
LimitStencilTable toFloatTable(const LimitStencilTableD& table);

std::size_t bytesOf(const LimitStencilTableD& table);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
