// The bench's outputs: the JSON file (--json, read by bench/performance_section.py) and the
// markdown tables on stdout.
#pragma once

#include <ostream>
#include <string>

#include "bench/figures.h"

namespace quadtri::bench {

// Every figure (null where not run); each time as {"median", "min", "max"} in ms over the
// repetitions. Throws std::runtime_error if the file cannot be written.
void writeJson(const std::string& path, const BenchResult& result);

// The frame cases first (per cage, level and evaluator: the frame, its fps and the like-for-like
// OSD/quadtri ratio), then one row per case with the main figures and the like-for-like
// OSD/quadtri ratios, the memcpy line and the limit cases.
void printMarkdown(std::ostream& out, const BenchResult& result);

}  // namespace quadtri::bench
