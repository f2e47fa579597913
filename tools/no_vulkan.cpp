// The CLI's Vulkan side when quadtri is built without Vulkan (QUADTRI_WITH_VULKAN=OFF): every
// request for it falls back to the CPU, saying so; `render`, which needs it, is refused.
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

int runRender(const RenderArgs&) {
    std::fprintf(stderr, "quadtri: render draws with Vulkan, and this quadtri was built without it (QUADTRI_WITH_VULKAN=OFF)\n");
    return 2;
}

}  // namespace quadtri::cli
