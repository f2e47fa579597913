// One composed stencil at a time: weights summed in double per source vertex through a dense
// slot array (a slot per source, -1 while untouched) and the list of sources touched, in the
// order first touched. Every add is O(1) whatever the stencil's size; composed stencils span a
// few dozen sources of a local neighbourhood, so the slots they touch stay in cache. Used by the
// composition of tables only (far/tables/compose_stencils.cpp); the per-level build keeps its own
// accumulator (sparse_accumulator.h).
#pragma once

#include <cstdint>
#include <vector>

namespace quadtri {
inline namespace v0 {
namespace internal {

class ScatterRow {
public:
    explicit ScatterRow(int numSources) : slot_(numSources, -1), indices_(64), weights_(64) {}

    // Room for `more` adds past size(): addScaled itself never checks.
    void reserve(int more) {
        if (size_ + more <= int(indices_.size())) return;
        const std::size_t grown = 2 * (std::size_t(size_) + std::size_t(more));
        indices_.resize(grown);
        weights_.resize(grown);
    }

    // Adds scale * weights[m] to the sum of sources[m], m < n, in that order. A source seen
    // before gets its term added to its sum; a new one starts its sum at the term itself (not
    // 0 + term, which would turn -0.0 into +0.0).
    // Weights of a float table widen to double exactly.
    template <class Weight>
    void addScaled(const int* sources, const Weight* weights, int n, double scale) {
        add([sources](int m) { return sources[m]; }, weights, n, scale);
    }
    // The same with source m at patch[corners[m]] (a templated stencil, regular_patches.h).
    void addScaled(const int* patch, const std::uint8_t* corners, const double* weights, int n, double scale) {
        add([patch, corners](int m) { return patch[corners[m]]; }, weights, n, scale);
    }

    int size() const { return size_; }
    const int* indices() const { return indices_.data(); }
    const double* weights() const { return weights_.data(); }

    // Forgets the stencil: its slots back to -1.
    void clear() {
        for (int k = 0; k < size_; ++k) slot_[indices_[k]] = -1;
        size_ = 0;
    }

private:
    // Raw pointers in locals: the stores cannot alias the row's own members.
    template <class Source, class Weight>
    void add(Source source, const Weight* weights, int n, double scale) {
        int* slot = slot_.data();
        int* indices = indices_.data();
        double* sums = weights_.data();
        int size = size_;
        for (int m = 0; m < n; ++m) {
            const int v = source(m);
            const double term = scale * double(weights[m]);
            const int at = slot[v];
            if (at < 0) {
                slot[v] = size;
                indices[size] = v;
                sums[size++] = term;
            } else {
                sums[at] += term;
            }
        }
        size_ = size;
    }

    std::vector<int> slot_;  // per source: its entry in the stencil, -1 outside it
    std::vector<int> indices_;
    std::vector<double> weights_;
    int size_ = 0;
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
