// The CLI's Vulkan side when quadtri is built without Vulkan (QUADTRI_WITH_VULKAN=OFF): every
// request for it falls back to the CPU, saying so.
#include <cstdio>

#include "tools/commands.h"

namespace quadtri::cli {

struct VulkanTiming {};

void VulkanTimingDeleter::operator()(VulkanTiming* timing) const { delete timing; }

std::optional<std::vector<std::vector<float>>> evaluateLevelsOnVulkan(const std::vector<LevelData>&) {
    std::fprintf(stderr, "quadtri: built without Vulkan (QUADTRI_WITH_VULKAN=OFF); using the CPU evaluator\n");
    return std::nullopt;
}

std::optional<Surface> evaluateSurfaceOnVulkan(const Refiner&, int, const std::vector<float>&, bool, NormalKind) {
    std::fprintf(stderr, "quadtri: built without Vulkan (QUADTRI_WITH_VULKAN=OFF); using the CPU evaluator\n");
    return std::nullopt;
}

VulkanTimingPtr openVulkanTiming() {
    std::fprintf(stderr, "quadtri: built without Vulkan (QUADTRI_WITH_VULKAN=OFF); no Vulkan timings\n");
    return nullptr;
}

double vulkanEvalMs(VulkanTiming&, const StencilTable&, const std::vector<float>&, int) { return 0; }

}  // namespace quadtri::cli
