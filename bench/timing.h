// Wall-clock timing for the bench: a steady_clock stopwatch and the median of repeated runs.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace quadtri::bench {

class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double elapsedMs() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    std::chrono::steady_clock::time_point start_;
};

inline double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// One untimed warm-up call of f, then the median in ms of `reps` timed calls.
template <class F>
double medianMs(int reps, F&& f) {
    f();
    std::vector<double> times;
    for (int r = 0; r < reps; ++r) {
        Stopwatch watch;
        f();
        times.push_back(watch.elapsedMs());
    }
    return median(times);
}

}  // namespace quadtri::bench
