// What a click at a pixel hits on the cage: the nearest control edge or vertex on screen, for
// a viewer's selection (docs/rendering.md). Occlusion by the surface is not considered.
#pragma once

#include <glm/glm.hpp>

#include "tools/render/renderer.h"

namespace quadtri::render {

// The edge (its index in cage.edges / 2) whose projection passes nearest to `pixel`, within
// `maxPixels`; -1 when none does. Edges with an end behind the eye are skipped.
int pickEdge(const Cage& cage, const ViewSettings& view, VkExtent2D extent, glm::vec2 pixel, float maxPixels = 6.0f);
// The control vertex projected nearest to `pixel`, within `maxPixels`; -1 when none is.
int pickVertex(const Cage& cage, const ViewSettings& view, VkExtent2D extent, glm::vec2 pixel, float maxPixels = 8.0f);

}  // namespace quadtri::render
