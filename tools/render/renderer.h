// The renderer (docs/rendering.md): pipelines for a caller's render pass that draw a refined
// surface by vertex pulling from the evaluators' own output buffers, in one of several shading
// modes, with the control cage over it. record() draws inside a render pass the caller began:
// OffscreenTarget's for `quadtri render`, a swapchain image's in a viewer.
//
// Set-up calls (set*, upload*) write buffers and descriptor sets the device reads when it runs
// the recorded commands: make them only while no command buffer recorded with this renderer is
// pending (after its fence).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

#include <quadtri/far/draw_buffers.h>
#include <quadtri/osd/vulkan_context.h>
#include <quadtri/osd/vulkan_evaluator.h>
#include "osd/vulkan/vulkan_memory.h"

#include "tools/render/camera.h"
#include "tools/render/image.h"
#include "tools/render/surface_data.h"

namespace quadtri::render {

enum class Shading : int32_t {
    Smooth = 0,
    Flat = 1,
    ReflectionLines = 2,
    MeanCurvature = 3,
    FaceType = 4,
    Textured = 5
};

struct ViewSettings {
    Camera camera;
    Light light;
    float sceneRadius = 1.0f;  // bounds the depth range: the radius of the scene's sphere around camera.target
    Shading shading = Shading::Smooth;
    bool showSurface = true, showCage = true, showPoints = false;
    float stripes = 16.0f;         // reflection lines: stripes over the half circle of directions
    float curvatureRange = 1.0f;   // mean curvature: |H| mapped to the ends of the colour map
    float edgeWidthPixels = 2.0f;  // cage edges
    float pointSizePixels = 7.0f;  // cage vertices
};

// The view's world-to-clip matrix over an image of `extent` (what record() draws with).
glm::mat4 viewProjection(const ViewSettings& view, VkExtent2D extent);
// A world point's pixel coordinates under the view (x right, y down, pixel centres at + 0.5) and
// its clip w (<= 0: behind the eye).
glm::vec3 toPixel(const ViewSettings& view, VkExtent2D extent, const glm::vec3& world);

// Makes compute-shader and transfer writes recorded before it (an evaluator's outputs, uploads)
// visible to the draw's vertex and fragment shaders. Record it outside a render pass, before the
// pass begins, unless the pass's own subpass dependency does this (OffscreenTarget's does).
void barrierBeforeDraw(VkCommandBuffer cmd);

class Renderer {
public:
    // Pipelines for subpass 0 of `renderPass` (one colour attachment, one depth attachment).
    Renderer(VulkanContext& ctx, VkRenderPass renderPass, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // The level's triangles: `draw` over its vertices, UVs per draw vertex's value (2 floats per
    // value of draw.valueOf[0]; null without UVs), and per triangle its FaceOrigin. Forgets the
    // vertex buffers: give the level's with useVertexBuffers or uploadVertices next (the
    // surface is not drawn until then).
    void setSurface(const DrawBuffers& draw, const float* uvValues, const std::vector<uint32_t>& triangleOrigins);
    // The positions and normals the draw reads (3 floats per level vertex from each ref's
    // byteOffset, a multiple of 4): the caller's storage buffers, e.g. an evaluator's outputs,
    // which the caller keeps alive until they are replaced (setSurface, useVertexBuffers,
    // uploadVertices) or the renderer is destroyed.
    void useVertexBuffers(const VulkanBufferRef& positions, const VulkanBufferRef& normals);
    // Or host data (CPU, oneTBB evaluators) copied into the renderer's own buffers, which the
    // draw then reads; numVertices = the level's vertices.
    void uploadVertices(const float* positions, const float* normals, int numVertices);
    // Per level vertex: the mean curvature that MeanCurvature shading shows.
    void uploadCurvature(const std::vector<float>& curvature);
    // The control cage: positions, edges and colours.
    void setCage(const Cage& cage);
    // New positions for the cage set last (as many), e.g. a deformed cage each frame.
    void updateCagePositions(const float* positions);
    // A texture for Textured shading; null: the procedural UV checker.
    void setTexture(const Image* image);

    // Draws the visible parts of the view into the current subpass, over the whole of `extent`.
    void record(VkCommandBuffer cmd, VkExtent2D extent, const ViewSettings& view);
    // The same into the rectangle `area` of the framebuffer (e.g. one of two schemes side by
    // side); the view's aspect is the rectangle's.
    void record(VkCommandBuffer cmd, const VkRect2D& area, const ViewSettings& view);

private:
    struct Texture;
    void destroy() noexcept;
    void createLayouts();
    void createPipelines(VkRenderPass renderPass, VkSampleCountFlagBits samples);
    void createDescriptors();
    void writeSurfaceSet();
    void writeCageSet();
    detail::DeviceBuffer hostBuffer(const void* data, std::size_t bytes) const;

    VulkanContext& ctx_;
    VkDescriptorSetLayout surfaceLayout_ = VK_NULL_HANDLE, cageLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout surfacePipelineLayout_ = VK_NULL_HANDLE, cagePipelineLayout_ = VK_NULL_HANDLE;
    VkPipeline surfacePipeline_ = VK_NULL_HANDLE, edgePipeline_ = VK_NULL_HANDLE, pointPipeline_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkDescriptorSet surfaceSet_ = VK_NULL_HANDLE, cageSet_ = VK_NULL_HANDLE;

    detail::DeviceBuffer empty_;  // bound where a buffer is absent
    detail::DeviceBuffer triangles_, vertexOf_, uvs_, curvature_, origins_;
    detail::DeviceBuffer ownPositions_, ownNormals_;
    VulkanBufferRef positions_{}, normals_{};
    detail::DeviceBuffer cagePositions_, cageEdges_, edgeColors_, pointColors_;
    std::unique_ptr<Texture> checker_, texture_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    int numTriangles_ = 0, numVertices_ = 0, numEdges_ = 0, numPoints_ = 0;  // numVertices_: the level's
    bool hasUVs_ = false;
};

}  // namespace quadtri::render
