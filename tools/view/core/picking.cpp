#include "tools/view/core/picking.h"

#include <algorithm>

namespace quadtri::view {

std::vector<ScreenPoint> projectPoints(const glm::mat4& viewProjection, const float* xyz, int numPoints,
                                       glm::vec2 origin, glm::vec2 size) {
    std::vector<ScreenPoint> points(std::size_t(std::max(numPoints, 0)));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec4 clip = viewProjection * glm::vec4(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], 1.0f);
        ScreenPoint& p = points[i];
        p.depth = clip.w;
        p.visible = clip.w > 1e-6f;
        if (!p.visible) continue;
        const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
        p.pixel = origin + (ndc * 0.5f + 0.5f) * size;
    }
    return points;
}

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float length2 = glm::dot(ab, ab);
    const float t = length2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

int nearestEdge(const std::vector<ScreenPoint>& points, const std::vector<uint32_t>& edges, glm::vec2 cursor,
                float maxPixels) {
    int best = -1;
    float bestDistance = maxPixels, bestDepth = 0.0f;
    for (std::size_t e = 0; 2 * e + 1 < edges.size(); ++e) {
        const ScreenPoint& a = points[edges[2 * e]];
        const ScreenPoint& b = points[edges[2 * e + 1]];
        if (!a.visible || !b.visible) continue;
        const float d = distanceToSegment(cursor, a.pixel, b.pixel);
        const float depth = 0.5f * (a.depth + b.depth);
        // Within half a pixel two edges are equally near: the nearer the camera wins.
        const bool nearer = d < bestDistance - 0.5f || (d <= bestDistance + 0.5f && depth < bestDepth);
        if (d <= maxPixels && (best < 0 || nearer)) {
            best = int(e);
            bestDistance = d, bestDepth = depth;
        }
    }
    return best;
}

int nearestPoint(const std::vector<ScreenPoint>& points, glm::vec2 cursor, float maxPixels) {
    int best = -1;
    float bestDistance = maxPixels;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!points[i].visible) continue;
        const float d = glm::length(points[i].pixel - cursor);
        if (d <= bestDistance) best = int(i), bestDistance = d;
    }
    return best;
}

}  // namespace quadtri::view
