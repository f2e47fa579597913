// Peak resident memory of one phase of the bench (Linux): the peak resident set is reset at the
// start (writing 5 to /proc/self/clear_refs) and read at the end (VmHWM of /proc/self/status),
// less what was resident at the start. The process's peak counts everything resident, so a phase
// measured this way is the memory it added: what it allocated and touched, transient arrays
// included, not what earlier phases still hold.
#pragma once

#include <cstddef>
#include <optional>

namespace quadtri::bench {

class PeakMemory {
public:
    // Returns freed heap to the kernel first (malloc_trim), so that the phase's allocations are
    // fresh pages rather than pages an earlier phase left resident; absent where the kernel
    // refuses the reset.
    PeakMemory();

    // The peak resident bytes since construction above the resident bytes then.
    std::optional<std::size_t> peakAboveStart() const;

private:
    bool reset_ = false;
    std::size_t startResident_ = 0;
};

}  // namespace quadtri::bench
