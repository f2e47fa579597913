#include "bench/memcpy_bandwidth.h"

#include <cstring>
#include <thread>
#include <vector>

#include "bench/timing.h"

namespace quadtri::bench {

double memcpyGbps(std::size_t bytes, int threads, int reps) {
    // Both buffers filled first, so the timed copies fault in no pages.
    std::vector<char> src(bytes, 1), dst(bytes, 0);
    auto copyAll = [&] {
        if (threads <= 1) {
            std::memcpy(dst.data(), src.data(), bytes);
            return;
        }
        std::vector<std::thread> pool;
        const std::size_t chunk = bytes / threads;
        for (int t = 0; t < threads; ++t) {
            const std::size_t begin = t * chunk, end = t + 1 == threads ? bytes : begin + chunk;
            pool.emplace_back([&, begin, end] { std::memcpy(dst.data() + begin, src.data() + begin, end - begin); });
        }
        for (std::thread& th : pool) th.join();
    };
    const double ms = medianMs(reps, copyAll);
    return 2.0 * double(bytes) / (ms * 1e-3) / 1e9;
}

}  // namespace quadtri::bench
