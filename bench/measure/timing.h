// Wall-clock timing for the bench: a steady_clock stopwatch and the median, fastest and slowest of
// repeated runs.
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

// Milliseconds over the repetitions of one figure: the median is the figure, min and max its spread.
struct Timing {
    double median = 0, min = 0, max = 0;
};

inline Timing summarize(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    const double middle = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {middle, values.front(), values.back()};
}

// Untimed warm-up calls of f for 100 ms (at least one), then `reps` timed calls. One warm-up call
// is not enough after the builds a case times first: on the 2-core VM the first evaluation of a
// cache-sized level (torus100_quad level 3, ~35 MB) then stays 1.5-2x slower for about a dozen
// calls, whatever its width (docs/stencil_kernel.md).
template <class F>
Timing timeMs(int reps, F&& f) {
    const Stopwatch warmUp;
    do f();
    while (warmUp.elapsedMs() < 100.0);
    std::vector<double> times;
    for (int r = 0; r < reps; ++r) {
        Stopwatch watch;
        f();
        times.push_back(watch.elapsedMs());
    }
    return summarize(times);
}

}  // namespace quadtri::bench
