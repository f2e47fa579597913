// The CLI's Vulkan side when quadtri is built without Vulkan (QUADTRI_WITH_VULKAN=OFF): every
// request for it falls back to the CPU, saying so; `render`, which needs it, is refused.
#include <cstdio>

#include "tools/commands.h"

namespace quadtri::cli {

std::optional<std::vector<std::vector<float>>> evaluateLevelsOnVulkan(const std::vector<LevelData>&) {
    std::fprintf(stderr, "quadtri: built without Vulkan (QUADTRI_WITH_VULKAN=OFF); using the CPU evaluator\n");
    return std::nullopt;
}

std::optional<Surface> evaluateSurfaceOnVulkan(const Refiner&, int, const std::vector<float>&, bool, NormalKind) {
    std::fprintf(stderr, "quadtri: built without Vulkan (QUADTRI_WITH_VULKAN=OFF); using the CPU evaluator\n");
    return std::nullopt;
}

std::unique_ptr<realtime::FrameEvaluator> makeVulkanFrameEvaluator(const realtime::SurfaceTables&, std::string&) {
    std::fprintf(stderr, "quadtri: built without Vulkan (QUADTRI_WITH_VULKAN=OFF); vulkan skipped\n");
    return nullptr;
}

int runRender(const RenderArgs&) {
    std::fprintf(stderr, "quadtri: render draws with Vulkan, and this quadtri was built without it (QUADTRI_WITH_VULKAN=OFF)\n");
    return 2;
}

}  // namespace quadtri::cli
