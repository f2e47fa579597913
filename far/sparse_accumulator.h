// Accumulates weights over vertex indices for one stencil at a time, merging repeated indices
// through a dense slot array (O(1) per add, no hashing, no allocation once warmed up).
#pragma once

#include <vector>

namespace quadtri {

class SparseAccumulator {
public:
    explicit SparseAccumulator(int numVertices) : slot_(numVertices, -1) {}

    void add(int vertex, double weight) {
        int& s = slot_[vertex];
        if (s < 0) {
            s = int(indices_.size());
            indices_.push_back(vertex);
            weights_.push_back(weight);
        } else {
            weights_[s] += weight;
        }
    }

    // Appends the stencil (in first-touched order) and resets; returns its size.
    template <typename Weight>
    int flush(std::vector<int>& indices, std::vector<Weight>& weights) {
        const int n = int(indices_.size());
        for (int k = 0; k < n; ++k) {
            indices.push_back(indices_[k]);
            weights.push_back(Weight(weights_[k]));
            slot_[indices_[k]] = -1;
        }
        indices_.clear();
        weights_.clear();
        return n;
    }

private:
    std::vector<int> slot_;
    std::vector<int> indices_;
    std::vector<double> weights_;
};

}  // namespace quadtri
