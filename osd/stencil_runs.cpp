#include <quadtri/osd/stencil_runs.h>

namespace quadtri {
inline namespace v0 {

StencilRuns::StencilRuns(const StencilTable& table) : table_(&table), numStencils_(table.numStencils()) {
    const int n = numStencils_;
    for (int i = 0; i < n;) {
        const int size = table.size(i), weightOffset = table.weightOffsets[i];
        int end = i + 1;
        while (end < n && table.weightOffsets[end] == weightOffset && table.size(end) == size) ++end;
        if (end - i >= kMinRun)
            runs_.push_back({i, end - i, size, weightOffset});
        else if (!runs_.empty() && runs_.back().weightOffset < 0)
            runs_.back().numStencils += end - i;  // extends the stretch before it
        else
            runs_.push_back({i, end - i, 0, -1});
        i = end;
    }
}

}  // namespace v0
}  // namespace quadtri
