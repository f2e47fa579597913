// Accumulates weights over vertex indices for one stencil at a time, merging repeated indices.
// Small stencils (all regular masks) merge by a linear search of their few entries, which stay
// in L1; a stencil that grows past kLinearLimit entries switches to a dense slot array indexed
// by vertex (O(1) per add), which would otherwise cost a cache miss per add on large levels.
// Entries live in arrays kept at their high-water size, so adding and flushing never allocate
// once warmed up.
#pragma once

#include <vector>

namespace quadtri {
inline namespace v0 {
namespace internal {

class SparseAccumulator {
public:
    explicit SparseAccumulator(int numVertices) : numVertices_(numVertices), indices_(64), weights_(64) {}

    void add(int vertex, double weight) {
        if (size_ <= kLinearLimit) {
            for (int k = 0; k < size_; ++k)
                if (indices_[k] == vertex) {
                    weights_[k] += weight;
                    return;
                }
            append(vertex, weight);
            if (size_ > kLinearLimit) useSlots();
            return;
        }
        int& s = slot_[vertex];
        if (s < 0) {
            s = size_;
            append(vertex, weight);
        } else {
            weights_[s] += weight;
        }
    }

    int size() const { return size_; }

    // Writes the stencil's size() entries (in first-touched order) and resets.
    template <typename Weight>
    void flushTo(int* indices, Weight* weights) {
        for (int k = 0; k < size_; ++k) {
            indices[k] = indices_[k];
            weights[k] = Weight(weights_[k]);
        }
        if (size_ > kLinearLimit)
            for (int k = 0; k < size_; ++k) slot_[indices_[k]] = -1;
        size_ = 0;
    }

    // Appends the stencil to growing arrays and resets; returns its size.
    template <typename Weight>
    int flush(std::vector<int>& indices, std::vector<Weight>& weights) {
        const int n = size_;
        const std::size_t i0 = indices.size(), w0 = weights.size();
        indices.resize(i0 + n);
        weights.resize(w0 + n);
        flushTo(indices.data() + i0, weights.data() + w0);
        return n;
    }

private:
    static constexpr int kLinearLimit = 16;

    void append(int vertex, double weight) {
        if (size_ == int(indices_.size())) {
            indices_.resize(2 * indices_.size());
            weights_.resize(2 * weights_.size());
        }
        indices_[size_] = vertex;
        weights_[size_] = weight;
        ++size_;
    }

    void useSlots() {
        if (slot_.empty()) slot_.assign(numVertices_, -1);
        for (int k = 0; k < size_; ++k) slot_[indices_[k]] = k;
    }

    int numVertices_;
    int size_ = 0;
    std::vector<int> slot_;  // allocated at the first large stencil; -1 outside a flush
    std::vector<int> indices_;
    std::vector<double> weights_;
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
