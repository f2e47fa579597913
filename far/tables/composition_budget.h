// The memory budget of one composition (Options::memoryBudgetBytes): what it may still allocate
// beside what the Refiner holds, and the refusal that names what was asked for.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>

#include <quadtri/far/options.h>

namespace quadtri {
inline namespace v0 {
namespace internal {

// What a composition may still allocate: the budget less what the Refiner holds, counting the
// tables alive at each step; a refusal names `subject`.
class CompositionBudget {
public:
    CompositionBudget(std::string subject, std::size_t held, std::size_t budget)
        : subject_(std::move(subject)), held_(held), budget_(budget) {}
    MemoryBudgetError refuse(std::size_t needed) const { return MemoryBudgetError(subject_, needed, held_, budget_); }
    void reserve(std::size_t more) {
        if (held_ > budget_ || used_ > budget_ - held_ || more > budget_ - held_ - used_)
            throw refuse(held_ + used_ + more);
        used_ += more;
    }
    void release(std::size_t less) { used_ -= std::min(less, used_); }  // estimates and actual sizes may differ
    std::size_t left() const { return budget_ - held_ - used_; }
    std::size_t budget() const { return budget_; }

private:
    std::string subject_;
    std::size_t held_, budget_, used_ = 0;  // used: bytes of the double tables alive at this point
};

}  // namespace internal
}  // namespace v0
}  // namespace quadtri
