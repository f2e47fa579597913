// Interning of stencil weight sequences: a float table stores each distinct sequence once, since
// after a level or two nearly every stencil is one of a handful of regular masks.
#pragma once

#include <cstdint>
#include <vector>

namespace quadtri {
inline namespace v0 {

class WeightPool {
public:
    WeightPool();

    // Pool offset of the sequence w[0..n): that of a bitwise-equal earlier sequence of the same
    // length if there is one, else of a copy appended now. Bitwise equality (not ==) keeps 0.0
    // and -0.0 apart, so sharing never changes a result. w must not point into the pool itself.
    // Offsets stay valid as the pool grows.
    int intern(const float* w, int n);

    const std::vector<float>& weights() const { return weights_; }
    // Hands the pool's weights over (a table's `weights`), leaving the pool empty.
    std::vector<float> takeWeights();

private:
    // One interned sequence. An empty slot has offset -1; the hash is kept so that growing never
    // rereads the weights and most mismatches are rejected without comparing them.
    struct Slot {
        std::uint32_t hash;
        int offset;
        int size;
    };
    static constexpr Slot kEmptySlot{0, -1, 0};

    void grow();

    std::vector<float> weights_;
    std::vector<Slot> slots_;  // open addressing, linear probing; capacity a power of two
    int used_ = 0;
};

}  // namespace v0
}  // namespace quadtri
