// quadtri's Vulkan evaluation of one bench case: the per-level tables and control positions
// uploaded, then all levels evaluated through one device buffer (record, submit, fence).
#pragma once

#include <vector>

#include "bench/measure/timing.h"
#include <quadtri/far/refiner.h>
#include <quadtri/osd/vulkan_context.h>

namespace quadtri::bench {

struct VulkanFigures {
    Timing uploadMs;  // VulkanStencilTable of every level + control positions
    Timing evalMs;    // EvalLevelsAndWait over every level (submit to fence)
};

// Checks the last level against `expected` (the serial CPU result) within `tolerance` first,
// throwing std::runtime_error on a mismatch.
VulkanFigures measureVulkan(VulkanContext& ctx, const Refiner& refiner, const std::vector<float>& control,
                            const std::vector<float>& expected, double tolerance, int reps);

}  // namespace quadtri::bench
