// The bench's outputs: the JSON file (--json) and the markdown table on stdout.
#pragma once

#include <ostream>
#include <string>

#include "bench/figures.h"

namespace quadtri::bench {

// Writes {"memcpy_gbps_1t", "memcpy_gbps_2t", "cases": [...]} (null where not run); throws
// std::runtime_error if the file cannot be written.
void writeJson(const std::string& path, const BenchResult& result);

// One row per case with the main figures and the OSD/quadtri ratios, then the memcpy line.
void printMarkdown(std::ostream& out, const BenchResult& result);

}  // namespace quadtri::bench
