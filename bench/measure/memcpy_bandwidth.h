// Memory bandwidth reference: memcpy between two buffers, measured in the same run as the cases.
#pragma once

#include <cstddef>

#include "bench/figures.h"

namespace quadtri::bench {

// Median over `reps` copies (after one warm-up copy) of `bytes` bytes, split evenly between
// `threads` oneTBB threads (the pool TbbEvaluator runs on, so no thread is started in the timed
// span), in GB/s of bytes read plus bytes written (2 * bytes per copy).
double memcpyGbps(std::size_t bytes, int threads, int reps);

// The same on one thread and on `threads`.
MemcpyFigures measureMemcpy(std::size_t bytes, int threads, int reps);

}  // namespace quadtri::bench
