#include "bench/measure/peak_memory.h"

#include <malloc.h>

#include <fstream>
#include <string>

namespace quadtri::bench {

namespace {

// A "Vm...:  1234 kB" line of /proc/self/status, in bytes; 0 if absent.
std::size_t statusBytes(const std::string& key) {
    std::ifstream status("/proc/self/status");
    std::string name;
    std::size_t kib = 0;
    while (status >> name) {
        if (name == key + ":") {
            status >> kib;
            return kib * 1024;
        }
        status.ignore(1 << 12, '\n');
    }
    return 0;
}

}  // namespace

PeakMemory::PeakMemory() {
    malloc_trim(0);
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.flush();
    reset_ = bool(clear);
    startResident_ = statusBytes("VmRSS");
}

std::optional<std::size_t> PeakMemory::peakAboveStart() const {
    if (!reset_) return std::nullopt;
    const std::size_t peak = statusBytes("VmHWM");
    return peak > startResident_ ? peak - startResident_ : 0;
}

}  // namespace quadtri::bench
