// Stencils recomputed by an edit put back into a table in place (docs/edits.md, "Splicing").
#pragma once

#include <cstddef>
#include <vector>

#include <quadtri/far/limit_stencil_table.h>
#include <quadtri/far/stencil_table.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

struct Splice {
    std::vector<int> changed;  // the rows whose stencil differs, sorted
    bool resized = false;      // a changed row has another size: the arrays moved from it on
    bool poolLaidOut = false;  // the weight pool was laid out again: every row's weight offset may differ
};

// Puts stencil k of `fresh` in row rows[k] of `table` (rows sorted) where the two differ, bit
// for bit. New weight sequences go to the end of the pool; once the pool is over twice
// `poolMark` floats (its size when last laid out) it is laid out again without the sequences no
// row reads, and poolMark becomes its new size.
Splice spliceStencils(StencilTable& table, const std::vector<int>& rows, const StencilTable& fresh,
                      std::size_t& poolMark);

// The pool laid out again in first-use order, each sequence once: what a build makes.
void compactWeights(StencilTable& table);

// The same for a limit table, whose runs of sources and weight triples are both pools: a changed
// row points at its new run and triples, appended (nothing moves). The pools are laid out again
// once either passes twice its mark.
struct LimitPoolMarks {
    std::size_t indices = 0, weights = 0;
};
// Returns the rows changed; `laidOut` says whether the pools were laid out again.
std::vector<int> spliceLimitStencils(LimitStencilTable& table, const std::vector<int>& rows,
                                     const LimitStencilTable& fresh, LimitPoolMarks& marks, bool* laidOut = nullptr);

// Both pools laid out again in stencil order, each sequence once: what a build makes.
void compactPools(LimitStencilTable& table);

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
