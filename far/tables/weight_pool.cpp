#include "far/tables/weight_pool.h"

#include <cstring>
#include <utility>

namespace quadtri {
inline namespace v0 {
namespace internal {

namespace {

constexpr int kInitialSlots = 64;  // a power of two; a regular level needs a handful

// Multiply-xorshift over the values' bits: the multiply carries every bit upwards, the shift
// brings the high half back down, so the low bits that pick a slot depend on every value.
template <class T>
std::uint32_t hashValues(const T* v, int n) {
    static_assert(sizeof(T) == sizeof(std::uint32_t), "pooled values are 32-bit");
    std::uint64_t h = 0x9E3779B97F4A7C15ull * std::uint64_t(n + 1);
    for (int k = 0; k < n; ++k) {
        std::uint32_t bits;
        std::memcpy(&bits, v + k, sizeof bits);
        h = (h ^ bits) * 0xFF51AFD7ED558CCDull;
        h ^= h >> 32;
    }
    return std::uint32_t(h);
}

}  // namespace

template <class T>
SequencePool<T>::SequencePool() : slots_(kInitialSlots, kEmptySlot) {}

template <class T>
int SequencePool<T>::intern(const T* v, int n) {
    const std::uint32_t hash = hashValues(v, n);
    const std::size_t mask = slots_.size() - 1;
    std::size_t s = hash & mask;
    for (; slots_[s].offset >= 0; s = (s + 1) & mask) {
        const Slot& slot = slots_[s];
        // n == 0 is checked first: memcmp must not see the empty pool's null data().
        if (slot.hash == hash && slot.size == n &&
            (n == 0 || std::memcmp(values_.data() + slot.offset, v, std::size_t(n) * sizeof(T)) == 0))
            return slot.offset;
    }
    const int offset = int(values_.size());
    values_.insert(values_.end(), v, v + n);
    slots_[s] = Slot{hash, offset, n};
    // Kept at most half full so that probe runs stay short.
    if (2 * ++used_ > int(slots_.size())) grow();
    return offset;
}

template <class T>
void SequencePool<T>::grow() {
    const std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.size() * 2, kEmptySlot);
    const std::size_t mask = slots_.size() - 1;
    for (const Slot& slot : old) {
        if (slot.offset < 0) continue;
        std::size_t s = slot.hash & mask;
        while (slots_[s].offset >= 0) s = (s + 1) & mask;
        slots_[s] = slot;
    }
}

template <class T>
std::vector<T> SequencePool<T>::take() {
    std::vector<T> out;
    out.swap(values_);
    slots_.assign(kInitialSlots, kEmptySlot);
    used_ = 0;
    return out;
}

template class SequencePool<float>;
template class SequencePool<int>;

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
