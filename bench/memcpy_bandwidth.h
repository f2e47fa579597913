// Memory bandwidth reference: memcpy between two large buffers.
#pragma once

#include <cstddef>

namespace quadtri::bench {

// Median over `reps` copies (after one warm-up copy) of `bytes` bytes, split evenly between
// `threads` std::threads, in GB/s of bytes read plus bytes written (2 * bytes per copy).
double memcpyGbps(std::size_t bytes, int threads, int reps);

}  // namespace quadtri::bench
