#include "tools/render/picking.h"

#include <algorithm>

namespace quadtri::render {

namespace {

glm::vec3 pointOf(const Cage& cage, uint32_t v) {
    return {cage.positions[3 * std::size_t(v)], cage.positions[3 * std::size_t(v) + 1],
            cage.positions[3 * std::size_t(v) + 2]};
}

}  // namespace

int pickEdge(const Cage& cage, const ViewSettings& view, VkExtent2D extent, glm::vec2 pixel, float maxPixels) {
    int best = -1;
    float bestDistance = maxPixels;
    for (std::size_t e = 0; 2 * e + 1 < cage.edges.size(); ++e) {
        const glm::vec3 a = toPixel(view, extent, pointOf(cage, cage.edges[2 * e]));
        const glm::vec3 b = toPixel(view, extent, pointOf(cage, cage.edges[2 * e + 1]));
        if (a.z <= 0.0f || b.z <= 0.0f) continue;
        const glm::vec2 ab = glm::vec2(b) - glm::vec2(a);
        const float t = std::clamp(glm::dot(pixel - glm::vec2(a), ab) / std::max(glm::dot(ab, ab), 1e-12f), 0.0f, 1.0f);
        const float d = glm::length(pixel - (glm::vec2(a) + t * ab));
        if (d <= bestDistance) best = int(e), bestDistance = d;
    }
    return best;
}

int pickVertex(const Cage& cage, const ViewSettings& view, VkExtent2D extent, glm::vec2 pixel, float maxPixels) {
    int best = -1;
    float bestDistance = maxPixels;
    for (std::size_t v = 0; 3 * v + 2 < cage.positions.size(); ++v) {
        const glm::vec3 p = toPixel(view, extent, pointOf(cage, uint32_t(v)));
        if (p.z <= 0.0f) continue;
        const float d = glm::length(pixel - glm::vec2(p));
        if (d <= bestDistance) best = int(v), bestDistance = d;
    }
    return best;
}

}  // namespace quadtri::render
