// Interning of sequences: a float table stores each distinct weight sequence once, since after a
// level or two nearly every stencil is one of a handful of regular masks; a limit table stores
// each distinct run of source indices once, since the limit points inside one regular face all
// read the same control vertices.
#pragma once

#include <cstdint>
#include <vector>

namespace quadtri {
inline namespace v0 {
namespace internal {

// T is float (weights) or int (source indices).
template <class T>
class SequencePool {
public:
    SequencePool();

    // Pool offset of the sequence v[0..n): that of a bitwise-equal earlier sequence of the same
    // length if there is one, else of a copy appended now. Bitwise equality (not ==) keeps 0.0
    // and -0.0 apart, so sharing never changes a result. v must not point into the pool itself.
    // Offsets stay valid as the pool grows.
    int intern(const T* v, int n);

    const std::vector<T>& values() const { return values_; }
    // Hands the pool's values over (a table's `weights` or `indices`), leaving the pool empty.
    std::vector<T> take();

private:
    // One interned sequence. An empty slot has offset -1; the hash is kept so that growing never
    // rereads the values and most mismatches are rejected without comparing them.
    struct Slot {
        std::uint32_t hash;
        int offset;
        int size;
    };
    static constexpr Slot kEmptySlot{0, -1, 0};

    void grow();

    std::vector<T> values_;
    std::vector<Slot> slots_;  // open addressing, linear probing; capacity a power of two
    int used_ = 0;
};

using WeightPool = SequencePool<float>;
using IndexPool = SequencePool<int>;

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
