// A refinement level handed to the Renderer: its triangles and their origins, and, for the
// Vulkan evaluator, its positions and limit normals evaluated on the renderer's own device into
// the buffers the draw reads (no copy through host memory).
#pragma once

#include <optional>
#include <vector>

#include <quadtri/far/refiner.h>
#include <quadtri/osd/vulkan_buffer.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_evaluator.h>

#include "tools/render/renderer.h"

namespace quadtri::render {

// Level `level`'s faces as the renderer's surface, with `uvValues` (2 floats per value of
// face-varying channel 0 at that level) when not null, and each triangle's FaceOrigin. With
// `elementOfVertex`, the vertex buffers hold level vertex v at element elementOfVertex[v] (a
// LevelPatchTable's order: pointOfVertex()).
void showLevel(Renderer& renderer, const Refiner& refiner, int level, const float* uvValues,
               const std::vector<int>* elementOfVertex = nullptr);

// Level `level`'s positions (one buffer holding every level, one dispatch per level) and limit
// normals, and with `limit` its limit positions, evaluated on `ctx`'s device.
class DeviceSurface {
public:
    DeviceSurface(VulkanContext& ctx, const Refiner& refiner, int level, const std::vector<float>& control, bool limit);

    // What Renderer::useVertexBuffers takes; valid while this object lives.
    VulkanBufferRef positions() const { return positionRef_; }
    VulkanBufferRef normals() const { return {normals_->buffer(), 0}; }
    // Read back (waits): for what the CPU computes from them, such as the mean curvature.
    std::vector<float> readPositions() const;
    std::vector<float> readNormals() const;

private:
    int numVertices_ = 0, firstVertex_ = 0;  // of the level, in levels_
    std::optional<VulkanVertexBuffer> levels_, limitPositions_, normals_;
    VulkanBufferRef positionRef_{};
};

}  // namespace quadtri::render
