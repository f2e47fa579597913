// The CLI's Vulkan side when quadtri is built without Vulkan (QUADTRI_WITH_VULKAN=OFF): every
// request for it falls back to the CPU, saying so.
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

}  // namespace quadtri::cli
