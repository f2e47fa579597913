// The evaluation form of a StencilTable: its stencils grouped into runs that share one size and
// one pooled weight sequence, so that the evaluators read neither `offsets` nor `weightOffsets`
// inside a run (8 of the ~33 table bytes a Catmull-Clark stencil costs; docs/stencil_kernel.md).
// Built once from a table (one pass over its per-stencil arrays), then passed to
// CpuEvaluator::EvalStencils or TbbEvaluator::EvalStencils in place of the table; the results are
// bitwise those of the table itself.
#pragma once

#include <cstddef>
#include <vector>

#include <quadtri/far/stencil_table.h>

namespace quadtri {
inline namespace v0 {

// Stencils [firstStencil, firstStencil + numStencils): a run of `size` entries each, all with the
// pooled weights at weightOffset, their indices consecutive from the table's
// offsets[firstStencil]; or, where weightOffset is -1 (size 0), a stretch of stencils in runs too
// short to be worth an entry here, evaluated through the table's per-stencil arrays.
struct StencilRun {
    int firstStencil;
    int numStencils;
    int size;
    int weightOffset;
};

class StencilRuns {
public:
    // Runs of at least this many stencils get an entry; shorter ones are merged into stretches read
    // through the per-stencil arrays (an entry costs 16 bytes, what two stencils' arrays do, and
    // the kernel's set-up for a run, its weights broadcast once, pays off over several stencils).
    static constexpr int kMinRun = 8;

    // Keeps a pointer to `table`: the table must outlive this object and keep its stencils; the
    // evaluators reject a table whose stencil count changed since (std::invalid_argument).
    explicit StencilRuns(const StencilTable& table);

    const StencilTable& table() const { return *table_; }
    // In stencil order, covering [0, numStencils()) without gaps.
    const std::vector<StencilRun>& runs() const { return runs_; }
    // The table's stencil count when the runs were built.
    int numStencils() const { return numStencils_; }
    std::size_t bytes() const { return runs_.size() * sizeof(StencilRun); }

private:
    const StencilTable* table_;
    int numStencils_;
    std::vector<StencilRun> runs_;
};

}  // namespace v0
}  // namespace quadtri
