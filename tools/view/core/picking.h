// Picking on the CPU: the cage's vertices projected with the view's camera, and the edge or
// vertex nearest the cursor on the screen, within a few pixels (docs/viewer.md).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace quadtri::view {

// A point in window pixels (x right, y down), `visible` when it lies in front of the camera.
struct ScreenPoint {
    glm::vec2 pixel{0.0f};
    float depth = 0.0f;  // clip w: distance along the view direction
    bool visible = false;
};

// `xyz` (3 floats per point) through `viewProjection` (Vulkan clip space: y down) into a
// viewport of `size` pixels whose top-left corner is at `origin`.
std::vector<ScreenPoint> projectPoints(const glm::mat4& viewProjection, const float* xyz, int numPoints,
                                       glm::vec2 origin, glm::vec2 size);

// Distance from `p` to the segment a-b.
float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b);

// The edge (index into `edges`, 2 vertex indices each) nearest `cursor` within `maxPixels`, both
// ends visible; among edges equally near, the one nearer the camera. -1 when none is near.
int nearestEdge(const std::vector<ScreenPoint>& points, const std::vector<uint32_t>& edges, glm::vec2 cursor,
                float maxPixels);
// The visible point nearest `cursor` within `maxPixels`, or -1.
int nearestPoint(const std::vector<ScreenPoint>& points, glm::vec2 cursor, float maxPixels);

}  // namespace quadtri::view
