#include <quadtri/osd/stencil_runs.h>

#include <algorithm>

namespace quadtri {
inline namespace v0 {

StencilRuns::StencilRuns(const StencilTable& table) : table_(&table), numStencils_(table.numStencils()) {
    const int n = numStencils_;
    int stretch = 0;  // first stencil of the stretch of short runs being collected
    for (int i = 0; i < n;) {
        const int size = table.size(i), weightOffset = table.weightOffsets[i];
        int end = i + 1;
        while (end < n && table.weightOffsets[end] == weightOffset && table.size(end) == size) ++end;
        if (end - i >= kMinRun) {
            addStretch(stretch, i);
            runs_.push_back({i, end - i, size, weightOffset, -1});
            stretch = end;
        }
        i = end;
    }
    addStretch(stretch, n);
}

// Stencils [first, end) in chunks that end at multiples of kChunk (so that TbbEvaluator's blocks,
// which start at such multiples, cover whole chunks), each chunk's stencils grouped by (size,
// weights) in the order the masks first appear, table order inside a group.
void StencilRuns::addStretch(int first, int end) {
    const StencilTable& t = *table_;
    std::vector<int> groupOf, filled;  // per stencil of the chunk its group; per group the stencils placed
    for (int chunk = first, chunkEnd; chunk < end; chunk = chunkEnd) {
        chunkEnd = std::min(end, (chunk / kChunk + 1) * kChunk);
        const int firstGroup = int(groups_.size());
        runs_.push_back({chunk, chunkEnd - chunk, 0, -1, firstGroup});
        groupOf.resize(std::size_t(chunkEnd - chunk));
        for (int i = chunk; i < chunkEnd; ++i) {  // each stencil's group, counted
            int g = firstGroup;
            while (g < int(groups_.size()) &&
                   (groups_[g].weightOffset != t.weightOffsets[i] || groups_[g].size != t.size(i)))
                ++g;
            if (g == int(groups_.size())) groups_.push_back({0, 0, t.size(i), t.weightOffsets[i]});
            ++groups_[g].count;
            groupOf[i - chunk] = g;
        }
        for (int g = firstGroup, at = int(order_.size()); g < int(groups_.size()); at += groups_[g].count, ++g)
            groups_[g].first = at;
        order_.resize(order_.size() + std::size_t(chunkEnd - chunk));
        filled.assign(groups_.size() - firstGroup, 0);
        for (int i = chunk; i < chunkEnd; ++i) {
            const int g = groupOf[i - chunk];
            order_[groups_[g].first + filled[g - firstGroup]++] = i;
        }
    }
}

}  // namespace v0
}  // namespace quadtri
