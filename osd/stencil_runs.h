// The evaluation form of a StencilTable: its stencils grouped into runs that share one size and
// one pooled weight sequence, so that the evaluators read neither `offsets` nor `weightOffsets`
// inside a run (8 of the ~33 table bytes a Catmull-Clark stencil costs), and the stretches of
// short runs (a mixed mesh's Schaefer-Warren levels) sorted by mask chunk by chunk, so that the
// loop keeps its weights in registers and its branches predictable there too
// (docs/stencil_kernel.md). Built once from a table (a pass over its per-stencil arrays), then
// passed to CpuEvaluator::EvalStencilRuns or TbbEvaluator::EvalStencilRuns in place of the
// table; the results are bitwise those of the table itself.
#pragma once

#include <cstddef>
#include <vector>

#include <quadtri/export.h>
#include <quadtri/far/stencil_table.h>

namespace quadtri {
inline namespace v0 {

// Stencils [firstStencil, firstStencil + numStencils). A run (firstGroup -1): `size` entries each,
// all with the pooled weights at weightOffset, their indices consecutive from the table's
// offsets[firstStencil]. A chunk of a stretch of short runs (firstGroup >= 0, size 0,
// weightOffset -1): its stencils listed by mask in groups [firstGroup, the next chunk's).
struct StencilRun {
    int firstStencil;
    int numStencils;
    int size;
    int weightOffset;
    int firstGroup;
};

// Stencils order()[first, first + count) of one chunk, all of `size` entries with the pooled
// weights at weightOffset.
struct StencilGroup {
    int first;
    int count;
    int size;
    int weightOffset;
};

class QUADTRI_API StencilRuns {
public:
    // Runs of at least this many stencils get an entry (an entry costs what two or three stencils'
    // arrays do, and the kernel's set-up for a run, its weights broadcast once, pays off over
    // several stencils); shorter ones form stretches.
    static constexpr int kMinRun = 8;
    // Stencils of a stretch per chunk at most (chunks end at its multiples): big enough for groups
    // of ~20 stencils on a mixed mesh's levels, small enough that a chunk's indices and outputs
    // stay in L2 while it is evaluated in mask order. A range that covers only part of a chunk
    // evaluates that part in table order.
    static constexpr int kChunk = 256;

    // Keeps a pointer to `table`: the table must outlive this object and keep its stencils; the
    // evaluators reject a table whose stencil count changed since (std::invalid_argument).
    explicit StencilRuns(const StencilTable& table);

    const StencilTable& table() const { return *table_; }
    // In stencil order, covering [0, numStencils()) without gaps.
    const std::vector<StencilRun>& runs() const { return runs_; }
    const std::vector<StencilGroup>& groups() const { return groups_; }
    // The stencils of every chunk, chunk after chunk, group after group.
    const std::vector<int>& order() const { return order_; }
    // The table's stencil count when the runs were built.
    int numStencils() const { return numStencils_; }
    std::size_t bytes() const {
        return runs_.size() * sizeof(StencilRun) + groups_.size() * sizeof(StencilGroup) + order_.size() * sizeof(int);
    }

private:
    void addStretch(int first, int end);

    const StencilTable* table_;
    int numStencils_;
    std::vector<StencilRun> runs_;
    std::vector<StencilGroup> groups_;
    std::vector<int> order_;
};

}  // namespace v0
}  // namespace quadtri
