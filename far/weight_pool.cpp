#include "far/internal/weight_pool.h"

#include <cstring>
#include <utility>

namespace quadtri {
inline namespace v0 {

namespace {

constexpr int kInitialSlots = 64;  // a power of two; a regular level needs a handful

// Multiply-xorshift over the float bits: the multiply carries every bit upwards, the shift
// brings the high half back down, so the low bits that pick a slot depend on every weight.
std::uint32_t hashWeights(const float* w, int n) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull * std::uint64_t(n + 1);
    for (int k = 0; k < n; ++k) {
        std::uint32_t bits;
        std::memcpy(&bits, w + k, sizeof bits);
        h = (h ^ bits) * 0xFF51AFD7ED558CCDull;
        h ^= h >> 32;
    }
    return std::uint32_t(h);
}

}  // namespace

WeightPool::WeightPool() : slots_(kInitialSlots, kEmptySlot) {}

int WeightPool::intern(const float* w, int n) {
    const std::uint32_t hash = hashWeights(w, n);
    const std::size_t mask = slots_.size() - 1;
    std::size_t s = hash & mask;
    for (; slots_[s].offset >= 0; s = (s + 1) & mask) {
        const Slot& slot = slots_[s];
        // n == 0 is checked first: memcmp must not see the empty pool's null data().
        if (slot.hash == hash && slot.size == n &&
            (n == 0 || std::memcmp(weights_.data() + slot.offset, w, std::size_t(n) * sizeof(float)) == 0))
            return slot.offset;
    }
    const int offset = int(weights_.size());
    weights_.insert(weights_.end(), w, w + n);
    slots_[s] = Slot{hash, offset, n};
    // Kept at most half full so that probe runs stay short.
    if (2 * ++used_ > int(slots_.size())) grow();
    return offset;
}

void WeightPool::grow() {
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

std::vector<float> WeightPool::takeWeights() {
    std::vector<float> out;
    out.swap(weights_);
    slots_.assign(kInitialSlots, kEmptySlot);
    used_ = 0;
    return out;
}

}  // namespace v0
}  // namespace quadtri
