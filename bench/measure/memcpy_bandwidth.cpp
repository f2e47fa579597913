#include "bench/measure/memcpy_bandwidth.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <cstring>
#include <vector>

#include "bench/measure/timing.h"

namespace quadtri::bench {

double memcpyGbps(std::size_t bytes, int threads, int reps) {
    // Both buffers filled first, so the timed copies fault in no pages.
    std::vector<char> src(bytes, 1), dst(bytes, 0);
    tbb::task_arena arena(threads);
    auto copyAll = [&] {
        if (threads <= 1) {
            std::memcpy(dst.data(), src.data(), bytes);
            return;
        }
        const std::size_t chunk = bytes / std::size_t(threads);
        arena.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<int>(0, threads, 1),
                [&](const tbb::blocked_range<int>& r) {
                    for (int t = r.begin(); t < r.end(); ++t) {
                        const std::size_t begin = std::size_t(t) * chunk;
                        const std::size_t end = t + 1 == threads ? bytes : begin + chunk;
                        std::memcpy(dst.data() + begin, src.data() + begin, end - begin);
                    }
                },
                tbb::static_partitioner());
        });
    };
    const double ms = timeMs(reps, copyAll).median;
    return 2.0 * double(bytes) / (ms * 1e-3) / 1e9;
}

MemcpyFigures measureMemcpy(std::size_t bytes, int threads, int reps) {
    MemcpyFigures f;
    f.bytes = bytes;
    f.gbps1 = memcpyGbps(bytes, 1, reps);
    f.gbpsAll = memcpyGbps(bytes, threads, reps);
    return f;
}

}  // namespace quadtri::bench
